"""The assembly rules: one check, in the order of the authors' simulator, then one placement.

Where the authors' simulator was wrong we are right (see ../shared/sartco-data/README.md):
- a negative coordinate is dimensions_mismatch (theirs wrapped around to the last row);
- an unknown colour is key_error (theirs stored any string by its first letter);
- nothing goes on a screw, a bridge included (theirs let a bridge onto a screw);
- a failed put leaves the board unchanged (theirs left a failed bridge's first half).

Bridges: `bridge-h` at (x, y) also covers (x, y+1), `bridge-v` also covers (x+1, y). As in the
authors' simulator, the same-shape rules apply only when a washer, nut or screw is placed: a
bridge may lie directly on a bridge of the same orientation (the published data needs it), and
a washer, nut or screw is checked against the two pieces below it in its cell, bridges
included. A bridge whose second cell is full is a value_error, checked before the depths.
"""
from __future__ import annotations

from .board import Board
from .components import BRIDGES, COLORS, MAX_DEPTH, NOTHING_ON_TOP, SHAPES
from .error_codes import ErrorCode, WorldError

E = ErrorCode


def _fail(code: ErrorCode, message: str):
    raise WorldError(code, message)


def _shown(value) -> str:
    """A value in a message: its repr if it is one of Python's own types, else its type's name
    (a program's object would show its address, and its own code, in the verdict)."""
    return f"{value!r:.40}" if type(value).__module__ == "builtins" else f"<{type(value).__name__} object>"


def _bad_coordinates(x, y):
    for name, value in (("x", x), ("y", y)):
        if type(value) is not int:
            _fail(E.TYPE_ERROR, f"{name} must be an integer, got {type(value).__name__} {_shown(value)}")


def check(board: Board, shape, color, x, y) -> int | None:
    """Raise the first rule a placement violates; return the index in board.stacks of a
    bridge's second cell (None for a piece that covers only (x, y)). Written for speed: it runs
    for every put of every program."""
    if type(x) is not int or type(y) is not int:
        _bad_coordinates(x, y)
    if not (0 <= x < board.rows and 0 <= y < board.cols):
        _fail(E.DIMENSIONS_MISMATCH, f"({x}, {y}) is outside the {board.rows}x{board.cols} board")
    stacks, cols = board.stacks, board.cols
    anchor = stacks[x * cols + y]
    height = len(anchor)
    if height >= MAX_DEPTH:
        _fail(E.VALUE_ERROR, f"cell ({x}, {y}) is full ({MAX_DEPTH} pieces)")
    offset = BRIDGES.get(shape) if isinstance(shape, str) else None
    second = None
    if offset is not None:
        x2, y2 = x + offset[0], y + offset[1]
        if not (x2 < board.rows and y2 < board.cols):
            _fail(E.VALUE_ERROR, f"{shape} at ({x}, {y}) needs cell ({x2}, {y2}), which is off the board")
        if height >= 2:
            _fail(E.BRIDGE_PLACEMENT, f"{shape} at ({x}, {y}) would sit at level {height + 1}; bridges go on level 1 or 2")
        second = x2 * cols + y2
        height2 = len(stacks[second])
        if height2 != height:  # (height < 2 here: a full second cell is always another height)
            if height2 >= MAX_DEPTH:
                _fail(E.VALUE_ERROR, f"{shape} at ({x}, {y}) needs cell ({x2}, {y2}), which is full ({MAX_DEPTH} pieces)")
            _fail(E.DEPTH_MISMATCH, f"{shape} at ({x}, {y}) spans cells of heights {height} and {height2}")
    if height:
        top = anchor[-1][0]
        if top in NOTHING_ON_TOP:
            _fail(E.NOT_ON_TOP_OF_SCREW, f"cell ({x}, {y}) has a {top} on top; nothing goes on a screw")
        if second is not None:  # a bridge: its second cell too; bridges are exempt from the same-shape rules
            if stacks[second][-1][0] in NOTHING_ON_TOP:
                _fail(E.NOT_ON_TOP_OF_SCREW, f"cell ({x2}, {y2}) has a {stacks[second][-1][0]} on top; nothing goes on a screw")
        elif top == shape:
            _fail(E.SAME_SHAPE_STACKING, f"{top} directly on a {top} at ({x}, {y})")  # top: the board's str
        elif height >= 2 and anchor[-2][0] == shape:
            below = anchor[-2][0]
            _fail(E.SAME_SHAPE_AT_ALTERNATE_LEVELS, f"{below} two levels above a {below} at ({x}, {y})")
    if type(shape) is not str or shape not in SHAPES:  # exact str: a program's object may claim equality
        _fail(E.KEY_ERROR, f"unknown shape {_shown(shape)}; expected one of {', '.join(SHAPES)}")
    if type(color) is not str or color not in COLORS:
        _fail(E.KEY_ERROR, f"unknown colour {_shown(color)}; expected one of {', '.join(COLORS)}")
    return second


def put(board: Board, shape, color, x, y) -> Board:
    """Place one piece, or raise WorldError and leave the board unchanged."""
    if not isinstance(board, Board):
        _fail(E.TYPE_ERROR, f"put: the first argument must be a board, got {type(board).__name__}")
    second = check(board, shape, color, x, y)
    piece = (shape, color)
    stacks = board.stacks
    stacks[x * board.cols + y].append(piece)
    if second is not None:
        stacks[second].append(piece)
    board.puts += 1
    return board
