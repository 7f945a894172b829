"""The type of a stand-in module (modules.py makes them, attributes.py reads their members).

Its own module so that the rule of `obj.name` (attributes.py) knows a stand-in module without
importing the stand-ins, which use that rule themselves (named.py: operator.attrgetter)."""
from __future__ import annotations

from .classes import serial_hash


class Module:
    """A stand-in module: its members are plain attributes (read through runtime's $attr); a
    fresh one per import, hashed by serial (classes.serial_hash)."""

    __hash__ = serial_hash

    def __init__(self, name: str, members: dict[str, object]) -> None:
        self.__dict__.update(members)
        self.__dict__["__name__"] = name

    def __repr__(self) -> str:
        return f"<module {self.__dict__['__name__']!r} (sandbox stand-in)>"
