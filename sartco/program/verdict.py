"""The parent decides: a child's end and answer -> an Execution, the board replayed here.

A child (child/template.py) sends only plain values: [ok, code or None, message, rows, cols, log], `log`
a flat list shape, colour, x, y, ... (runtime.answer). Nothing of the child's objects is trusted:
the parent checks every value's exact type, makes its own board of that size and replays the
log with the world's own `put` (sartco.world.rules), so the cells of every Execution are what put
built here, whatever happened in the child. How a child ended is the program's doing:

- killed at the wall time: `timeout`; wrote more than worker.ANSWER_BYTES: `resource_limit`;
- killed by the kernel (SIGKILL: out of memory; SIGXCPU: CPU time): `resource_limit`; another
  signal: `runtime_error`, "crashed (SIGSEGV)"; exit status worker.OUT_OF_MEMORY: `resource_limit`;
- any other exit without an answer, an answer that is not one (bytes after the JSON, wrong types,
  `harness_error` claimed by the child), a message too long: `runtime_error`;
- a log that put refuses, or a board over the world's limits: `forbidden`, "the board was changed
  outside put", with what put built of the log up to there.
`harness_error` is the parent's and the template's own failure alone (handle.py): a child that
ended before its walls were up ("unconfined": no program ran), a template that could not start,
died or answered garbage. No program can produce it.
"""
from __future__ import annotations

import json
import signal

from sartco.world import Board, ErrorCode, WorldError, put

from .execution import Execution, clean
from .child.result import FORGED
from .child.template import OUT_OF_MEMORY

MESSAGE_CHARS = 1 << 16  # far above any message runtime.py writes (400 characters, escaped, + a line number)
_CODES = {code.value: code for code in ErrorCode}


def failed(code: ErrorCode, message: str) -> Execution:
    return Execution(False, code, message, {}, 0)


def decide(how: bytes, status: int, answer: bytes, wall_time: float) -> Execution:
    """The Execution of one program from how its child ended and what it wrote."""
    if how == b"timeout":
        return failed(ErrorCode.TIMEOUT, f"the program ran longer than {wall_time:g} s")
    if how == b"overflow":
        return failed(ErrorCode.RESOURCE_LIMIT, "the program's process wrote more than its answer may hold")
    if how == b"unconfined":
        return failed(ErrorCode.HARNESS_ERROR, f"the sandbox could not confine the program's process (status {status}); "
                                               f"no program ran")
    if how == b"signal":
        return died(-status)
    if status != 0:
        return died(status)
    return _replayed(answer)


def died(status: int) -> Execution:
    """The verdict of a child that ended without an answer: `status` as subprocess gives it
    (negative: killed by that signal)."""
    if status == OUT_OF_MEMORY:
        return failed(ErrorCode.RESOURCE_LIMIT, "the program ran out of memory")
    if status in (-signal.SIGKILL, -signal.SIGXCPU):  # the kernel's OOM killer or the CPU limit
        return failed(ErrorCode.RESOURCE_LIMIT, f"the program's process was killed ({signal.Signals(-status).name}): "
                                                f"out of memory or CPU time")
    if status < 0:
        try:
            name = signal.Signals(-status).name
        except ValueError:
            name = f"signal {-status}"
        return failed(ErrorCode.RUNTIME_ERROR, f"the program crashed its process ({name})")
    return failed(ErrorCode.RUNTIME_ERROR, f"the program's process ended without an answer (status {status})")


def _replayed(answer: bytes) -> Execution:
    try:
        ok, code, message, rows, cols, log = json.loads(answer)
    except (ValueError, TypeError, RecursionError):
        return failed(ErrorCode.RUNTIME_ERROR, "the program's process sent an answer that is not one")
    error = _CODES.get(code) if type(code) is str else None
    if (type(ok) is not bool or type(message) is not str or type(log) is not list or len(log) % 4
            or (code is not None and error is None) or ok != (code is None) or len(message) > MESSAGE_CHARS):
        return failed(ErrorCode.RUNTIME_ERROR, "the program's process sent an answer that is not one")
    message = clean(message)
    if error is ErrorCode.HARNESS_ERROR:  # the child's own code failed: still the program's process
        error, message = ErrorCode.RUNTIME_ERROR, f"in the program's process: {message}"
    if rows == cols == 0 and not log:  # no board: the program never ran (refused, or a bad size)
        return Execution(ok, error, message, {}, 0)
    try:
        board = Board(rows, cols)
    except WorldError:
        return failed(ErrorCode.FORBIDDEN, f"{FORGED} (a board of {rows!r:.20} x {cols!r:.20})")
    for k in range(0, len(log), 4):
        try:
            put(board, *log[k:k + 4])
        except WorldError:
            return Execution(False, ErrorCode.FORBIDDEN, f"{FORGED} (its log of puts is not one that put wrote)",
                             board.cells(), board.puts)
    return Execution(ok, error, message, board.cells(), board.puts)
