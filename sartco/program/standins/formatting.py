"""Formatting within the budgets: printf-style `%`, `str.format`, `format()` and f-string fields.

Widths and precisions have at most SPEC_DIGITS digits, `*` widths are refused, and format
fields may name an argument (`{0}`, `{name}`, `{}`) but never read an attribute or an item of
it (`{0.x}`, `{0[k]}`); every result is checked against the length budget (budget.py), and
holds no address (conversions.relabel: each formatted value, or a `%` result with other values
than plain str, int, float and bool).
"""
from __future__ import annotations

import re
import string

from .budget import Forbidden, checked_len
from .conversions import relabel, to_ascii, to_repr, to_str

SPEC_DIGITS = 3  # most digits of a width or precision
_PLAIN = frozenset({str, int, float, bool})  # values whose text holds no address
LONG_NUMBER = re.compile(r"\d{%d,}" % (SPEC_DIGITS + 1))  # a width or precision with too many digits
# one printf-style conversion: %[(key)][flags][width][.precision][length]type
_PRINTF = re.compile(r"%(?:\([^)]*\))?[-#0 +]*(\*|\d+)?(?:\.(\*|\d*))?")


def _check_spec(spec: str) -> str:
    if LONG_NUMBER.search(spec):
        raise Forbidden(f"format widths and precisions above {'9' * SPEC_DIGITS} are not allowed: {spec[:40]!r}")
    return spec


def mod(a, b):
    """a % b; for a string, printf-style formatting with bounded widths."""
    t = type(a)
    if t is not str and t is not bytes:
        return a % b
    text = a if t is str else a.decode("latin-1")
    for m in _PRINTF.finditer(text):
        for number in m.groups():
            if number == "*":
                raise Forbidden("printf-style '*' widths are not allowed; write the width in the format")
            if number and len(number) > SPEC_DIGITS:
                _check_spec(number)
    values = b if type(b) is tuple else (b,)
    if t is bytes or all(type(v) in _PLAIN for v in values):
        return checked_len(a % b)
    return checked_len(relabel(a % b))


class _Formatter(string.Formatter):
    """str.format without attribute or item access in fields, widths bounded."""

    def get_field(self, field_name, args, kwargs):
        if "." in field_name or "[" in field_name:
            raise Forbidden(f"format fields may not read attributes or items: {{{field_name[:40]}}}")
        return super().get_field(field_name, args, kwargs)

    def format_field(self, value, format_spec):
        return relabel(format(value, _check_spec(format_spec)))


_FORMATTER = _Formatter()


def str_format(text: str, args, kwargs) -> str:
    return checked_len(_FORMATTER.vformat(text, args, kwargs))


def format_value(value, spec=""):
    """format(value, spec), the builtin, and f-string fields whose spec is computed."""
    if type(spec) is not str:
        raise TypeError(f"format() argument 2 must be str, not {type(spec).__name__}")
    return checked_len(relabel(format(value, _check_spec(spec))))


def converted(value, conversion: int):
    """An f-string field's value after its !s, !r or !a conversion (-1: none)."""
    if conversion == 115:
        return to_str(value)
    if conversion == 114:
        return to_repr(value)
    if conversion == 97:
        return to_ascii(value)
    return value


def fstring_field(value, conversion: int, spec: str):
    """An f-string field (`$fstr`, every field: nodes.py)."""
    if conversion == -1 and not spec and type(value) is str:
        return value
    return format_value(converted(value, conversion), spec)
