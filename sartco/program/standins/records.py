"""Records a program may define: `@dataclass`, `collections.namedtuple` and `typing.NamedTuple`
(and `typing.TypedDict`); and build_class, which every class statement calls.

All three make classes of the program (classes.ProgramClass), with what the standard library
makes of them: dataclasses' own `__init__`/`__repr__`/`__eq__` (and order, frozen), the
namedtuple's tuple, fields, `_asdict`, `_replace`, `_make`. Only program classes are decorated;
a namedtuple's names are checked by collections itself (identifiers, no leading underscore).
A dataclass hashes as Python's: by its fields when frozen (or `unsafe_hash=True`), unhashable
when it compares by its fields and is not frozen, and by classes.serial_hash only when Python
would hash it by identity (`eq=False`). `dataclasses.fields()` gives the Field objects, of which a
program reads the public attributes (attributes.TYPES).
"""
from __future__ import annotations

import builtins
import collections
import dataclasses
import types
import typing

from .budget import Forbidden
from .classes import EXCEPTION_TYPES, ProgramClass, ProgramEnumType, make, serial_hash
from .conversions import INT, STR
from .enums import ABC_META

_OPTIONS = frozenset({"init", "repr", "eq", "order", "unsafe_hash", "frozen", "kw_only", "match_args", "slots"})


def dataclass(cls=None, /, **options):
    """`@dataclass` and `@dataclass(frozen=True, ...)` on the program's own classes."""
    unknown = set(options) - _OPTIONS
    if unknown:
        raise Forbidden(f"dataclass({', '.join(sorted(unknown))}=...) is not available in the sandbox")

    def wrap(klass):
        if type(klass) is not ProgramClass:
            raise TypeError("dataclass() decorates a class of the program")
        if klass.__dict__.get("__hash__") is serial_hash:  # classes.make's, not the program's: dataclass
            del klass.__hash__  # decides the hash as for any class without one of its own
        made = dataclasses.dataclass(klass, **options)
        if made.__hash__ is object.__hash__:  # hashed by identity (eq=False): by serial, as make does
            made.__hash__ = serial_hash
        return made
    return wrap if cls is None else wrap(cls)


def _record(typename, base, methods: dict):
    return make(typename, (base,), {**methods, "__slots__": (), "__module__": "__main__", "__qualname__": typename})


def namedtuple(typename, field_names, *, rename=False, defaults=None):
    base = collections.namedtuple(typename, field_names, rename=rename, defaults=defaults, module="__main__")
    return _record(typename, base, {})


def NamedTuple(typename, fields=None, /, **kwargs):  # typing's name
    """typing.NamedTuple's functional form; as a base, classes.build_class calls named_record."""
    pairs = list(fields) if fields is not None else list(kwargs.items())
    return namedtuple(typename, [name for name, _ in pairs])


def named_record(typename: str, namespace: dict):
    """`class P(NamedTuple): x: int; y: int = 0` (and its methods), as typing makes it."""
    names = list(namespace.get("__annotations__", {}))
    defaults = [namespace[name] for name in names if name in namespace]
    if any(name not in namespace for name in names[len(names) - len(defaults):]):
        raise TypeError(f"Non-default namedtuple field follows default field in {typename}")
    methods = {k: v for k, v in namespace.items() if k not in names and k not in ("__module__", "__qualname__")}
    base = collections.namedtuple(typename, names, defaults=defaults or None, module="__main__")
    return _record(typename, base, methods)


def _capture(name, bases, namespace):
    return namespace


def _generic(cls: type, params: object) -> types.GenericAlias:
    """`Queue[int]` of a class deriving from typing's Generic or Protocol: an alias, as typing's."""
    return types.GenericAlias(cls, params)


def _typing_base(name: str) -> ProgramClass:
    """typing's Generic and Protocol as bases of the program's classes (they only annotate)."""
    return ProgramClass(name, (), {"__slots__": (), "__module__": "typing", "__qualname__": name,
                                   "__class_getitem__": classmethod(_generic)})


Generic, Protocol = _typing_base("Generic"), _typing_base("Protocol")
MIXINS = {STR: str, INT: int, float: float}  # the data types an enum may mix in (`class Shape(str, Enum)`)


def build_class(body, name, *bases, **keywords):
    """The `__build_class__` of a program's class statements (classes.py says what it allows)."""
    abstract = keywords == {"metaclass": ABC_META}  # made as ABCMeta makes it (enums.py)
    if keywords and not abstract:
        raise Forbidden(f"class {name}: class keywords ({', '.join(keywords)}) are not allowed "
                        f"(a metaclass reaches the interpreter)")
    # `Generic[T]`, `Protocol[T]`, `Queue[int]` as a base: the class they alias
    bases = tuple(base.__origin__ if type(base) is types.GenericAlias and type(base.__origin__) is ProgramClass
                  else base for base in bases)
    if any(type(base) is ProgramEnumType for base in bases) and not abstract:
        mixed = tuple(MIXINS.get(base, base) for base in bases)
        for base in mixed:
            if type(base) is not ProgramEnumType and base not in MIXINS.values():
                raise Forbidden(f"class {name}: an enum may derive only from enum's classes, the program's enums "
                                f"and str, int or float, not from {base!r:.60}")
        return builtins.__build_class__(body, name, *mixed, metaclass=ProgramEnumType)
    for base in bases:
        if base is NamedTuple or base is typing.TypedDict:
            if len(bases) > 1:
                raise Forbidden(f"class {name}: a {'NamedTuple' if base is NamedTuple else 'TypedDict'} has no other base")
        elif type(base) is not ProgramClass and base not in EXCEPTION_TYPES:
            raise Forbidden(f"class {name}: a class may derive only from the program's own classes, the "
                            f"exception classes, enum's, typing's NamedTuple, TypedDict, Generic and Protocol "
                            f"and abc.ABC, not from {base!r:.60}")
    namespace = builtins.__build_class__(body, name, metaclass=_capture)
    if bases and bases[0] is NamedTuple:
        return named_record(name, namespace)
    if bases and bases[0] is typing.TypedDict:  # typing makes it: a dict's type, only annotations
        return typing.TypedDict(name, namespace.get("__annotations__", {}))
    return make(name, bases, namespace, abstract)


MEMBERS = {
    "dataclasses": {"dataclass": dataclass, "field": dataclasses.field, "fields": dataclasses.fields,
                    "MISSING": dataclasses.MISSING, "KW_ONLY": dataclasses.KW_ONLY, "asdict": dataclasses.asdict,
                    "astuple": dataclasses.astuple, "replace": dataclasses.replace,
                    "is_dataclass": dataclasses.is_dataclass, "FrozenInstanceError": dataclasses.FrozenInstanceError},
}
