"""The `random` stand-in: CPython's own generator (Mersenne Twister), one per program.

`import random` gives functions bound to the current program's generator (SHARED, replaced by
runtime.namespace for every program), `random.Random(n)` a generator of the program's own; both
produce exactly CPython's sequence for the same seed (`seed`, `random`, `randint`, `randrange`,
`choice`, `choices`, `shuffle`, `sample`, `uniform`, `gauss`, ...). Unseeded, the generator is
seeded with 0 (CPython seeds from the operating system): the same program gives the same board
in every worker and every run, never a board of chance; `random.seed()` without an argument
does the same. `sample` and `choices` keep the length budget. No state, `getrandbits` or
`randbytes`: nothing outside the sequence.
"""
from __future__ import annotations

import random as _random

from . import budget
from .budget import too_long
from .classes import program_hash, serial_hash

RANDOM_METHODS = frozenset({"seed", "random", "randint", "randrange", "choice", "choices", "shuffle", "sample",
                            "uniform", "gauss", "normalvariate", "triangular", "expovariate", "betavariate"})
UNSEEDED = 0


class SeededRandom(_random.Random):
    """random.Random, seeded with UNSEEDED instead of the operating system's entropy; named,
    hashed and seeded by no address (a generator hashes by serial, a NaN seed by its
    classes.program_hash, as Python seeds from a float's hash)."""

    __hash__ = serial_hash

    def seed(self, a=None, version=2):
        if type(a) is float and a != a:
            a = program_hash(a) & ((1 << 64) - 1)  # what Python's C seed makes of a hash
        super().seed(UNSEEDED if a is None else a, version)

    def sample(self, population, k, *, counts=None):
        if type(k) is int and k > budget.LENGTH:
            too_long(k)
        return super().sample(population, k, counts=counts)

    def choices(self, population, weights=None, *, cum_weights=None, k=1):
        if type(k) is int and k > budget.LENGTH:
            too_long(k)
        return super().choices(population, weights, cum_weights=cum_weights, k=k)


SeededRandom.__module__, SeededRandom.__name__, SeededRandom.__qualname__ = "random", "Random", "Random"

# Python 3.13 imports sha512 at the first string seed (random.seed('abc')), which a confined
# child cannot do (it opens no file): seeding one here, in the template, imports it before any child
_random.Random("sha512")

SHARED = [None]  # the current program's generator, behind the module's functions (made at first use)


def fresh():
    """A new program starts: the module's generator starts from the unseeded state."""
    SHARED[0] = None


def _bound(name):
    def function(*args, **kwargs):
        if SHARED[0] is None:
            SHARED[0] = SeededRandom()
        return getattr(SHARED[0], name)(*args, **kwargs)
    function.__name__ = name
    return function


MEMBERS = {**{name: _bound(name) for name in RANDOM_METHODS}, "Random": SeededRandom}
