"""Run one prepared program on a fresh board, inside the worker process.

The program's globals are `board`, `put`, `init_board`; its `__builtins__` is a small dict of
the allowed builtins (some wrapped: `range`, `round`, `sum`, `print`) plus the `$` helpers that
`check.py` inserted. The result board is the global `board` if it is a Board, else the most
recently created board. Every outcome is turned into `[ok, code, message, cells, puts]`.

Python exceptions map to codes: NameError -> name_error, TypeError -> type_error, ValueError ->
value_error, KeyError -> key_error, IndexError -> index_error, ZeroDivisionError ->
zero_division, RecursionError/MemoryError/OverflowError and exhausted length/integer budgets ->
resource_limit, a spent step budget -> timeout, WorldError -> its own code, Forbidden (a method
on an object that is not a list/dict/str/tuple, printf-style %) -> forbidden, anything else ->
runtime_error. A method that the object's (allowed) type lacks raises AttributeError, as in
plain Python, hence runtime_error.
"""
from __future__ import annotations

import gc
import math
import sys
from itertools import repeat
from operator import length_hint

from sartco.world import DEFAULT_COLS, DEFAULT_ROWS, Board, ErrorCode, WorldError, put

from .check import TYPE_METHODS, Forbidden, prepare
from .records import not_a_str

E = ErrorCode
INTS = (int, bool)
SEQS = frozenset({list, tuple, str, bytes})
SIZED = frozenset({list, tuple, str, bytes, dict, set, frozenset, range})
MESSAGE_CHARS = 400
CACHE_SIZE = 4096

# the current budgets, set by run() before each program (one program at a time per worker)
LENGTH = 1_000_000
INT_BITS = 65_536


class Limit(Exception):
    """A length or integer budget would be exceeded."""


def _too_long(n):
    raise Limit(f"a sequence of {n} items is longer than the limit of {LENGTH}")


def _too_big(bits):
    raise Limit(f"an integer of about {int(bits)} bits is larger than the limit of {INT_BITS}")


# --- checked operators ------------------------------------------------------------------------

def _add(a, b):
    ta = type(a)
    if ta in SEQS and type(b) is ta and len(a) + len(b) > LENGTH:
        _too_long(len(a) + len(b))
    return a + b


def _mul(a, b):
    ta, tb = type(a), type(b)
    if ta in INTS:
        if tb in INTS:
            if a.bit_length() + b.bit_length() > INT_BITS:
                _too_big(a.bit_length() + b.bit_length())
        elif tb in SEQS and a > 0 and len(b) * a > LENGTH:
            _too_long(len(b) * a)
    elif ta in SEQS and tb in INTS and b > 0 and len(a) * b > LENGTH:
        _too_long(len(a) * b)
    return a * b


def _pow(a, b):
    if type(a) in INTS and type(b) in INTS and b > 0 and (a > 1 or a < -1):
        bits = b * math.log2(abs(a))
        if bits > INT_BITS:
            _too_big(bits)
    return a ** b


def _lshift(a, b):
    if type(a) in INTS and type(b) in INTS and a and b > 0 and a.bit_length() + b > INT_BITS:
        _too_big(a.bit_length() + b)
    return a << b


def _mod(a, b):
    if type(a) is str or type(a) is bytes:
        raise Forbidden("printf-style % formatting is not allowed; use an f-string")
    return a % b


def _grow(lst, items):
    """lst.extend(items) within the length budget: checked before for sized items, after for
    any other iterable."""
    n = len(items) if type(items) in SIZED else 0
    if len(lst) + n > LENGTH:
        _too_long(len(lst) + n)
    lst.extend(items)
    if len(lst) > LENGTH:
        _too_long(len(lst))


def _iadd(a, b):
    if type(a) is list:  # list += is list.extend
        _grow(a, b)
        return a
    return _add(a, b)


def _imul(a, b):
    if type(a) is not list:
        return _mul(a, b)
    if type(b) in INTS and b > 0 and len(a) * b > LENGTH:
        _too_long(len(a) * b)
    a *= b
    return a


def _iitem(obj, key, op, value):
    """obj[key] op= value, `op` being one of the checked in-place helpers ($iadd, ...)."""
    obj[key] = op(obj[key], value)


def _len(s):
    if len(s) > LENGTH:
        _too_long(len(s))
    return s


def _attr(obj, name):
    allowed = TYPE_METHODS.get(type(obj))
    if allowed is None:
        raise Forbidden(f".{name} is allowed only on lists, dicts, strings and tuples, not on {type(obj).__name__}")
    if name not in allowed:
        raise AttributeError(f"'{type(obj).__name__}' object has no attribute '{name}'")
    if name == "extend":
        return _extender(obj)
    return getattr(obj, name)


def _extender(obj):
    def extend(items):
        _grow(obj, items)
    return extend


# --- wrapped builtins -------------------------------------------------------------------------

def _range(*args):
    r = range(*args)
    try:
        n = len(r)
    except OverflowError:
        n = math.inf
    if n > LENGTH:
        raise Limit(f"range of {n} items is longer than the limit of {LENGTH}")
    return r


def _round(number, ndigits=None):
    if ndigits is not None and type(ndigits) in INTS and abs(ndigits) > 10_000:
        raise Limit(f"round() with ndigits={ndigits} is not allowed")
    return round(number) if ndigits is None else round(number, ndigits)


def _sum(iterable, start=0):
    if type(start) in SEQS:
        items = list(iterable)
        total = len(start) + sum(len(x) for x in items if type(x) in SIZED)
        if total > LENGTH:
            _too_long(total)
        return sum(items, start)
    return sum(iterable, start)


def _print(*args, **kwargs):
    return None


BUILTINS = {
    "range": _range, "zip": zip, "enumerate": enumerate, "len": len, "min": min, "max": max,
    "abs": abs, "sum": _sum, "sorted": sorted, "reversed": reversed, "any": any, "all": all,
    "round": _round, "divmod": divmod, "int": int, "str": str, "bool": bool, "list": list,
    "tuple": tuple, "dict": dict, "set": set, "print": _print,
    "$add": _add, "$mul": _mul, "$pow": _pow, "$lshift": _lshift, "$mod": _mod,
    "$iadd": _iadd, "$imul": _imul, "$ipow": _pow, "$ilshift": _lshift, "$imod": _mod,
    "$iitem": _iitem, "$slice": slice, "$len": _len, "$attr": _attr,
}

# --- compile (cached by exact source text: the verdict and code object depend on nothing else) --

_cache: dict[str, tuple] = {}


def compile_program(source: str, limits, cache: bool = True) -> tuple:
    """(code object, None, "") or (None, error code, message): the source's type and size
    checked, then parsed, checked, instrumented and compiled (see check.py)."""
    if type(source) is not str:
        return (None, E.TYPE_ERROR, not_a_str(source))
    if len(source) > limits.source:
        return (None, E.RESOURCE_LIMIT, f"the program has {len(source)} characters; the limit is {limits.source}")
    hit = _cache.get(source) if cache else None
    if hit is not None:
        return hit
    collecting = gc.isenabled()
    try:
        # parsing allocates thousands of syntax-tree nodes that form no cycles (they are freed by
        # reference counting): the cyclic collector would only traverse them in vain
        gc.disable()
        result = (prepare(source), None, "")
    except Forbidden as exc:
        result = (None, E.FORBIDDEN, str(exc))
    except SyntaxError as exc:
        result = (None, E.SYNTAX_ERROR, f"line {exc.lineno}: {exc.msg}" if exc.lineno else str(exc.msg))
    except (ValueError, UnicodeError) as exc:  # e.g. null bytes, lone surrogates
        result = (None, E.SYNTAX_ERROR, str(exc))
    except (RecursionError, MemoryError) as exc:
        result = (None, E.RESOURCE_LIMIT, f"the program is too deeply nested to compile ({type(exc).__name__})")
    except Exception as exc:  # noqa: BLE001 - a compiler failure must not end the worker
        result = (None, E.RUNTIME_ERROR, f"{type(exc).__name__}: {exc}")
    finally:
        if collecting:
            gc.enable()
    if cache:
        if len(_cache) >= CACHE_SIZE:
            _cache.clear()
        _cache[source] = result
    return result


# --- run ----------------------------------------------------------------------------------------

EXCEPTION_CODES = (
    (WorldError, None), (Forbidden, E.FORBIDDEN),
    ((Limit, RecursionError, MemoryError, OverflowError), E.RESOURCE_LIMIT),
    (NameError, E.NAME_ERROR), (TypeError, E.TYPE_ERROR), (ValueError, E.VALUE_ERROR),
    (KeyError, E.KEY_ERROR), (IndexError, E.INDEX_ERROR), (ZeroDivisionError, E.ZERO_DIVISION),
)


def _describe(exc: BaseException) -> str:
    line = None
    tb = exc.__traceback__
    while tb is not None:
        if tb.tb_frame.f_code.co_filename == "<program>":
            line = tb.tb_lineno
        tb = tb.tb_next
    try:
        if isinstance(exc, WorldError):
            text = exc.message
        elif isinstance(exc, (Limit, Forbidden)):
            text = str(exc)
        else:
            text = f"{type(exc).__name__}: {exc}"
    except Exception:  # noqa: BLE001
        text = type(exc).__name__
    text = text[:MESSAGE_CHARS]
    return f"line {line}: {text}" if line else text


def _classify(exc: BaseException) -> ErrorCode:
    for kinds, code in EXCEPTION_CODES:
        if isinstance(exc, kinds):
            return exc.code if code is None else code
    return E.RUNTIME_ERROR


def _depth() -> int:
    frame, n = sys._getframe(), 0
    while frame is not None:
        frame, n = frame.f_back, n + 1
    return n


def run(compiled: tuple, rows: int, cols: int, limits) -> list:
    """Run one program, given what compile_program made of it; return [ok, code or None,
    message, cells, puts]."""
    global LENGTH, INT_BITS
    code, error, message = compiled
    try:
        board = Board(rows, cols)
    except WorldError as exc:
        return [False, exc.code, exc.message, {}, 0]
    if code is None:
        return [False, error, message, {}, 0]
    last = [board]

    def init_board(rows=DEFAULT_ROWS, cols=DEFAULT_COLS):
        last[0] = Board(rows, cols)
        return last[0]

    LENGTH, INT_BITS = limits.length, limits.int_bits
    steps = repeat(True, limits.steps)
    names = dict(BUILTINS)
    names["$t"] = steps.__next__
    env = {"__builtins__": names, "board": board, "put": put, "init_board": init_board}
    old_limit = sys.getrecursionlimit()
    error = None
    try:
        sys.setrecursionlimit(_depth() + limits.depth + 10)
        try:
            exec(code, env)
        finally:
            sys.setrecursionlimit(old_limit)
    except BaseException as exc:  # noqa: BLE001 - everything the program does ends here
        if length_hint(steps) == 0:
            error, message = E.TIMEOUT, f"the program used up its budget of {limits.steps} steps (loop iterations and calls)"
        else:
            error, message = _classify(exc), _describe(exc)
        del exc
    result_board = env.get("board")
    if type(result_board) is not Board:
        result_board = last[0]
    env.clear()
    names.clear()
    try:
        cells, puts = result_board.cells(), result_board.puts
    except MemoryError:
        cells, puts = {}, 0
    return [error is None, error, message, cells, puts]
