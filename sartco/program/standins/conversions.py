"""The conversions a program calls with budgets: `int` (a long digit string is refused before it
is read), `str`, `repr` and `ascii` (the result is checked before the program sees it), and the
`int` and `str` types a program sees, which still work in isinstance checks and annotations."""
from __future__ import annotations

import math

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


def to_str(*args, **kwargs):
    return checked_len(str(*args, **kwargs))


def to_repr(value):
    return checked_len(repr(value))


def to_ascii(value):
    return checked_len(ascii(value))


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
