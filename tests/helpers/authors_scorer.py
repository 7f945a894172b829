"""A small model of the authors' scorer, written from ../shared/sartco-data/paper-protocol/README.md
("How the authors ran a program"): plain `exec(code)` with no namespace arguments inside a
function of this module, `_execute_instructions(instruction, board)`, and that function's
`board` is the one scored. The module imports what the README says theirs did (numpy as `np`,
`re`, `json`, `Counter`, `deepcopy`) and defines `init_board` and `put` at its top level. No
sandbox: tests (tests/paper/test_authors_exec.py) run trusted programs here and require the
sandbox's PAPER semantics to give the same verdict and board.

    reference(program) -> (ok, error code or None, cells)
"""
import json  # noqa: F401 - the authors' namespace, read by the programs
import re  # noqa: F401
from types import FunctionType
from collections import Counter  # noqa: F401
from copy import deepcopy  # noqa: F401

import numpy as np  # noqa: F401

from sartco.world import Board, ErrorCode, WorldError
from sartco.world import put  # noqa: F401

_CODES = {NameError: ErrorCode.NAME_ERROR, TypeError: ErrorCode.TYPE_ERROR, ValueError: ErrorCode.VALUE_ERROR,
          KeyError: ErrorCode.KEY_ERROR, IndexError: ErrorCode.INDEX_ERROR, ZeroDivisionError: ErrorCode.ZERO_DIVISION}


def init_board(rows=8, cols=8):
    return Board(rows, cols)


def _execute_instructions(instruction, board):
    exec(instruction)
    return board


def reference(program: str) -> tuple:
    """What the authors' scorer made of `program` on a fresh 8x8 board. Each program gets a fresh
    copy of the module's globals (a `global` statement of one program must not reach the next;
    in the authors' process it did, which no single verdict of the README depends on)."""
    board = init_board(8, 8)
    scorer = FunctionType(_execute_instructions.__code__, dict(_MODULE))
    try:
        scored = scorer(program, board)
    except WorldError as exc:
        return False, exc.code, board.cells()
    except Exception as exc:  # the program's own error, as the sandbox names it
        code = next((c for kind, c in _CODES.items() if isinstance(exc, kind)), ErrorCode.RUNTIME_ERROR)
        return False, code, board.cells()
    return True, None, scored.cells()


_MODULE = dict(globals())  # the scorer module's globals, as the programs found them
