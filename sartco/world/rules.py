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

from typing import NoReturn

from .board import Board
from .components import BRIDGES, COLORS, MAX_DEPTH, NOTHING_ON_TOP, SHAPES
from .error_codes import ErrorCode, WorldError



def _fail(code: ErrorCode, message: str) -> NoReturn:
    raise WorldError(code, message)


def _shown(value: object) -> str:
    """A value in a message: its repr if it is one of Python's own types, else its type's name
    (a program's object would show its address, and its own code, in the verdict)."""
    return f"{value!r:.40}" if type(value).__module__ == "builtins" else f"<{type(value).__name__} object>"


def _bad_coordinates(x: object, y: object) -> None:
    for name, value in (("x", x), ("y", y)):
        if type(value) is not int:
            _fail(ErrorCode.TYPE_ERROR, f"{name} must be an integer, got {type(value).__name__} {_shown(value)}")


def check(board: Board, shape: object, color: object, x: int, y: int) -> int | None:
    """Raise the first rule a placement violates; return the index in board.stacks of a
    bridge's second cell (None for a piece that covers only (x, y)). Written for speed: it runs
    for every put of every program."""
    if type(x) is not int or type(y) is not int:
        _bad_coordinates(x, y)
    if not (0 <= x < board.rows and 0 <= y < board.cols):
        _fail(ErrorCode.DIMENSIONS_MISMATCH, f"({x}, {y}) is outside the {board.rows}x{board.cols} board")
    stacks, cols = board.stacks, board.cols
    anchor = stacks[x * cols + y]
    height = len(anchor)
    if height >= MAX_DEPTH:
        _fail(ErrorCode.VALUE_ERROR, f"cell ({x}, {y}) is full ({MAX_DEPTH} pieces)")
    # compared by value on exact built-in types only: a str subclass may answer any == (and run)
    name = shape if type(shape) is str else None
    offset = None if name is None else BRIDGES.get(name)
    second = None
    if offset is not None:
        x2, y2 = x + offset[0], y + offset[1]
        if not (x2 < board.rows and y2 < board.cols):
            _fail(ErrorCode.VALUE_ERROR, f"{shape} at ({x}, {y}) needs cell ({x2}, {y2}), which is off the board")
        if height >= 2:
            _fail(ErrorCode.BRIDGE_PLACEMENT, f"{shape} at ({x}, {y}) would sit at level {height + 1}; bridges go on level 1 or 2")
        second = x2 * cols + y2
        height2 = len(stacks[second])
        if height2 != height:  # (height < 2 here: a full second cell is always another height)
            if height2 >= MAX_DEPTH:
                _fail(ErrorCode.VALUE_ERROR, f"{shape} at ({x}, {y}) needs cell ({x2}, {y2}), which is full ({MAX_DEPTH} pieces)")
            _fail(ErrorCode.DEPTH_MISMATCH, f"{shape} at ({x}, {y}) spans cells of heights {height} and {height2}")
    if height:
        top = anchor[-1][0]
        if top in NOTHING_ON_TOP:
            _fail(ErrorCode.NOT_ON_TOP_OF_SCREW, f"cell ({x}, {y}) has a {top} on top; nothing goes on a screw")
        if second is not None:  # a bridge: its second cell too; bridges are exempt from the same-shape rules
            if stacks[second][-1][0] in NOTHING_ON_TOP:
                _fail(ErrorCode.NOT_ON_TOP_OF_SCREW, f"cell ({x2}, {y2}) has a {stacks[second][-1][0]} on top; nothing goes on a screw")
        elif top == name:
            _fail(ErrorCode.SAME_SHAPE_STACKING, f"{shape} directly on a {shape} at ({x}, {y})")
        elif height >= 2 and anchor[-2][0] == name:
            _fail(ErrorCode.SAME_SHAPE_AT_ALTERNATE_LEVELS, f"{shape} two levels above a {shape} at ({x}, {y})")
    if name not in SHAPES:
        if name is None:
            _fail(ErrorCode.KEY_ERROR, f"a shape is one of {', '.join(SHAPES)}, not a {type(shape).__name__}")
        _fail(ErrorCode.KEY_ERROR, f"unknown shape {shape!r:.40}; expected one of {', '.join(SHAPES)}")
    if type(color) is not str:  # (see name above)
        _fail(ErrorCode.KEY_ERROR, f"a colour is one of {', '.join(COLORS)}, not a {type(color).__name__}")
    if color not in COLORS:
        _fail(ErrorCode.KEY_ERROR, f"unknown colour {color!r:.40}; expected one of {', '.join(COLORS)}")
    return second


def put(board: Board, shape: str, color: str, x: int, y: int) -> Board:
    """Place one piece, or raise WorldError and leave the board unchanged."""
    if not isinstance(board, Board):
        _fail(ErrorCode.TYPE_ERROR, f"put: the first argument must be a board, got {type(board).__name__}")
    _place(board, (shape, color), x, y, check(board, shape, color, x, y))
    return board


def _place(board: Board, piece: tuple[str, str], x: int, y: int, second: int | None) -> None:
    stacks = board.stacks
    stacks[x * board.cols + y].append(piece)
    if second is not None:
        stacks[second].append(piece)
    board.puts += 1
    board.log.append((piece, x, y))


def replay(board: Board) -> Board:
    """A fresh board of the same size built from `board`'s log alone, every put checked again
    (WorldError when one is not a legal put). Its stacks hold the very piece objects of the
    log, as `board`'s do when only put changed it."""
    fresh = Board(board.rows, board.cols)
    for piece, x, y in board.log:
        if type(piece) is not tuple:
            _fail(ErrorCode.FORBIDDEN, f"a logged piece is a {type(piece).__name__}, not a tuple")
        shape, color = piece
        _place(fresh, piece, x, y, check(fresh, shape, color, x, y))
    return fresh
