"""The conversions a program calls with budgets: `int` (a long digit string is refused before it
is read), `str`, `repr` and `ascii` (the result is checked before the program sees it), and the
`int` and `str` types a program sees, which still work in isinstance checks and annotations.

No text a program makes of an object holds an address: Python's default reprs do
(`<function f at 0x7f3a...>`, `<__main__.P object at 0x55d1...>`), and an address differs between
processes. `relabel` writes each address as the serial of its first appearance in the program
(`<function f at 0x1>`, the next one `0x2`): str, repr, ascii, format, f-string fields, `%` and
str.format (formatting.py) and the messages (runtime.describe) go through it."""
from __future__ import annotations

import math
import re

from . import budget
from .budget import checked_len, too_big


def to_int(x=0, *args, **kwargs):
    if type(x) in (str, bytes) and (args or kwargs):
        base = args[0] if args else kwargs.get("base", 10)
        bits_per_digit = math.log2(base) if type(base) is int and 2 <= base <= 36 else 6
        digits = len(x.strip())
        if digits * bits_per_digit > budget.INT_BITS + 64:
            too_big(digits * bits_per_digit)
    return int(x, *args, **kwargs)


ADDRESSES: dict[str, str] = {}  # an address in a default repr -> its serial: the current program's
_ADDRESS = re.compile(" at 0x[0-9a-f]{6,}")  # how Python's default reprs give an address (%p)


def _serial(match: re.Match[str]) -> str:
    address = match.group()
    serial = ADDRESSES.get(address)
    if serial is None:
        serial = ADDRESSES[address] = f" at 0x{len(ADDRESSES) + 1:x}"
    return serial


def relabel(text: str) -> str:
    """`text` with every address of a default repr written as its serial (see the docstring)."""
    return _ADDRESS.sub(_serial, text) if " at 0x" in text else text


def to_str(*args, **kwargs):
    if len(args) == 1 and not kwargs and type(args[0]) is str:
        return args[0]
    return checked_len(relabel(str(*args, **kwargs)))


def to_repr(value):
    return checked_len(relabel(repr(value)))


def to_ascii(value):
    return checked_len(relabel(ascii(value)))


class _TypeLike(type):
    """The type of the `int` and `str` a program sees: callables with budgets that still work
    in isinstance/issubclass checks and annotations."""

    def __instancecheck__(cls, obj):
        return isinstance(obj, cls.real)

    def __subclasscheck__(cls, sub):
        return issubclass(sub, cls.real)

    def __call__(cls, *args, **kwargs):
        return cls.convert(*args, **kwargs)

    def __repr__(cls):
        return repr(cls.real)


def _type_like(real: type, convert):
    return _TypeLike(real.__name__, (), {"real": real, "convert": staticmethod(convert), "__module__": "builtins"})


INT = _type_like(int, to_int)
STR = _type_like(str, to_str)
