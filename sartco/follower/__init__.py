"""The rule-based builder: a genuine instruction follower for template-style instructions.

It reads the instruction text (and, for the repetition task, the given object function, as a
model would) and writes code; it never sees gold code. The grammar is in grammar.py.

    follow(instructions, task, context="", rows=8, cols=8) -> str
    follow_turn(instruction, history=(), rows=8, cols=8) -> str     # multi-turn, one turn's puts

task: "first_order" (put lines), "sequence_function" (a def of hard-coded puts + its call),
"optimal_function" (a def of shapes and offsets + its call), "repetition" (loop code calling
the given object function). The code does not create the board: the caller runs it after
`board = init_board(rows, cols)` (and, for repetition, after the given function).

Failure: FollowError (a ValueError) with a one-line message saying what could not be read;
no other exception leaves these functions for str input.
"""
from __future__ import annotations

from sartco.dataset import TASKS
from sartco.world import DEFAULT_COLS, DEFAULT_ROWS

from . import emit
from .parse import Arrangement, FollowError, Placement, object_name, placements
from .regular import arrange

__all__ = ["follow", "follow_turn", "read_placements", "FollowError", "Placement",
           "Arrangement", "TASKS"]


def _texts(instructions) -> list[str]:
    if isinstance(instructions, str):
        instructions = [instructions]
    if not isinstance(instructions, (list, tuple)) or not all(isinstance(t, str) for t in instructions):
        raise FollowError("instructions must be a list of strings")
    return list(instructions)


def read_placements(instructions, rows: int = DEFAULT_ROWS, cols: int = DEFAULT_COLS) -> list[Placement]:
    """All placements of the turns so far, in order ('on top of it' refers across turns)."""
    steps: list[Placement] = []
    for text in _texts(instructions):
        steps.extend(placements(text, rows, cols, previous=steps[-1] if steps else None))
    return steps


def follow(instructions, task: str, context: str = "", rows: int = DEFAULT_ROWS, cols: int = DEFAULT_COLS) -> str:
    """The code for `task` that the instructions describe; FollowError if they cannot be read."""
    texts = _texts(instructions)
    if task not in TASKS:
        raise FollowError(f"unknown task {task!r}; expected one of {', '.join(TASKS)}")
    try:
        if task == "repetition":
            return emit.repetition(arrange(" ".join(texts), context or "", rows, cols), rows, cols)
        steps = read_placements(texts, rows, cols)
        if not steps:
            raise FollowError(f"no placement found in {' '.join(texts).strip()!r:.160}")
        if task == "first_order":
            return emit.first_order(steps)
        name = next((n for n in map(object_name, texts) if n), None)
        if task == "sequence_function":
            return emit.sequence_function(steps, name)
        return emit.optimal_function(steps, name)
    except FollowError:
        raise
    except Exception as exc:  # a grammar bug must still fail in the documented way
        raise FollowError(f"follower failed on {' '.join(texts).strip()!r:.120}: "
                          f"{type(exc).__name__}: {exc}") from exc


def follow_turn(instruction: str, history=(), rows: int = DEFAULT_ROWS, cols: int = DEFAULT_COLS) -> str:
    """The put lines for one multi-turn instruction; `history` holds the earlier turns' texts."""
    try:
        before = read_placements(list(history), rows, cols) if history else []
        steps = placements(instruction, rows, cols, previous=before[-1] if before else None) \
            if isinstance(instruction, str) else None
    except FollowError:
        raise
    except Exception as exc:
        raise FollowError(f"follower failed on {instruction!r:.120}: {type(exc).__name__}: {exc}") from exc
    if steps is None:
        raise FollowError("instruction must be a string")
    if not steps:
        raise FollowError(f"no placement found in {instruction.strip()!r:.160}")
    return emit.first_order(steps)

