"""The length and integer budgets, kept inside C code too: checked operators, conversions,
formatting and string methods that refuse to build a too-long sequence or a too-large integer.

Each helper checks before it builds where the size is known in advance (`*`, `**`, `<<`,
`int(text, 16)`, widths, joins, replacements) and otherwise checks the result before the
program sees it (`str(x)`, `repr(x)`, case mappings): the worker's address-space limit
(Limits.memory) bounds what such a result may take on the way.

Formatting (`%`, `str.format`, `format()`, f-strings with computed specs) accepts widths and
precisions of at most three digits, no `*` widths, and format fields that name an argument
(`{0}`, `{name}`, `{}`) but never read an attribute or an item of it (`{0.x}`, `{0[k]}`).

LENGTH and INT_BITS are the current program's budgets, set by runtime.run before each program
(a worker runs one program at a time). STOPPED remembers the first budget stop or refusal of the
current program, so that a program that catches one (by a handler, or by a `finally: return`
that swallows it) still ends with that verdict.
"""
from __future__ import annotations

import math
import re
import string

LENGTH = 1_000_000
INT_BITS = 65_536
STOPPED: BaseException | None = None  # the current program's first Limit or Forbidden

INTS = (int, bool)
SEQS = frozenset({list, tuple, str, bytes})
SIZED = frozenset({list, tuple, str, bytes, dict, set, frozenset, range})
SPEC_DIGITS = 3  # most digits of a width or precision
_LONG_NUMBER = re.compile(r"\d{%d,}" % (SPEC_DIGITS + 1))
# one printf-style conversion: %[(key)][flags][width][.precision][length]type
_PRINTF = re.compile(r"%(?:\([^)]*\))?[-#0 +]*(\*|\d+)?(?:\.(\*|\d*))?")


class _Stop(Exception):
    """A budget stop or a refusal: the first one of a program is remembered in STOPPED."""

    def __init__(self, message: str):
        global STOPPED
        super().__init__(message)
        if STOPPED is None:
            STOPPED = self


class Limit(_Stop):
    """A length or integer budget would be exceeded."""


class Forbidden(_Stop):
    """A construct outside the allowed subset (found before running, or at run time)."""

    position = (0, 0)


def too_long(n):
    raise Limit(f"a sequence of {n} items is longer than the limit of {LENGTH}")


def too_big(bits):
    raise Limit(f"an integer of about {int(bits)} bits is larger than the limit of {INT_BITS}")


def checked_len(s):
    if len(s) > LENGTH:
        too_long(len(s))
    return s


# --- checked operators ------------------------------------------------------------------------

def add(a, b):
    ta = type(a)
    if ta in SEQS and type(b) is ta and len(a) + len(b) > LENGTH:
        too_long(len(a) + len(b))
    return a + b


def mul(a, b):
    ta, tb = type(a), type(b)
    if ta in INTS:
        if tb in INTS:
            if a.bit_length() + b.bit_length() > INT_BITS:
                too_big(a.bit_length() + b.bit_length())
        elif tb in SEQS and a > 0 and len(b) * a > LENGTH:
            too_long(len(b) * a)
    elif ta in SEQS and tb in INTS and b > 0 and len(a) * b > LENGTH:
        too_long(len(a) * b)
    return a * b


def power(a, b, mod=None):
    if mod is None and type(a) in INTS and type(b) in INTS and b > 0 and (a > 1 or a < -1):
        bits = b * math.log2(abs(a))
        if bits > INT_BITS:
            too_big(bits)
    return a ** b if mod is None else pow(a, b, mod)


def lshift(a, b):
    if type(a) in INTS and type(b) in INTS and a and b > 0 and a.bit_length() + b > INT_BITS:
        too_big(a.bit_length() + b)
    return a << b


def _check_spec(spec: str) -> str:
    if _LONG_NUMBER.search(spec):
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
    return checked_len(a % b)


def grow(lst, items):
    """lst.extend(items) within the length budget: checked before for sized items, after for
    any other iterable."""
    n = len(items) if type(items) in SIZED else 0
    if len(lst) + n > LENGTH:
        too_long(len(lst) + n)
    lst.extend(items)
    if len(lst) > LENGTH:
        too_long(len(lst))


def iadd(a, b):
    if type(a) is list:  # list += is list.extend
        grow(a, b)
        return a
    return add(a, b)


def imul(a, b):
    if type(a) is not list:
        return mul(a, b)
    if type(b) in INTS and b > 0 and len(a) * b > LENGTH:
        too_long(len(a) * b)
    a *= b
    return a


def iitem(obj, key, op, value):
    """obj[key] op= value, `op` being one of the checked in-place helpers."""
    obj[key] = op(obj[key], value)


# --- formatting -------------------------------------------------------------------------------

class _Formatter(string.Formatter):
    """str.format without attribute or item access in fields, widths bounded."""

    def get_field(self, field_name, args, kwargs):
        if "." in field_name or "[" in field_name:
            raise Forbidden(f"format fields may not read attributes or items: {{{field_name[:40]}}}")
        return super().get_field(field_name, args, kwargs)

    def format_field(self, value, format_spec):
        return format(value, _check_spec(format_spec))


_FORMATTER = _Formatter()


def str_format(text: str, args, kwargs) -> str:
    return checked_len(_FORMATTER.vformat(text, args, kwargs))


def format_value(value, spec=""):
    """format(value, spec), the builtin, and f-string fields whose spec is computed."""
    if type(spec) is not str:
        raise TypeError(f"format() argument 2 must be str, not {type(spec).__name__}")
    return checked_len(format(value, _check_spec(spec)))


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
    return format_value(converted(value, conversion), spec)


# --- conversions --------------------------------------------------------------------------------

def to_int(x=0, *args, **kwargs):
    if type(x) in (str, bytes) and (args or kwargs):
        base = args[0] if args else kwargs.get("base", 10)
        bits_per_digit = math.log2(base) if type(base) is int and 2 <= base <= 36 else 6
        digits = len(x.strip())
        if digits * bits_per_digit > INT_BITS + 64:
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


# --- string and list methods with a size the budget must see ----------------------------------

def _case(method):
    def checked(s):
        bound = getattr(s, method)

        def call(*args, **kwargs):
            return checked_len(bound(*args, **kwargs))
        return call
    return checked


def _join(sep):
    def join(iterable):
        items = list(iterable)
        total = len(sep) * max(0, len(items) - 1)
        for item in items:
            if type(item) is str:
                total += len(item)
        if total > LENGTH:
            too_long(total)
        return sep.join(items)
    return join


def _replace(s):
    def replace(old, new, count=-1):
        if type(old) is str and type(new) is str and len(new) > len(old):
            n = s.count(old) if old else len(s) + 1
            if type(count) is int and 0 <= count < n:
                n = count
            if len(s) + n * (len(new) - len(old)) > LENGTH:
                too_long(len(s) + n * (len(new) - len(old)))
        return s.replace(old, new, count)
    return replace


def _padder(method):
    def checked(s):
        bound = getattr(s, method)

        def pad(width, *args):
            if type(width) in INTS and width > LENGTH:
                too_long(width)
            return bound(width, *args)
        return pad
    return checked


def _format_method(s):
    def format_(*args, **kwargs):
        return str_format(s, args, kwargs)
    return format_


def _format_map(s):
    def format_map(mapping):
        return str_format(s, (), mapping)
    return format_map


def _extender(obj):
    def extend(items):
        grow(obj, items)
    return extend


# name -> (object -> the bound method the program gets), for methods whose result the budget
# must see; every other allowed method is the object's own
CHECKED_METHODS = {
    **{m: _case(m) for m in ("upper", "lower", "title", "capitalize", "swapcase", "casefold")},
    **{m: _padder(m) for m in ("center", "ljust", "rjust", "zfill")},
    "join": _join, "replace": _replace, "format": _format_method, "format_map": _format_map,
    "extend": _extender,
}


# --- wrapped builtins ---------------------------------------------------------------------------

def checked_range(*args):
    r = range(*args)
    try:
        n = len(r)
    except OverflowError:
        n = math.inf
    if n > LENGTH:
        raise Limit(f"range of {n} items is longer than the limit of {LENGTH}")
    return r


def checked_round(number, ndigits=None):
    if ndigits is not None and type(ndigits) in INTS and abs(ndigits) > 10_000:
        raise Limit(f"round() with ndigits={ndigits} is not allowed")
    return round(number) if ndigits is None else round(number, ndigits)


def checked_sum(iterable, start=0):
    if type(start) in SEQS:
        items = list(iterable)
        total = len(start) + sum(len(x) for x in items if type(x) in SIZED)
        if total > LENGTH:
            too_long(total)
        return sum(items, start)
    return sum(iterable, start)


def no_print(*args, **kwargs):
    return None
