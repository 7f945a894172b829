"""The modules a program may import: safe, bounded stand-ins of harmless standard modules.

`import math`, `from itertools import product`, `import numpy as np`, ... bind a fresh `Module` (standin.py)
per import (nothing a program does to it outlives the program) whose members are the real
functions where they cannot reach anything outside the task's world or grow without a budget,
and checked versions where they could (`math.factorial`, `operator.mul`, ...). Every other
module is refused, naming why: `os`, `sys`, `subprocess`, `importlib`, `builtins`, `ctypes`,
`pickle`, `io`, `socket`, ... reach the interpreter, the file system or the network; `re` can
backtrack in C code for longer than any budget sees; `typing.get_type_hints` and
`string.Formatter` run text as code or read attributes by name, so they are not members;
`operator.attrgetter` and `methodcaller` read names under the run-time attribute rule of
`x.name` (named.py). `copy.copy` and `copy.deepcopy` take one argument (the memo would hand
out the internals of what they copy; a board's copy is an independent board), and typing's
caches, shared by a worker's programs, are emptied before each program (forget_typing).
`MEMBERS` (names only) lets instrument.py refuse an unknown module or member before anything runs.

Stand-ins of their own: numpy (arrays.py, numpy_members.py: arrays with numpy's semantics for
the subset models use), random (chance.py: CPython's sequence, one generator per program,
seeded with 0 unless the program seeds it), dataclasses and namedtuple/NamedTuple (records.py:
classes of the program), `functools.wraps(f)` and `update_wrapper` (without `assigned`/`updated`;
copying from the program's own objects only), `functools.total_ordering`,
contextlib's `suppress` (which never swallows a budget stop, a refusal, a RecursionError or a
MemoryError: budget.STOPS) and `nullcontext`, the only context managers a `with` can use, and
`from __future__ import annotations`.
"""
from __future__ import annotations

import bisect
import collections
import collections.abc
import contextlib
import copy
import functools
import heapq
import itertools
import math
import operator
import string
import textwrap
import typing
from collections.abc import Callable
from typing import Any

from . import budget, chance, enums, formatting, named, numpy_members, records
from .attributes import own_function
from .budget import STOPS, Forbidden, too_big
from .classes import ProgramClass, serial_hash
from .conversions import INT
from .json_module import MEMBERS as JSON_MEMBERS
from .standin import Module



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


def update_wrapper(wrapper: Any, wrapped: Any) -> Any:
    """functools.update_wrapper(wrapper, wrapped) with its defaults only (no `assigned`/`updated`:
    they name attributes to copy, `__globals__` among them), onto a function or an object of the
    program. From the program's own functions and objects it copies what Python copies (the
    names of functools.WRAPPER_ASSIGNMENTS, and the `__dict__` entries but dunders, which no
    store of a program makes); from anything else (a stand-in, a type, a class of the program,
    whose dict holds descriptors) only the names that are plain text (`__name__`, `__doc__`,
    ...): no class dict, descriptor, type or module's globals reaches a program through it."""
    if not (own_function(wrapper) or type(type(wrapper)) is ProgramClass):
        raise TypeError("update_wrapper() updates a function or an object of the program")
    own = own_function(wrapped) or type(type(wrapped)) is ProgramClass
    for name in functools.WRAPPER_ASSIGNMENTS:
        try:
            value = getattr(wrapped, name)
        except AttributeError:
            continue
        if own or type(value) is str or (value is None and name == "__doc__"):
            setattr(wrapper, name, value)
    if own:
        attributes = getattr(wrapped, "__dict__", {})
        wrapper.__dict__.update({k: v for k, v in attributes.items() if k[:2] != "__"})
    wrapper.__wrapped__ = wrapped
    return wrapper


def wraps(wrapped: Any) -> Callable[[Any], Any]:
    """functools.wraps(wrapped): a decorator of one argument that calls update_wrapper (Python's
    is a partial whose keywords a caller may replace)."""
    def decorate(wrapper: Any) -> Any:
        return update_wrapper(wrapper, wrapped)
    return decorate


def total_ordering(cls):
    """functools.total_ordering on the program's own classes."""
    if type(cls) is not records.ProgramClass:
        raise TypeError("total_ordering() decorates a class of the program")
    return functools.total_ordering(cls)


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


class suppress:  # contextlib's name
    """contextlib.suppress(*exceptions): a `with` block that ends quietly on one of them, except
    on what a program may never swallow (budget.STOPS)."""

    __slots__ = ("_exceptions",)
    __hash__ = serial_hash

    def __init__(self, *exceptions):
        self._exceptions = exceptions

    def __enter__(self):
        return None

    def __exit__(self, kind, value, traceback):
        return kind is not None and not isinstance(value, STOPS) and issubclass(kind, self._exceptions)


shallow_copy.__name__ = shallow_copy.__qualname__ = "copy"
deep_copy.__name__ = deep_copy.__qualname__ = "deepcopy"


_TYPING_USED = [True]  # whether typing's caches may hold something: a program imported typing since they were emptied


def forget_typing() -> None:
    """Empty typing's caches, which are shared by every program of a worker (Literal[x], List[x],
    ... keep their arguments): runtime calls it before each program. Only typing's objects fill
    them, and only its stand-in hands them out (import_module): after programs that never
    imported it there is nothing to empty (and in a fresh child, nothing to write)."""
    if _TYPING_USED[0]:
        for clear in typing._cleanups:
            clear()
        _TYPING_USED[0] = False


_TYPING = ("Any", "Callable", "Dict", "FrozenSet", "Iterable", "Iterator", "List", "Literal", "Mapping",
           "Optional", "Sequence", "Set", "Tuple", "Union", "TypeVar", "Generator", "Deque", "DefaultDict",
           "ClassVar", "Final", "TypedDict", "Hashable", "Sized", "Collection", "MutableMapping",
           "MutableSequence", "Type", "NoReturn", "Counter", "OrderedDict", "ChainMap", "Reversible")
_MATH = ("pi", "e", "tau", "inf", "nan", "sqrt", "isqrt", "floor", "ceil", "trunc", "fabs", "gcd", "log",
         "log2", "log10", "exp", "sin", "cos", "tan", "asin", "acos", "atan", "atan2", "hypot", "degrees",
         "radians", "copysign", "fmod", "modf", "isclose", "isfinite", "isinf", "isnan", "dist", "fsum", "pow")
_ITERTOOLS = ("product", "permutations", "combinations", "combinations_with_replacement", "chain", "count",
              "cycle", "repeat", "islice", "accumulate", "groupby", "zip_longest", "starmap", "takewhile",
              "dropwhile", "compress", "pairwise", "filterfalse")
_OPERATOR = ("sub", "truediv", "floordiv", "neg", "pos", "eq", "ne", "lt", "le", "gt", "ge", "not_", "and_",
             "or_", "xor", "itemgetter", "truth", "abs", "index")
_HEAPQ = ("heappush", "heappop", "heapify", "heapreplace", "heappushpop", "merge", "nlargest", "nsmallest")
_BISECT = ("bisect", "bisect_left", "bisect_right", "insort", "insort_left", "insort_right")
_ABCS = ("Iterable", "Iterator", "Generator", "Sequence", "MutableSequence", "Mapping", "MutableMapping", "Set",
         "MutableSet", "Callable", "Hashable", "Sized", "Container", "Collection", "Reversible")
_COLLECTIONS_ABC = Module("collections.abc", {n: getattr(collections.abc, n) for n in _ABCS})  # for annotations
_STRING = ("ascii_letters", "ascii_lowercase", "ascii_uppercase", "digits", "hexdigits", "octdigits",
           "punctuation", "whitespace", "printable")

_FACTORIES = {
    "math": lambda: {**{n: getattr(math, n) for n in _MATH}, "factorial": factorial, "comb": comb,
                     "perm": perm, "prod": prod, "lcm": lcm},
    "itertools": lambda: {n: getattr(itertools, n) for n in _ITERTOOLS},
    "functools": lambda: {"wraps": wraps, "update_wrapper": update_wrapper, "total_ordering": total_ordering, "reduce": functools.reduce, "partial": functools.partial, "cache": functools.cache,
                          "lru_cache": functools.lru_cache, "cmp_to_key": functools.cmp_to_key,
                          "cached_property": functools.cached_property},
    "typing": lambda: {**{n: getattr(typing, n) for n in _TYPING}, "NamedTuple": records.NamedTuple,
                       "Generic": records.Generic, "Protocol": records.Protocol},
    "collections": lambda: {"namedtuple": records.namedtuple, "defaultdict": collections.defaultdict, "Counter": collections.Counter,
                            "deque": collections.deque, "OrderedDict": collections.OrderedDict,
                            "ChainMap": collections.ChainMap, "abc": _COLLECTIONS_ABC},
    "collections.abc": lambda: dict(vars(_COLLECTIONS_ABC)),
    "textwrap": lambda: {"dedent": textwrap.dedent},  # (its other functions use regular expressions)
    "heapq": lambda: {n: getattr(heapq, n) for n in _HEAPQ},
    "bisect": lambda: {n: getattr(bisect, n) for n in _BISECT},
    "enum": lambda: dict(enums.MEMBERS["enum"]),
    "abc": lambda: dict(enums.MEMBERS["abc"]),
    "copy": lambda: {"copy": shallow_copy, "deepcopy": deep_copy},
    "contextlib": lambda: {"suppress": suppress, "nullcontext": contextlib.nullcontext},
    "operator": lambda: {**{n: getattr(operator, n) for n in _OPERATOR}, "add": budget.add, "mul": budget.mul,
                         "pow": budget.power, "mod": formatting.mod, "lshift": budget.lshift,
                         "attrgetter": named.attrgetter, "methodcaller": named.methodcaller},
    "string": lambda: {n: getattr(string, n) for n in _STRING},
    "numpy": lambda: {**numpy_members.MEMBERS, "int_": INT, "int32": INT, "int64": INT, "float64": float,
                      "float32": float, "pi": math.pi, "e": math.e},
    "random": lambda: dict(chance.MEMBERS),
    "dataclasses": lambda: dict(records.MEMBERS["dataclasses"]),
    "__future__": lambda: {"annotations": True},
    "json": lambda: dict(JSON_MEMBERS),  # json_module.py
}
_MEMBERS_CACHE = {name: make() for name, make in _FACTORIES.items()}
MEMBERS = {name: frozenset(members) for name, members in _MEMBERS_CACHE.items()}  # for allowed.py and nodes.py

REFUSED = {  # why a module a program may want is not there
    **dict.fromkeys(("os", "sys", "subprocess", "shutil", "pathlib", "io", "glob", "tempfile", "signal",
                     "ctypes", "gc", "inspect", "importlib", "builtins", "pickle", "marshal", "threading",
                     "multiprocessing", "socket", "urllib", "http", "requests", "resource", "code", "codeop",
                     "types", "dis", "runpy", "atexit", "traceback", "weakref", "sysconfig", "site"),
                    "it reaches the interpreter, the file system or the network"),
    "re": "a regular expression can run in C code beyond every budget",
    "time": "the board must not depend on the clock", "datetime": "the board must not depend on the clock",
}


def refusal(name: str) -> str:
    top, _, rest = name.partition(".")
    if top in MEMBERS and rest:
        return f"{top}'s {rest} is not available in the sandbox (available: {', '.join(sorted(MEMBERS[top]))})"
    reason = REFUSED.get(top, f"the sandbox offers only {', '.join(sorted(MEMBERS))}")
    return f"import of {name} is not allowed: {reason}"


def load(name: str) -> Module:
    """A fresh stand-in module (its members shared: functions, types and constants)."""
    return Module(name, dict(_MEMBERS_CACHE[name]))


def import_module(name, globals=None, locals=None, fromlist=(), level=0):
    """The `__import__` of a program's import statements (instrument.py refused every other name)."""
    if level != 0 or name not in _MEMBERS_CACHE:
        raise Forbidden(refusal(name))
    if name == "typing":
        _TYPING_USED[0] = True
    return load(name if fromlist else name.partition(".")[0])  # `import collections.abc` binds collections

