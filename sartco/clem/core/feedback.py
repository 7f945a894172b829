"""The one message a builder gets after a failed attempt in a feedback (repair) experiment.

Built from the execution facts only - what running the builder's program showed, as a cobot on
the shop floor would report it: the error code and its message, or that the board differs from
the target, and the board that was built, in the text form of the prompts
(sartco.world.render.grid_text). Never the target, and nothing derived from it: no mismatch
category (mismatch_color would tell that shapes and places are right), no count of differing
cells, no cell precision/recall/F1.

`feedback_for(record, ...)` takes a BuildRecord but hands `feedback_message` only the fields
that come from the execution (error, message, cells, rows, cols), so the target cannot reach
the text by accident.
"""
from __future__ import annotations

import re

from sartco import settings
from sartco.world import DEFAULT_COLS, DEFAULT_ROWS, ErrorCode
from sartco.world.render import grid_text

ATTEMPTS_FIELD = "attempts"  # experiment field: attempts per episode, the first included (default settings.ATTEMPTS)


def max_attempts(experiment: dict) -> int:
    """How many attempts an episode of this experiment allows (1 = the paper's protocol). The
    one rule for the game master and the scorer (the report reads the scorer's Max Attempts)."""
    value = experiment.get(ATTEMPTS_FIELD)
    if value is None:
        return settings.ATTEMPTS
    if isinstance(value, bool) or not isinstance(value, int) or value < 1:
        raise ValueError(f"experiment {experiment.get('name')!r}: field {ATTEMPTS_FIELD!r} must be an integer >= 1, "
                         f"not {value!r}")
    return value


BOARD_FORM = ("one list per row from the top; an empty cell is ⬜️, a filled cell lists its components "
              "from the bottom up as (shape, color)")


def feedback_message(*, error: str | None, message: str, cells: dict, rows: int = DEFAULT_ROWS, cols: int = DEFAULT_COLS,
                     attempts_left: int | None = None) -> str:
    """What the game master tells the builder about its last attempt.

    error: the ErrorCode value when the program did not run to the end (or parse_error when the
    answer held no code), None when it ran and built a board other than the target."""
    if error == ErrorCode.PARSE_ERROR:
        head = f"No code was found in your answer (parse_error: {message or 'no code found'})."
        board = ""
    else:
        if error is None:
            head = "Your code ran, but the board you built differs from the target board."
        else:
            head = f"Your code failed with {error}" + (f": {message}" if message else ".")
            if not head.endswith("."):
                head += "."
        board = f"\n\nThe board you built ({BOARD_FORM}):\n{grid_text(cells, rows, cols)}"
    left = ""
    if attempts_left is not None:
        left = f" You have {attempts_left} attempt{'s' if attempts_left != 1 else ''} left."
    return (f"{head}{board}\n\nWrite the complete corrected code, in the same answer format as before; "
            f"it runs on a fresh, empty board.{left}")


def feedback_for(record, *, attempts_left: int | None = None) -> str:
    """feedback_message from a BuildRecord's execution facts (never its target or comparison);
    line numbers in the message are counted in the builder's own code."""
    message = builder_lines(record.message, record.program, record.builder_code)
    return feedback_message(error=record.error, message=message, cells=record.cells,
                            rows=record.rows, cols=record.cols, attempts_left=attempts_left)


_LINE = re.compile(r"\bline (\d+)\b")


def builder_lines(message: str, program: str, builder_code: str) -> str:
    """sartco.program numbers lines in the executed program (given code, `board = init_board(...)`,
    then the builder's code, sartco.clem.core.building.compose_program); say "line k" of the builder's
    code instead, or "line k of the given code"."""
    code = builder_code.strip()
    program = program.rstrip()
    if not message or not code or not program.endswith(code):
        return message
    offset = program[:-len(code)].count("\n")  # lines before the builder's first line
    given = max(0, offset - 1)                              # the given code's lines (then init_board)

    def renumber(m: re.Match) -> str:
        n = int(m.group(1))
        if n > offset:
            return f"line {n - offset}"
        if n <= given:
            return f"line {n} of the given code"
        return "the board set-up line"
    return _LINE.sub(renumber, message)
