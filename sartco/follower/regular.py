"""Regular boards: an arrangement instruction (+ the given object function) -> the anchors of the object."""
from __future__ import annotations

import re

from ..world import COLORS, DEFAULT_COLS, DEFAULT_ROWS, parse_key
from ..world.board import MAX_SIDE
from . import parse
from .parse import Arrangement, FollowError

Footprint = frozenset[tuple[int, int]]  # the cells an object occupies, as (row, col) offsets from its anchor


def function_name(context: str) -> str | None:
    m = re.search(r"^\s*def\s+([A-Za-z_]\w*)\s*\(", context or "", re.MULTILINE)
    return m.group(1) if m else None


def footprint(context: str, name: str | None, n_colors: int, rows: int = DEFAULT_ROWS,
              cols: int = DEFAULT_COLS) -> Footprint | None:
    """The cells the given object function covers, relative to its anchor.

    The follower reads the object function the way a model would try it out: it runs the function
    once through sartco.program (the only place where code from outside runs) on a scratch board
    with room on every side, anchored in its middle, and reads the covered cells from the built
    board. Any failure just means "unknown" (None).
    """
    if not context or not name:
        return None
    from sartco.program import execute  # deferred: the grammar works without a worker process

    pad = max(rows, cols)  # an object may reach up to a board's size away from its anchor
    size = min(2 * pad + max(rows, cols), MAX_SIDE)
    colors = [COLORS[i % len(COLORS)] for i in range(max(n_colors, 1))]
    program = (f"{context.strip()}\nboard = init_board({size}, {size})\n"
               f"{name}(board, {colors!r}, {pad}, {pad})\n")
    ex = execute(program, rows=size, cols=size)
    if not ex.ok or not ex.cells:
        return None
    return frozenset((x - pad, y - pad) for x, y in map(parse_key, ex.cells))


def _span(cells: Footprint) -> tuple[int, int]:
    xs = [x for x, _ in cells]
    ys = [y for _, y in cells]
    return max(xs) - min(xs) + 1, max(ys) - min(ys) + 1


def arrange(text: str, context: str = "", rows: int = DEFAULT_ROWS, cols: int = DEFAULT_COLS) -> Arrangement:
    """Read a regular-board instruction; decide where the object's anchors go."""
    kind, m = parse.arrangement_kind(text)
    colors = parse.colors_of(text)
    given = function_name(context)
    name = given or parse.regular_name(text)
    cells = footprint(context, given, len(colors), rows, cols)
    size = parse.size_of(text) or (_span(cells) if cells else (1, 1))
    h, w = size
    if cells is None:
        cells = frozenset((dx, dy) for dx in range(h) for dy in range(w))
    R, C = rows - h + 1, cols - w + 1  # anchors must leave room for the whole object

    def grid(rs, cs) -> Arrangement:
        rs, cs = tuple(rs), tuple(cs)
        if not rs or not cs:
            raise FollowError(f"a {h}x{w} object does not fit the {rows}x{cols} board this way")
        return Arrangement(name, colors, tuple((r, c) for r in rs for c in cs), rs, cs)

    if kind == "corners":
        corners = []
        for pos in ((0, 0), (0, C - 1), (R - 1, 0), (R - 1, C - 1)):
            if pos not in corners:
                corners.append(pos)
        return Arrangement(name, colors, tuple(corners))
    if kind == "diagonal":
        taken: set[tuple[int, int]] = set()
        anchors = []
        for i in range(min(R, C)):  # each next diagonal cell where the object does not overlap
            mine = {(i + dx, i + dy) for dx, dy in cells}
            if mine & taken:
                continue
            taken |= mine
            anchors.append((i, i))
        return Arrangement(name, colors, tuple(anchors))
    if kind == "alternate_grid":  # one empty row / column between objects
        return grid(range(0, R, h + 1), range(0, C, w + 1))
    if kind == "fill_column":  # packed down the column; "every alternate column" skips one
        first = parse._index(parse.ordinal(m.group("first")), cols, "column")
        return grid(range(0, R, h), range(first, C, w + 1) if m.group("repeat") else [first])
    if kind == "fill_row":
        first = parse._index(parse.ordinal(m.group("first")), rows, "row")
        return grid(range(first, R, h + 1) if m.group("repeat") else [first], range(0, C, w))
    if kind == "list_of_line":
        return _list_of_line(m, name, colors, rows, cols, h, w, grid)
    raise AssertionError(kind)


def _axis(word: str | None) -> str | None:
    return None if word is None else ("row" if word.lower().startswith("row") else "col")


def _list_of_line(m, name, colors, rows, cols, h, w, grid) -> Arrangement:
    """'in the first, fourth, and seventh columns of the first row. Then, repeat ... in the
    remaining rows' (or '... in the fifth row')."""
    axis, line_axis = _axis(m.group("axis")), _axis(m.group("line_axis"))
    if axis == line_axis:
        raise FollowError(f"'{m.group(0)[:80]}': the list and the line are both {axis}s")
    size = {"row": rows, "col": cols}
    listed = [parse._index(v, size[axis], axis) for v in parse.ordinal_list(m.group("list"))]
    line = parse._index(parse.ordinal(m.group("line")), size[line_axis], line_axis)
    extent = {"row": h, "col": w}[line_axis]
    if m.group("remaining"):
        if _axis(m.group("rem_axis")) != line_axis:
            raise FollowError(f"'{m.group(0)[:80]}': repeated along {m.group('rem_axis')}")
        lines = sorted(set(range(line % extent, size[line_axis] - extent + 1, extent)) | {line})
    elif m.group("more"):
        lines = [line] + [parse._index(v, size[line_axis], line_axis) for v in parse.ordinal_list(m.group("more"))]
    elif re.search(r"\brepeat", m.string[m.start():], re.IGNORECASE):
        raise FollowError(f"could not read where to repeat the pattern in {m.string[m.start():].strip()!r:.160}")
    else:
        lines = [line]
    return grid(lines, listed) if line_axis == "row" else grid(listed, lines)
