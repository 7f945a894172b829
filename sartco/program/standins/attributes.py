"""What `obj.name` may read and write: the one rule for attributes.

Before running (nodes.py): a name with two leading underscores only if the program may define
it (classes.DEFINABLE: `super().__init__(...)`, `self.__repr__()`) or read it (classes.READABLE);
any other name must be a
method or member the sandbox offers (allowed.ATTRIBUTES) or a name the program itself defines (a name it
binds, an attribute it stores, a word of one of its string constants: a namedtuple's fields).
Stores (`obj.name = v`, `del obj.name`, `obj.name += v`) become `$fields(obj, name)[name] ...`.

When it runs (`$attr` = read, `$fields` = fields):
- a stand-in module: its members;
- an object of the program's own classes (or such a class): a name that the object holds or a
  class of its MRO other than `object` defines (never the metaclass's `mro`), dunders only
  DEFINABLE ones, and classes.READABLE: an instance's `__class__` (never a class's: the
  metaclass stays unreachable), a class's `__name__`/`__qualname__`
  (`f"{self.__class__.__name__}(...)"`); `super()` in a program's method reads like an object;
- an enum of the program's (enums.py) as any program class, never enum's machinery
  (enums.INTERNALS), with a class's `__members__`; a str enum's str methods as a str's (checked);
- a built-in type used unbound: its allowed methods (`map(str.lower, words)`), `dict.fromkeys`,
  `itertools.chain.from_iterable`; any class's `__name__`;
- a function the program defined (its code is the program's): its name, and the attributes the
  program gave it (`wrapper.calls = 0`);
- any other object: the methods its type offers (methods.TYPE_METHODS and TYPES below);
- writing and deleting: on objects of the program's own classes and on the functions it
  defined only, never a dunder.
So nothing reaches `__class__`, `__dict__`, `__globals__`, frames, code or another object's
internals: those names are never offered and no type the program can reach offers them.
"""
from __future__ import annotations

import dataclasses
import functools
import itertools
import types
from collections.abc import Callable
from typing import Any

from .arrays import ARRAY_NAMES, ndarray
from .budget import Forbidden
from .chance import RANDOM_METHODS, SeededRandom
from .classes import DEFINABLE, EXCEPTION_TYPES, FILENAME, METACLASSES, READABLE, ProgramEnumType
from .conversions import STR
from .enums import INTERNALS, is_enum
from .methods import CHECKED_METHODS, TYPE_METHODS, _DICT, _FROZEN, _LIST, _SET, _STR
from .standin import Module

TYPES = {  # types of the stand-ins and of the class machinery, with the names they offer
    property: frozenset({"setter", "getter", "deleter"}), SeededRandom: RANDOM_METHODS, ndarray: ARRAY_NAMES,
    types.GeneratorType: frozenset({"send", "close"}),
    types.FunctionType: frozenset({"__name__", "__qualname__"}),  # a function's name (functools.wraps loggers)
    **dict.fromkeys(EXCEPTION_TYPES, frozenset({"args"})),  # what a handler may read of a caught error
    StopIteration: frozenset({"args", "value"}),  # a generator's return value
    dataclasses.Field: frozenset({"name", "type", "default", "default_factory", "init", "repr", "hash", "compare",
                                  "metadata", "kw_only"}),  # what dataclasses.fields() gives, its public part
    functools._lru_cache_wrapper: frozenset({"cache_info", "cache_clear", "cache_parameters", "__name__",
                                             "__qualname__"}),  # functools.cache / lru_cache
    functools._CacheInfo: frozenset({"hits", "misses", "maxsize", "currsize", "_asdict", "count", "index"}),
    types.MappingProxyType: frozenset({"items", "keys", "values", "get", "copy"}),  # an enum's __members__
    type: frozenset({"__name__", "__qualname__"}),  # any class's name (`type(e).__name__`)
}
UNBOUND = {  # built-in types and stand-in members a program may read a method of
    STR: (str, _STR), list: (list, _LIST), dict: (dict, _DICT | {"fromkeys"}), set: (set, _SET),
    frozenset: (frozenset, _FROZEN), tuple: (tuple, frozenset({"index", "count"})),
    itertools.chain: (itertools.chain, frozenset({"from_iterable"})),
}
_TYPE_LIKE = type(STR)  # the type of the program's `str` and `int` (conversions.py)
_SLOTS = (types.MemberDescriptorType, types.GetSetDescriptorType)  # what a class's __slots__ make
_REAL_STR = frozenset(name for name in dir(str) if name[:1] != "_")
RECORD_NAMES = frozenset({"_asdict", "_replace", "_fields", "_make", "_field_defaults", "args"})  # args: exceptions
OFFERED = frozenset({"fromkeys", "from_iterable"})  # dict.fromkeys, itertools.chain.from_iterable


def _defined(obj, name: str) -> bool:
    """Whether the program's object (or class) holds `name` or one of its classes defines it."""
    if type(obj) in METACLASSES:
        mro = obj.__mro__
    else:
        own = getattr(obj, "__dict__", None)  # no program class defines __getattr__
        if type(own) is dict and name in own:
            return True
        mro = type(obj).__mro__
    return any(name in klass.__dict__ for klass in mro[:-1])  # mro[-1] is object


def own_function(obj) -> bool:
    """A function the program defined (def or lambda): its code was compiled from the program."""
    return type(obj) is types.FunctionType and obj.__code__.co_filename == FILENAME


def _unbound(real: type, name: str):
    checked = CHECKED_METHODS.get(name)
    if checked is None:
        return getattr(real, name)

    def method(self, *args, **kwargs):
        if not isinstance(self, real):
            raise TypeError(f"descriptor '{name}' for '{real.__name__}' objects doesn't apply to a "
                            f"'{type(self).__name__}' object")
        return checked(self)(*args, **kwargs)
    return method


def read(obj: Any, name: str, fetch: Callable[[Any, str], Any] = getattr) -> Any:
    """`obj.name` in a program (`$attr`). `fetch(obj, name)` reads a name the rule allows (the
    rule alone: patterns.py passes one that reads nothing, for Python's own read after it)."""
    t = type(obj)
    allowed = TYPE_METHODS.get(t)
    if allowed is not None:
        if name not in allowed:
            _missing(t, name)
        checked = CHECKED_METHODS.get(name)
        return fetch(obj, name) if checked is None else checked(obj)
    if t is Module:
        try:
            return obj.__dict__[name]
        except KeyError:
            raise AttributeError(f"module {obj.__dict__['__name__']!r} has no attribute {name!r} in the sandbox") from None
    if type(t) in METACLASSES or t in METACLASSES:
        is_class = t in METACLASSES
        if name in READABLE:
            if name == "__class__" and not is_class:
                return t
            if name != "__class__" and is_class and (name != "__members__" or t is ProgramEnumType):
                return type.__getattribute__(obj, name)
            raise Forbidden(f".{name} is not available on {'a class' if is_class else 'an instance'} in the sandbox")
        if ((name[:2] == "__" and name not in DEFINABLE) or not _defined(obj, name)
                or (name in INTERNALS and is_enum(obj))):
            raise AttributeError(f"'{obj.__name__ if is_class else t.__name__}' object has no attribute '{name}'")
        if isinstance(obj, str) and name in _REAL_STR:  # a str enum's member: str's methods, as on a str
            if name not in _STR:
                _missing(str, name)
            if name in CHECKED_METHODS:
                return CHECKED_METHODS[name](obj)
        value = fetch(obj, name)
        if is_class and type(value) in _SLOTS:
            raise Forbidden(f"{obj.__name__}.{name} is a slot's descriptor: it is not available in the sandbox")
        return value
    if t is super:
        if type(obj.__thisclass__) not in METACLASSES or (name[:2] == "__" and name not in DEFINABLE):
            raise Forbidden(f"super().{name} is allowed only in the program's own classes")
        return getattr(obj, name)
    if t is type or t is _TYPE_LIKE:
        entry = UNBOUND.get(obj)
        if entry is not None and name in entry[1]:
            return _unbound(entry[0], name)
    allowed = TYPES.get(t)
    if allowed is None:
        raise Forbidden(f".{name} is allowed only on str, list, dict, set, tuple, the allowed modules and the "
                        f"program's own classes, not on {t.__name__}")
    if name not in allowed:
        if name[:2] != "__" and own_function(obj) and name in obj.__dict__:
            return obj.__dict__[name]
        _missing(t, name)
    return fetch(obj, name)


def _missing(t: type, name: str):
    if name[:2] == "__":
        raise Forbidden(f".{name} is available only on the program's own objects, not on {t.__name__}")
    raise AttributeError(f"'{t.__name__}' object has no attribute '{name}'")


class _Fields:
    """The target of `obj.name = v`, `del obj.name` and `obj.name op= v` (made by fields)."""

    __slots__ = ("obj",)

    def __init__(self, obj):
        self.obj = obj

    def __getitem__(self, name):
        return read(self.obj, name)

    def __setitem__(self, name, value):
        setattr(self.obj, name, value)

    def __delitem__(self, name):
        delattr(self.obj, name)


def fields(obj, name: str) -> _Fields:
    """`$fields`: the store target of the program's object `obj` for attribute `name`."""
    t = type(obj)
    if name[:2] == "__" or not (type(t) in METACLASSES or t in METACLASSES or own_function(obj)):
        raise Forbidden(f"assigning to an attribute (.{name}) is allowed only on objects of the program's own "
                        f"classes and on its own functions, not on {t.__name__}")
    return _Fields(obj)
