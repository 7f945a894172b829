"""Run one prepared program on a fresh board, inside the program's own confined process (a child
of the template, template.py), and make the answer it sends (`answer`: a put log and an outcome).

The program's globals (namespace()) are `__name__`, `board`, `put`, `init_board`; under PAPER
semantics namespaces.paper splits them into the authors' globals and locals. Its `__builtins__` is BUILTINS (no
program can reach the dict, so one serves them all; `$t` is set per program): the allowed
builtins (some with budgets: `range`, `round`, `sum`, `pow` in budget.py, `int`, `str`, `repr`,
`ascii` in conversions.py, `format` in formatting.py; `print` does nothing), a refusing
stand-in for every other builtin name (calling it is `forbidden`), `__import__` for the
stand-in modules (modules.py), `__build_class__` for class statements (records.py), and the `$` helpers that nodes.py inserts. The result board is
the global `board` if it is a Board, else the most recently created board. Every outcome is
turned into (ok, code, message, the board put built), the message cleaned (execution.clean).

Python exceptions map to codes by EXCEPTION_CODES (a spent step budget: timeout; any other
exception: runtime_error). A budget stop or refusal is the verdict even when the program swallowed
it (budget.STOPPED, a spent step counter; a RecursionError or MemoryError seen by a finally body,
`$final`). No internal error ever ends as `ok` (it is `harness_error` here, and the parent makes it
the program's `runtime_error`: the process is the program's, verdict.py). RAN counts its programs.
"""
from __future__ import annotations

import binascii
import builtins
import gc
import json
import marshal
import sys
from itertools import repeat
from operator import length_hint
from typing import Any

from sartco.world import DEFAULT_COLS, DEFAULT_ROWS, Board, ErrorCode, WorldError, put

from ..standins import budget, conversions, formatting
from . import namespaces
from ..check.allowed import ALLOWED_BUILTINS, DENIED
from ..standins.budget import Forbidden, Limit
from ..execution import MODULE, PAPER, Limits, clean, not_a_str
from ..check.instrument import prepare
from ..standins import attributes, chance
from ..standins.classes import SERIALS, program_hash, type_of
from ..standins.records import build_class
from ..standins.modules import forget_typing, import_module, load
from ..standins.patterns import PATTERNS
from .result import checked

MESSAGE_CHARS = 400
_STEPS = repeat(True, 0)  # the current program's step counter


def _caught(exc):
    """The first statement of every except handler: budget stops and refusals go on."""
    if isinstance(exc, budget.STOPS) or length_hint(_STEPS) == 0:
        raise exc


def _final():
    """The first statement of every finally body: a RecursionError or MemoryError passing through
    is remembered as the program's stop (budget.STOPPED), so that a `return`, `break` or
    `continue` in the body cannot swallow it (budget stops of our own remember themselves)."""
    exc = sys.exc_info()[1]
    if budget.STOPPED is None and isinstance(exc, (RecursionError, MemoryError)):
        budget.STOPPED = exc


class _Refused:
    """A builtin that reaches the interpreter, files or the terminal, for a program that reads
    its name without binding it (instrument.py refuses the plain case before running)."""

    __slots__ = ("name",)

    def __init__(self, name):
        self.name = name

    def __call__(self, *args, **kwargs):
        raise Forbidden(f"{self.name} is not available in the sandbox: it reaches the interpreter, files or "
                        f"the terminal")

    def __repr__(self):
        return f"<{self.name}: not available in the sandbox>"


_OWN = {  # builtins of ours (with budgets); the rest of ALLOWED_BUILTINS are Python's own
    "range": budget.checked_range, "round": budget.checked_round, "sum": budget.checked_sum,
    "print": budget.no_print, "int": conversions.INT, "str": conversions.STR, "pow": budget.power,
    "format": formatting.format_value, "repr": conversions.to_repr, "ascii": conversions.to_ascii,
    "type": type_of, "hash": program_hash,
}
BUILTINS = {
    **{name: _Refused(name) for name in DENIED},
    **{name: _OWN.get(name) or getattr(builtins, name) for name in ALLOWED_BUILTINS},
    "__import__": import_module,  # what import statements call; no program can spell the name
    "__build_class__": build_class,  # what class statements call (classes.py)
    "$add": budget.add, "$mul": budget.mul, "$pow": budget.power, "$lshift": budget.lshift, "$mod": formatting.mod,
    "$iadd": budget.iadd, "$imul": budget.imul, "$ipow": budget.power, "$ilshift": budget.lshift,
    "$imod": formatting.mod, "$iitem": budget.iitem, "$slice": slice, "$len": budget.checked_len,
    "$attr": attributes.read, "$fields": attributes.fields, "$caught": _caught, "$final": _final,
    "$fstr": formatting.fstring_field, "$pattern": PATTERNS,
}

# --- compile ------------------------------------------------------------------------------------

def compile_program(source: str, limits, heads: dict[str, Any] | None = None, room: int = 0) -> tuple:
    """(code, None, "") or (None, error code, message): instrument.prepare(source, heads), `room` frames deeper (answer_item)."""
    if type(source) is not str:
        return (None, ErrorCode.TYPE_ERROR, not_a_str(source))
    if len(source) > limits.source:
        return (None, ErrorCode.RESOURCE_LIMIT, f"the program has {len(source)} characters; the limit is {limits.source}")
    collecting, deepest = gc.isenabled(), sys.getrecursionlimit()
    try:
        # parsing allocates thousands of syntax-tree nodes that form no cycles (they are freed by
        # reference counting): the cyclic collector would only traverse them in vain
        gc.disable()
        if room:
            sys.setrecursionlimit(deepest + room)
        return (prepare(source, heads), None, "")
    except Forbidden as exc:
        return (None, ErrorCode.FORBIDDEN, clean(str(exc)))
    except SyntaxError as exc:
        return (None, ErrorCode.SYNTAX_ERROR, clean(f"line {exc.lineno}: {exc.msg}" if exc.lineno else str(exc.msg)))
    except (ValueError, UnicodeError) as exc:  # e.g. null bytes, lone surrogates
        return (None, ErrorCode.SYNTAX_ERROR, clean(str(exc)))
    except RecursionError:
        return (None, ErrorCode.RESOURCE_LIMIT, "the program is too deeply nested to compile")
    except MemoryError:
        return (None, ErrorCode.RESOURCE_LIMIT, "the program's process ran out of memory while compiling it")
    except Exception as exc:  # a compiler failure must not end the process without an answer
        return (None, ErrorCode.HARNESS_ERROR, clean(f"internal error while compiling: {type(exc).__name__}: {exc}"))
    finally:
        if room:
            sys.setrecursionlimit(deepest)
        if collecting:
            gc.enable()


# --- run ----------------------------------------------------------------------------------------

EXCEPTION_CODES = (
    (WorldError, None), (Forbidden, ErrorCode.FORBIDDEN),
    ((Limit, RecursionError, MemoryError, OverflowError), ErrorCode.RESOURCE_LIMIT),
    (NameError, ErrorCode.NAME_ERROR), (TypeError, ErrorCode.TYPE_ERROR), (ValueError, ErrorCode.VALUE_ERROR),
    (KeyError, ErrorCode.KEY_ERROR), (IndexError, ErrorCode.INDEX_ERROR), (ZeroDivisionError, ErrorCode.ZERO_DIVISION),
)


def describe(exc: BaseException) -> str:
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
        elif isinstance(exc, MemoryError):
            text = "the program ran out of memory (MemoryError)"
        else:
            detail = str(exc)
            text = f"{type(exc).__name__}: {detail}" if detail else type(exc).__name__
    except BaseException:  # a program's __str__ may raise anything: the message is then the name
        text = type(exc).__name__
    text = conversions.relabel(text)[:MESSAGE_CHARS]
    return f"line {line}: {text}" if line else text


def classify(exc: BaseException) -> ErrorCode:
    for kinds, code in EXCEPTION_CODES:
        if isinstance(exc, kinds):
            return exc.code if code is None else code
    return ErrorCode.RUNTIME_ERROR


def _depth() -> int:
    frame, n = sys._getframe(), 0
    while frame is not None:
        frame, n = frame.f_back, n + 1
    return n


def namespace(board, init_board, name: str = "__main__") -> dict:
    """The globals of one program, a fresh module named `name` (`__main__`: a script, so
    `if __name__ == "__main__":` runs): `board`, `put`, `init_board`, `np` (numpy's stand-in, bound
    without an import as the authors' namespace bound it) and the sandbox's builtins.
    A new program also starts the `random` stand-in, the default hashes of its objects and the
    serials of addresses in its text afresh (chance.py, classes.serial_hash, conversions.relabel)."""
    chance.fresh()
    SERIALS.clear()
    conversions.ADDRESSES.clear()
    return {"__builtins__": BUILTINS, "__name__": name, "board": board, "put": put, "init_board": init_board,
            "np": NUMPY[RAN[0] - 1] if RAN[0] <= len(NUMPY) else load("numpy")}


# programs this process ran (_run counts): a child's first 32 bind np stand-ins the template made, one each
# (making one copies numpy's members: page faults in a child), and find typing's caches as the template emptied them
RAN, NUMPY = [0], [load("numpy") for _ in range(32)]


def run(compiled: tuple, rows: int, cols: int, limits, semantics: str = MODULE, source: str = "") -> list:
    """Run one program, given what compile_program made of it; return [ok, code or None,
    message, cells, puts] (see _run)."""
    ok, error, message, board = _run(compiled, rows, cols, limits, semantics, source)
    return [ok, error, message, {} if board is None else board.cells(), 0 if board is None else board.puts]


def answer(compiled: tuple[Any, Any, str], rows: int, cols: int, limits: Limits, semantics: str = MODULE,
           source: str = "") -> bytes:
    """What a child sends its template for one program, given compile_program's result: ASCII JSON
    [ok, code or None, message, rows, cols, log], `log` the puts of the result board as one flat
    list shape, colour, x, y, ... of plain str and int. The parent replays the log and decides
    the board (verdict.py): nothing else of the child's board leaves it."""
    return encode(*_run(compiled, rows, cols, limits, semantics, source))


def answer_item(item: bytes, rows: int, cols: int, limits: Limits, semantics: str = MODULE) -> bytes:
    """answer() of an item of compiled.prepare's: base64 of marshalled (code, source); code None: compile here
    (the parent compiled it and judged its nesting: this stack, deeper than the parent's, must refuse nothing)."""
    code, source = marshal.loads(binascii.a2b_base64(item))
    return answer((code, None, "") if code else compile_program(source, limits, room=50), rows, cols, limits, semantics, source)


def encode(ok, error, message, board) -> bytes:
    log: list = []
    if board is not None:
        for (shape, color), x, y in board.log:
            log += (str(shape), str(color), int(x), int(y))
    shape = (board.rows, board.cols) if board is not None else (0, 0)
    return json.dumps([ok, error, message, *shape, log]).encode("ascii")


def _run(compiled: tuple, rows: int, cols: int, limits, semantics: str = MODULE, source: str = "") -> tuple:
    """Run one program, given what compile_program made of it; return (ok, code or None,
    message, board): `board` is the result board as put built it (result.checked's replay), or
    None. The message is clean (execution.clean). PAPER semantics: separate globals and locals
    (namespaces.paper), and the board passed in is the one scored."""
    global _STEPS
    code, error, message = compiled
    try:
        board = Board(rows, cols)
    except WorldError as exc:
        return False, exc.code, exc.message, None
    if code is None:
        return False, error, message, None
    last = [board]

    def init_board(rows=DEFAULT_ROWS, cols=DEFAULT_COLS):
        last[0] = Board(rows, cols)
        return last[0]

    budget.LENGTH, budget.INT_BITS, budget.STOPPED = limits.length, limits.int_bits, None
    _STEPS = steps = repeat(True, limits.steps)
    BUILTINS["$t"] = steps.__next__  # no program can reach the dict: one serves them all
    RAN[0] += 1
    env = namespace(board, init_board)
    env, scope = namespaces.paper(env, source) if semantics == PAPER else namespaces.script(env)
    if RAN[0] > 1:
        forget_typing()  # typing's caches start empty: nothing of an earlier program is in them
    old_limit = sys.getrecursionlimit()
    error = None
    try:
        sys.setrecursionlimit(_depth() + limits.depth + 10)
        try:
            for part in code if type(code) is tuple else (code,):  # (a shared head's code, then its last line's)
                exec(part, env, scope)
        finally:
            sys.setrecursionlimit(old_limit)
    except BaseException as exc:  # everything the program does ends here
        error, message = _verdict(exc, limits)
        del exc
    # a budget stop, refusal, RecursionError or MemoryError that the program swallowed (finally:
    # return/break/continue, a StopIteration ending a map() early) is still its verdict
    if length_hint(steps) == 0 or budget.STOPPED is not None:
        error, message = _verdict(budget.STOPPED, limits)
    budget.STOPPED = None
    fresh = None
    try:
        result_board = board if semantics == PAPER else env.get("board")
        if type(result_board) is not Board:
            result_board = last[0]
        env.clear()
        scope.clear()
        SERIALS.clear()  # (the program's objects go with it)
        fresh, forged = checked(result_board)  # only what put placed leaves the worker
        if forged is not None:
            error, message = ErrorCode.FORBIDDEN, forged
        message = clean(message)
    except MemoryError:
        error, message, fresh = ErrorCode.RESOURCE_LIMIT, "the sandbox ran out of memory while reading the board", None
    except Exception as exc:  # never `ok` after an internal error
        error, message, fresh = ErrorCode.HARNESS_ERROR, clean(f"internal error: {type(exc).__name__}"), None
    return error is None, error, message, fresh


def _verdict(exc: BaseException | None, limits) -> tuple:
    if length_hint(_STEPS) == 0:
        return ErrorCode.TIMEOUT, f"the program used up its budget of {limits.steps} steps (loop iterations and calls)"
    return classify(exc), describe(exc)
