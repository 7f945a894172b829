"""Structured records -> Python code in the styles of the tasks (no board creation: the game adds it)."""
from __future__ import annotations

import keyword

from ..world.components import DEFAULT_COLS, DEFAULT_ROWS, LETTERS
from .parse import Arrangement, FollowError, Placement

RESERVED = {"board", "put", "init_board", "colors", "x", "y", "row", "col", "shape", "color", "shapes"}


def first_order(steps: list[Placement]) -> str:
    """One put per placement."""
    return "\n".join(f"put(board, {s.shape!r}, {s.color!r}, {s.x}, {s.y})" for s in steps)


def safe_name(name: str | None, steps: list[Placement]) -> str:
    """The object's name as a function name; the shapes' letters when none was given."""
    if not name:
        name = "".join(LETTERS[s.shape] for s in steps) or "build"
    if not name.isidentifier() or keyword.iskeyword(name) or name in RESERVED:
        name = f"obj_{name}" if name.isidentifier() else "build_object"
    return name


def sequence_function(steps: list[Placement], name: str | None) -> str:
    """A function made of first-order puts (hard-coded cells) and its call (paper: single_turn_sc)."""
    fn = safe_name(name, steps)
    body = "\n".join(f"    put(board, {s.shape!r}, {s.color!r}, x={s.x}, y={s.y})" for s in steps)
    usage = (f"{fn}(board, {[s.color for s in steps]!r}, {[s.x for s in steps]!r}, "
             f"{[s.y for s in steps]!r})")
    return f"def {fn}(board, colors, x, y):\n{body}\n{usage}"


def optimal_function(steps: list[Placement], name: str | None) -> str:
    """A function of shapes and offsets from the first piece, called at that piece's cell."""
    fn = safe_name(name, steps)
    x0, y0 = steps[0].x, steps[0].y
    shapes = [s.shape for s in steps]
    dxs = [s.x - x0 for s in steps]
    dys = [s.y - y0 for s in steps]
    colors = tuple(s.color for s in steps)
    return (f"def {fn}(board, colors, x, y):\n"
            f"    shapes = {shapes!r}\n"
            f"    for shape, color, dx, dy in zip(shapes, colors, {dxs!r}, {dys!r}):\n"
            f"        put(board, shape, color, x + dx, y + dy)\n"
            f"{fn}(board, {colors!r}, {x0}, {y0})")


def _sequence(values: tuple[int, ...], limit: int) -> str:
    """[0, 3, 6] with limit 8 -> 'range(0, 8, 3)'; irregular -> a list literal."""
    vs = list(values)
    if len(vs) >= 2:
        step = vs[1] - vs[0]
        if step > 0 and all(b - a == step for a, b in zip(vs, vs[1:])):
            stop = limit if vs[-1] + step >= limit else vs[-1] + 1
            if step == 1:
                return f"range({stop})" if vs[0] == 0 else f"range({vs[0]}, {stop})"
            return f"range({vs[0]}, {stop}, {step})"
    return repr(vs)


def repetition(arr: Arrangement, rows: int = DEFAULT_ROWS, cols: int = DEFAULT_COLS) -> str:
    """Loop code calling the given object function at every anchor."""
    if not arr.name:
        raise FollowError("no object name (expected a given function 'def NAME(board, colors, x, y)' "
                          "or a quoted 'NAME' object)")
    if not arr.positions:
        raise FollowError("the arrangement places no object")
    call = f"{arr.name}(board, colors={list(arr.colors)!r}, x={{x}}, y={{y}})"
    if arr.rows is not None and arr.cols is not None:
        return (f"for row in {_sequence(arr.rows, rows)}:\n"
                f"    for col in {_sequence(arr.cols, cols)}:\n"
                f"        {call.format(x='row', y='col')}")
    if all(r == c for r, c in arr.positions):
        return f"for i in {_sequence(tuple(r for r, _ in arr.positions), min(rows, cols))}:\n" \
               f"    {call.format(x='i', y='i')}"
    return (f"for row, col in {[tuple(pos) for pos in arr.positions]!r}:\n"
            f"    {call.format(x='row', y='col')}")
