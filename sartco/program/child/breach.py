"""The assume-breach tests' run (template.py's mode "breach"): a source exec'd with Python's real
builtins and none of the sandbox's checks, as if every one had fallen, inside the same walls as
every program (tests/program/test_walls.py). Only a template started with `--breach` runs it."""
from __future__ import annotations

import builtins

from sartco.world import DEFAULT_COLS, DEFAULT_ROWS, Board, put

from ..execution import clean
from .result import checked
from .runtime import classify, describe, encode


def breached(source: str, rows: int, cols: int) -> bytes:
    """The assume-breach tests' run (template.py mode "breach"): `source` exec'd with Python's real
    builtins and none of the sandbox's checks, as if every one had fallen; the answer as answer()
    makes it from the global `board` or the last board made. Only the kernel's walls hold."""
    last = [Board(rows, cols)]

    def init_board(rows: int = DEFAULT_ROWS, cols: int = DEFAULT_COLS) -> Board:
        last[0] = Board(rows, cols)
        return last[0]

    env = {"__builtins__": builtins, "__name__": "__main__", "board": last[0], "put": put, "init_board": init_board}
    ok, error, message = True, None, ""
    try:
        exec(compile(source, "<program>", "exec"), env)
    except BaseException as exc:
        ok, error, message = False, classify(exc), clean(describe(exc))
    result = env.get("board")
    fresh, _ = checked(result if type(result) is Board else last[0])
    return encode(ok, error, message, fresh)
