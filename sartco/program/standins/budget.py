"""The length and integer budgets, kept inside C code too: the current program's budgets, the
stops that end it (Limit, Forbidden), the checked operators and the wrapped builtins with a size.

Each helper checks before it builds where the size is known in advance (`*`, `**`, `<<`,
`range`, `sum` of sequences) and otherwise checks the result before the program sees it: the
worker's address-space limit (Limits.memory) bounds what such a result may take on the way.
The budgets of formatting are in formatting.py, those of conversions (`int`, `str`, `repr`) in
conversions.py and those of str and list methods in methods.py; they all read the budgets here.

LENGTH and INT_BITS are the current program's budgets, set by runtime.run before each program
(a worker runs one program at a time; other modules read them as `budget.LENGTH`, never by
importing the value). STOPPED remembers the first budget stop or refusal of the
current program, so that a program that catches one (by a handler, or by a `finally: return`
that swallows it) still ends with that verdict.
"""
from __future__ import annotations

import math
from collections.abc import Callable, Iterable
from typing import Any, NoReturn, SupportsIndex

LENGTH = 1_000_000
INT_BITS = 65_536
STOPPED: BaseException | None = None  # the current program's first Limit or Forbidden

INTS = (int, bool)
SEQS = frozenset({list, tuple, str, bytes})
SIZED = frozenset({list, tuple, str, bytes, dict, set, frozenset, range})


class _Stop(Exception):
    """A budget stop or a refusal: the first one of a program is remembered in STOPPED."""

    def __init__(self, message: str) -> None:
        global STOPPED
        super().__init__(message)
        if STOPPED is None:
            STOPPED = self


class Limit(_Stop):
    """A length or integer budget would be exceeded."""


class Forbidden(_Stop):
    """A construct outside the allowed subset (found before running, or at run time)."""

    position = (0, 0)


# what no handler, finally body or context manager of a program may swallow: a budget stop, a
# refusal, and the interpreter's own stops (runtime's $caught and $final, modules.suppress)
STOPS = (Limit, Forbidden, MemoryError, RecursionError)


def too_long(n: float) -> NoReturn:
    raise Limit(f"a sequence of {n} items is longer than the limit of {LENGTH}")


def too_big(bits: float) -> NoReturn:
    raise Limit(f"an integer of about {int(bits)} bits is larger than the limit of {INT_BITS}")


def checked_len(s: Any) -> Any:
    if len(s) > LENGTH:
        too_long(len(s))
    return s


# --- checked operators ------------------------------------------------------------------------

def add(a: Any, b: Any) -> Any:
    ta = type(a)
    if ta in SEQS and type(b) is ta and len(a) + len(b) > LENGTH:
        too_long(len(a) + len(b))
    return a + b


def mul(a: Any, b: Any) -> Any:
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


def power(a: Any, b: Any, mod: Any = None) -> Any:
    if mod is None and type(a) in INTS and type(b) in INTS and b > 0 and (a > 1 or a < -1):
        bits = b * math.log2(abs(a))
        if bits > INT_BITS:
            too_big(bits)
    return a ** b if mod is None else pow(a, b, mod)


def lshift(a: Any, b: Any) -> Any:
    if type(a) in INTS and type(b) in INTS and a and b > 0 and a.bit_length() + b > INT_BITS:
        too_big(a.bit_length() + b)
    return a << b


def grow(lst: list[Any], items: Any) -> None:
    """lst.extend(items) within the length budget: checked before for sized items, after for
    any other iterable."""
    n = len(items) if type(items) in SIZED else 0
    if len(lst) + n > LENGTH:
        too_long(len(lst) + n)
    lst.extend(items)
    if len(lst) > LENGTH:
        too_long(len(lst))


def iadd(a: Any, b: Any) -> Any:
    if type(a) is list:  # list += is list.extend
        grow(a, b)
        return a
    return add(a, b)


def imul(a: Any, b: Any) -> Any:
    if type(a) is not list:
        return mul(a, b)
    if type(b) in INTS and b > 0 and len(a) * b > LENGTH:
        too_long(len(a) * b)
    a *= b
    return a


def iitem(obj: Any, key: Any, op: Callable[[Any, Any], Any], value: Any) -> None:
    """obj[key] op= value, `op` being one of the checked in-place helpers."""
    obj[key] = op(obj[key], value)


# --- wrapped builtins ---------------------------------------------------------------------------

def checked_range(*args: SupportsIndex) -> range:
    r = range(*args)
    n: float
    try:
        n = len(r)
    except OverflowError:
        n = math.inf
    if n > LENGTH:
        raise Limit(f"range of {n} items is longer than the limit of {LENGTH}")
    return r


def checked_round(number: Any, ndigits: Any = None) -> Any:
    if ndigits is not None and type(ndigits) in INTS and abs(ndigits) > 10_000:
        raise Limit(f"round() with ndigits={ndigits} is not allowed")
    return round(number) if ndigits is None else round(number, ndigits)


def checked_sum(iterable: Iterable[Any], start: Any = 0) -> Any:
    if type(start) in SEQS:
        items = list(iterable)
        total = len(start) + sum(len(x) for x in items if type(x) in SIZED)
        if total > LENGTH:
            too_long(total)
        return sum(items, start)
    return sum(iterable, start)


def no_print(*args: object, **kwargs: object) -> None:
    return None
