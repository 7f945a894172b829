"""The modules a program may import: safe, bounded stand-ins of harmless standard modules.

`import math`, `from itertools import product`, `import numpy as np`, ... bind a fresh `Module`
per import (nothing a program does to it outlives the program) whose members are the real
functions where they cannot reach anything outside the task's world or grow without a budget,
and checked versions where they could (`math.factorial`, `operator.mul`, ...). Every other
module is refused, naming why: `os`, `sys`, `subprocess`, `importlib`, `builtins`, `ctypes`,
`pickle`, `io`, `socket`, ... reach the interpreter, the file system or the network; `random`
would make the board a matter of chance; `re` can backtrack in C code for longer than any
budget sees; `collections.namedtuple`, `typing.get_type_hints` and `string.Formatter` run text
as code or read attributes by name, so they are not members; `operator.attrgetter` and
`methodcaller` read names under the attribute rule of `x.name` (named.py). `copy.copy` and
`copy.deepcopy` take one argument (the memo would hand out the internals of what they copy;
a board's copy is an independent board), and typing's caches, shared by a worker's programs,
are emptied before each program (forget_typing). `MEMBERS` (names only)
lets instrument.py refuse an unknown module or member before anything runs.

numpy is a stand-in for what honest code of this task does with it: `np.ndarray` (and the
scalar types) in annotations and isinstance checks, small helpers (`arange`, `zeros`, `ones`,
`full`, `array`) that return plain lists within the length budget, and `pi`, `e`, `sqrt`,
`floor`, `ceil`, `abs`. Everything else of numpy is refused by name.
"""
from __future__ import annotations

import collections
import copy
import functools
import itertools
import math
import operator
import string
import typing

from . import budget, formatting, named
from .budget import Forbidden, too_big, too_long
from .conversions import INT
from .json_module import MEMBERS as JSON_MEMBERS


class Module:
    """A stand-in module: its members are plain attributes (read through runtime's $attr)."""

    def __init__(self, name: str, members: dict):
        self.__dict__.update(members)
        self.__dict__["__name__"] = name

    def __repr__(self):
        return f"<module {self.__dict__['__name__']!r} (sandbox stand-in)>"


# --- checked members ------------------------------------------------------------------------------

def _bits_of(value) -> int:
    return value.bit_length() if type(value) in (int, bool) else 64


def factorial(n):
    if type(n) is int and n > 2 and math.lgamma(n + 1) / math.log(2) > budget.INT_BITS:
        too_big(math.lgamma(n + 1) / math.log(2))
    return math.factorial(n)


def _choose_bits(n, k) -> float:
    return min(k, n - k) * math.log2(n) if type(n) is int and type(k) is int and n > 1 and 0 < k < n else 0


def comb(n, k):
    if _choose_bits(n, k) > budget.INT_BITS:
        too_big(_choose_bits(n, k))
    return math.comb(n, k)


def perm(n, k=None):
    if type(n) is int and n > 1 and (k is None or type(k) is int):
        bits = (n if k is None else min(k, n)) * math.log2(n)
        if bits > budget.INT_BITS:
            too_big(bits)
    return math.perm(n, k)


def prod(iterable, *, start=1):
    items = list(iterable)
    bits = _bits_of(start) + sum(map(_bits_of, items))
    if bits > budget.INT_BITS:
        too_big(bits)
    return math.prod(items, start=start)


def lcm(*ints):
    bits = sum(map(_bits_of, ints))
    if bits > budget.INT_BITS:
        too_big(bits)
    return math.lcm(*ints)


class ndarray:  # noqa: N801 - numpy's name
    """numpy.ndarray for annotations and isinstance checks (no program value is one)."""


def _size(shape) -> tuple:
    dims = (shape,) if type(shape) is int else tuple(shape)
    total = 1
    for d in dims:
        if type(d) is not int or d < 0:
            raise ValueError(f"numpy stand-in: a shape is non-negative integers, got {shape!r:.40}")
        total *= d
        if total > budget.LENGTH:
            too_long(total)
    return dims


def _filled(dims: tuple, value):
    if len(dims) == 1:
        return [value] * dims[0]
    return [_filled(dims[1:], value) for _ in range(dims[0])]


def full(shape, fill_value, dtype=None):
    return _filled(_size(shape), fill_value if dtype is None else dtype(fill_value))


def zeros(shape, dtype=float):
    return full(shape, 0, dtype)


def ones(shape, dtype=float):
    return full(shape, 1, dtype)


def arange(*args, dtype=None):
    if all(type(a) is int for a in args):
        return list(budget.checked_range(*args))
    start, stop, step = (0, *args, 1)[-3:] if len(args) == 1 else (*args, 1)[:3]
    n = max(0, math.ceil((stop - start) / step))
    if n > budget.LENGTH:
        too_long(n)
    return [start + i * step for i in range(n)]


def array(obj, dtype=None):
    if isinstance(obj, (list, tuple, range)):
        if len(obj) > budget.LENGTH:
            too_long(len(obj))
        return [array(x, dtype) for x in obj]
    return obj if dtype is None else dtype(obj)


def shallow_copy(x, *more, **named):
    """copy.copy with the safe signature (a board's copy is an independent board: world/board.py)."""
    if more or named:
        raise TypeError(f"copy() takes exactly one argument ({1 + len(more) + len(named)} given)")
    return copy.copy(x)


def deep_copy(x, *more, **named):
    """copy.deepcopy without its memo: the objects a copy passes through never reach a program."""
    if more or named:
        raise Forbidden("copy.deepcopy takes one argument in the sandbox: its memo would hand out the "
                        "internals of the objects copied (the board's storage among them)")
    return copy.deepcopy(x)


shallow_copy.__name__ = shallow_copy.__qualname__ = "copy"
deep_copy.__name__ = deep_copy.__qualname__ = "deepcopy"


def forget_typing() -> None:
    """Empty typing's caches, which are shared by every program of a worker (Literal[x], List[x],
    ... keep their arguments): runtime calls it before each program."""
    for clear in typing._cleanups:
        clear()


_TYPING = ("Any", "Callable", "Dict", "FrozenSet", "Iterable", "Iterator", "List", "Literal", "Mapping",
           "Optional", "Sequence", "Set", "Tuple", "Union", "TypeVar", "Generator", "Deque", "DefaultDict")
_MATH = ("pi", "e", "tau", "inf", "nan", "sqrt", "isqrt", "floor", "ceil", "trunc", "fabs", "gcd", "log",
         "log2", "log10", "exp", "sin", "cos", "tan", "asin", "acos", "atan", "atan2", "hypot", "degrees",
         "radians", "copysign", "fmod", "modf", "isclose", "isfinite", "isinf", "isnan", "dist", "fsum", "pow")
_ITERTOOLS = ("product", "permutations", "combinations", "combinations_with_replacement", "chain", "count",
              "cycle", "repeat", "islice", "accumulate", "groupby", "zip_longest", "starmap", "takewhile",
              "dropwhile", "compress", "pairwise", "filterfalse")
_OPERATOR = ("sub", "truediv", "floordiv", "neg", "pos", "eq", "ne", "lt", "le", "gt", "ge", "not_", "and_",
             "or_", "xor", "itemgetter", "truth", "abs", "index")
_STRING = ("ascii_letters", "ascii_lowercase", "ascii_uppercase", "digits", "hexdigits", "octdigits",
           "punctuation", "whitespace", "printable")

_FACTORIES = {
    "math": lambda: {**{n: getattr(math, n) for n in _MATH}, "factorial": factorial, "comb": comb,
                     "perm": perm, "prod": prod, "lcm": lcm},
    "itertools": lambda: {n: getattr(itertools, n) for n in _ITERTOOLS},
    "functools": lambda: {"reduce": functools.reduce, "partial": functools.partial, "cache": functools.cache,
                          "lru_cache": functools.lru_cache, "cmp_to_key": functools.cmp_to_key},
    "typing": lambda: {n: getattr(typing, n) for n in _TYPING},
    "collections": lambda: {"defaultdict": collections.defaultdict, "Counter": collections.Counter,
                            "deque": collections.deque, "OrderedDict": collections.OrderedDict},
    "copy": lambda: {"copy": shallow_copy, "deepcopy": deep_copy},
    "operator": lambda: {**{n: getattr(operator, n) for n in _OPERATOR}, "add": budget.add, "mul": budget.mul,
                         "pow": budget.power, "mod": formatting.mod, "lshift": budget.lshift,
                                 "attrgetter": named.attrgetter, "methodcaller": named.methodcaller},
    "string": lambda: {n: getattr(string, n) for n in _STRING},
    "numpy": lambda: {"ndarray": ndarray, "array": array, "zeros": zeros, "ones": ones, "full": full,
                      "arange": arange, "int_": INT, "int32": INT, "int64": INT, "float64": float,
                      "float32": float, "pi": math.pi, "e": math.e, "sqrt": math.sqrt, "floor": math.floor,
                      "ceil": math.ceil, "abs": abs},
}
_FACTORIES["json"] = lambda: dict(JSON_MEMBERS)  # json_module.py
_MEMBERS_CACHE = {name: make() for name, make in _FACTORIES.items()}
MEMBERS = {name: frozenset(members) for name, members in _MEMBERS_CACHE.items()}  # for allowed.py and nodes.py

REFUSED = {  # why a module a program may want is not there
    **dict.fromkeys(("os", "sys", "subprocess", "shutil", "pathlib", "io", "glob", "tempfile", "signal",
                     "ctypes", "gc", "inspect", "importlib", "builtins", "pickle", "marshal", "threading",
                     "multiprocessing", "socket", "urllib", "http", "requests", "resource", "code", "codeop",
                     "types", "dis", "runpy", "atexit", "traceback", "weakref", "sysconfig", "site"),
                    "it reaches the interpreter, the file system or the network"),
    "random": "a board that depends on chance cannot be scored; write the coordinates",
    "re": "a regular expression can run in C code beyond every budget",
    "time": "the board must not depend on the clock", "datetime": "the board must not depend on the clock",
}


def refusal(name: str) -> str:
    top = name.partition(".")[0]
    reason = REFUSED.get(top, f"the sandbox offers only {', '.join(sorted(MEMBERS))}")
    return f"import of {name} is not allowed: {reason}"


def load(name: str) -> Module:
    """A fresh stand-in module (its members shared: functions, types and constants)."""
    return Module(name, dict(_MEMBERS_CACHE[name]))


def import_module(name, globals=None, locals=None, fromlist=(), level=0):
    """The `__import__` of a program's import statements (instrument.py refused every other name)."""
    if level != 0 or name not in _MEMBERS_CACHE:
        raise Forbidden(refusal(name))
    return load(name)

