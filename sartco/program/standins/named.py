"""Stand-ins that take attribute names as strings (operator.attrgetter, operator.methodcaller):
each name is read by the run-time rule of `x.name` (attributes.read), and a name with two
leading underscores only where the source may name it (classes.READABLE), so no string reaches
what an attribute cannot.
Any future stand-in that reads attributes by name (functools.wraps' `assigned`/`updated`, ...)
reads them through `read`."""
from __future__ import annotations

from typing import Any

from .attributes import read as attribute
from .budget import Forbidden
from .classes import READABLE, serial_hash


def read(obj: Any, name: object) -> Any:
    """`obj.name` for a name given as a string (dotted names as attrgetter takes them)."""
    if type(name) is not str:
        raise TypeError(f"attribute name must be a str, not {type(name).__name__}")
    for part in name.split("."):
        if part[:2] == "__" and part not in READABLE:
            raise Forbidden(f"attributes starting with two underscores reach the interpreter: .{part}")
        obj = attribute(obj, part)
    return obj


class attrgetter:  # operator's name
    """operator.attrgetter(*names): f(obj) -> obj.name, or a tuple for several names."""

    __slots__ = ("_names",)
    __hash__ = serial_hash

    def __init__(self, name: str, *names: str) -> None:
        self._names = (name, *names)
        for n in self._names:
            if type(n) is not str:
                raise TypeError(f"attribute name must be a str, not {type(n).__name__}")

    def __call__(self, obj: Any) -> Any:
        if len(self._names) == 1:
            return read(obj, self._names[0])
        return tuple(read(obj, n) for n in self._names)

    def __repr__(self) -> str:
        return f"operator.attrgetter({', '.join(map(repr, self._names))})"


class methodcaller:  # operator's name
    """operator.methodcaller(name, *args, **kwargs): f(obj) -> obj.name(*args, **kwargs)."""

    __slots__ = ("_name", "_args", "_kwargs")
    __hash__ = serial_hash

    def __init__(self, name: str, /, *args: Any, **kwargs: Any) -> None:
        if type(name) is not str:
            raise TypeError("method name must be a string")
        self._name, self._args, self._kwargs = name, args, kwargs

    def __call__(self, obj: Any) -> Any:
        if "." in self._name:
            raise Forbidden(f"method name {self._name!r:.40} is not a method")
        return read(obj, self._name)(*self._args, **self._kwargs)

    def __repr__(self) -> str:
        return f"operator.methodcaller({self._name!r:.40}, ...)"
