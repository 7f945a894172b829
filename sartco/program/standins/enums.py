"""The stand-ins of `enum` and `abc`: bases that make special classes of the program.

enum: `Enum`, `IntEnum`, `StrEnum`, `Flag`, `IntFlag` are enum's own classes remade with
classes.ProgramEnumType (enum's EnumType, which checks a class body's names as classes.make does),
so a program's `class Color(Enum)` is a real enum: members, `auto()`, iteration, `len`,
`Color['RED']`, `Color('red')`, `.name`/`.value`, members in sets and dicts (they hash by name),
`@unique`, the functional API (`Enum('Color', 'RED GREEN')`). What a program reads of an enum
goes through the attribute rule (attributes.py): its members, what its own classes define,
`name`, `value`, `__members__`, never enum's machinery (INTERNALS: `_member_map_`,
`_member_type_` (a real type), `_new_member_`, ...) nor the metaclass. In a class statement
`str` and `int` (conversions.py's) stand for Python's own as a mixin (`class Shape(str, Enum)`).

abc: `ABC` is a program class of the sandbox's (no ABCMeta runs): a class deriving from it gets
`__abstractmethods__` as ABCMeta computes it (classes.make), so instantiating one with an
abstract method left raises Python's TypeError. `metaclass=ABCMeta` (the only class keyword a
program may write) does the same without the base. `abstractmethod` marks the program's own
functions, properties, static and class methods only.
"""
from __future__ import annotations

import abc
import enum
import types
from typing import Any

from .budget import Forbidden
from .classes import FILENAME, ProgramClass, ProgramEnumType, set_abstract_methods


def _remade(base: type) -> type:
    namespace = ProgramEnumType.__prepare__(base.__name__, (base,))
    namespace.update({"__module__": "enum", "__qualname__": base.__name__})
    made: type = ProgramEnumType(base.__name__, (base,), namespace)
    return made


BASES = {base: _remade(base) for base in (enum.Enum, enum.IntEnum, enum.StrEnum, enum.Flag, enum.IntFlag)}


def _internals() -> frozenset[str]:
    """Enum's machinery: every `_name` that EnumType and enum's classes put on a class or member."""
    names: set[str] = set()
    for base in BASES.values():
        probe = base("Probe", ["A"])  # a real enum of this kind (the functional API)
        for space in (*(vars(k) for k in type(probe.A).__mro__), vars(probe.A)):
            names.update(n for n in space if n[:1] == "_" and n[:2] != "__")
    return frozenset(names - {"_name_", "_value_"})


INTERNALS = _internals()


def is_enum(obj: object) -> bool:
    """An enum class of the program's, or one of its members."""
    return type(obj) is ProgramEnumType or type(type(obj)) is ProgramEnumType


ABC = ProgramClass("ABC", (), {"__slots__": (), "__module__": "abc", "__qualname__": "ABC"})
set_abstract_methods(ABC)  # (none: what makes its subclasses abstract classes)


class ABCMeta:
    """`metaclass=ABCMeta`: records.build_class makes the class as it makes one deriving from ABC."""

    __slots__ = ()

    def __repr__(self) -> str:
        return "<class 'abc.ABCMeta'>"


ABC_META = ABCMeta()


def abstractmethod(funcobj: Any) -> Any:
    """abc.abstractmethod, on the program's own functions (and their property/static/class methods)."""
    inner = funcobj.__func__ if type(funcobj) in (staticmethod, classmethod) else \
        funcobj.fget if type(funcobj) is property else funcobj
    if type(inner) is not types.FunctionType or inner.__code__.co_filename != FILENAME:
        raise Forbidden("abstractmethod() marks the program's own functions only")
    return abc.abstractmethod(funcobj)


MEMBERS = {
    "enum": {**{base.__name__: made for base, made in BASES.items()}, "auto": enum.auto, "unique": enum.unique},
    "abc": {"ABC": ABC, "ABCMeta": ABC_META, "abstractmethod": abstractmethod},
}
