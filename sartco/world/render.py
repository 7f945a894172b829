"""Renderers, all from the canonical cells form: the paper's text grid and grid explanation for
prompts, and the picture of a target beside a built board (SVG) for transcripts."""
from __future__ import annotations

from collections.abc import Sequence
from html import escape

from .board import Cells, parse_key
from .components import DEFAULT_COLS, DEFAULT_ROWS

EMPTY = "⬜️"


def grid_text(cells: Cells, rows: int = DEFAULT_ROWS, cols: int = DEFAULT_COLS) -> str:
    """The paper's text form: one list per row, empty cells as "⬜️", a filled cell as the list of
    its (shape, colour) tuples bottom to top."""
    lines = []
    for r in range(rows):
        parts = []
        for c in range(cols):
            stack = cells.get(f"{r}:{c}")
            parts.append(repr(EMPTY) if not stack else "[" + ", ".join(f"('{s}', '{k}')" for s, k in stack) + "]")
        lines.append(" [" + ", ".join(parts) + "]")
    return "[\n" + ",\n".join(lines) + "\n]"


def grid_explanation(cells: Cells) -> str:
    """One sentence per filled cell, 1-based: "Row(8), Col(4) contains red washer, blue nut."."""
    sentences = []
    for key in sorted(cells, key=parse_key):
        r, c = parse_key(key)
        pieces = ", ".join(f"{color} {shape}" for shape, color in cells[key])
        sentences.append(f"Row({r + 1}), Col({c + 1}) contains {pieces}.")
    return "\n".join(sentences)


# --- pictures -------------------------------------------------------------------------------
# Sized to read where a transcript shows them: an <img> squeezed to MIN_WIDTH px keeps every label
# at least MIN_LABEL px high (font size x MIN_WIDTH / the picture's width).

FILL = {"red": "#d62728", "green": "#2ca02c", "blue": "#1f77b4", "yellow": "#f2c318"}
CELL = 40           # a cell's side; a stack's pieces sit in it bottom to top, one slice each
FONT = 33           # every label's font size (numbers, titles, legend)
MIN_WIDTH = 250     # the narrowest a transcript shows a picture: a one-player board event in a 1000 px window
MIN_LABEL = 11      # px
GAP = 24            # between the two grids
MARK = "#e0007a"    # the frame of a cell that differs between target and built board


def _text(x: float, y: float, text: str, anchor: str = "middle") -> str:
    """A label (its font family and the anchor "middle" are the picture's, set once on the <svg>)."""
    where = "" if anchor == "middle" else f' text-anchor="{anchor}"'
    return f'<text x="{x:g}" y="{y:g}" font-size="{FONT}"{where}>{escape(text)}</text>'


def _piece_svg(shape: str, color: str, x: float, y: float, w: float, h: float) -> str:
    """One piece in the box (x, y, w, h): washer a diamond, nut a hexagon, screw a circle, bridge a
    bar (horizontal: across the whole box width, so the halves of a bridge join; vertical: upright)."""
    fill = FILL.get(color, "#888888")
    cx, cy = x + w / 2, y + h / 2
    r = (min(w, h) - 2) / 2
    rx, ry = min(w - 2, 2.2 * h) / 2, (h - 2) / 2  # a flat slice of a stack gets a flattened shape
    if shape == "washer":
        return f'<polygon points="{cx:g},{cy - ry:g} {cx + rx:g},{cy:g} {cx:g},{cy + ry:g} {cx - rx:g},{cy:g}" fill="{fill}" stroke="#222"/>'
    if shape == "nut":
        pts = " ".join(f"{cx + rx * dx:.1f},{cy + ry * dy:.1f}" for dx, dy in
                       ((-1, 0), (-.5, -1), (.5, -1), (1, 0), (.5, 1), (-.5, 1)))
        return f'<polygon points="{pts}" fill="{fill}" stroke="#222"/>'
    if shape == "screw":
        return f'<ellipse cx="{cx:g}" cy="{cy:g}" rx="{rx * .8:.1f}" ry="{ry * .8:.1f}" fill="{fill}" stroke="#222"/>'
    if shape == "bridge-h":
        return f'<rect x="{x - 2:g}" y="{cy - r * .45:.1f}" width="{w + 4:g}" height="{r * .9:.1f}" fill="{fill}" stroke="{fill}"/>'
    if shape == "bridge-v":
        return f'<rect x="{cx - r * .45:.1f}" y="{y:g}" width="{r * .9:.1f}" height="{h:g}" fill="{fill}" stroke="{fill}"/>'
    return f'<rect x="{x + 2:g}" y="{y + 2:g}" width="{w - 4:g}" height="{h - 4:g}" fill="none" stroke="{fill}" stroke-dasharray="3"/>'


def _stack_svg(stack: Sequence[Sequence[str]], x: float, y: float) -> list[str]:
    """A stack in its cell: one horizontal slice per piece, the bottom piece in the bottom slice."""
    slice_h = (CELL - 4) / max(len(stack), 1)
    return [_piece_svg(shape, color, x + 2, y + CELL - 2 - (level + 1) * slice_h, CELL - 4, slice_h)
            for level, (shape, color) in enumerate(stack)]


def _label_width(rows: int) -> float:
    return FONT * .6 * len(str(rows)) + 10


def _grid_svg(cells: Cells, rows: int, cols: int, ox: float, title: str, marked: set[str],
              stacks: dict[tuple[tuple[str, ...], ...], str]) -> list[str]:
    """One grid with its title, column numbers above and row numbers left, 1-based as the
    instructions count them ("the 8th row, 4th column"). Kept small, because a transcript embeds
    every picture and clemcore's HTML and LaTeX transcripts read each character of it: the cells
    are one grey square crossed by one path of lines, and each stack is drawn once (`stacks`:
    its pieces -> the id of its drawing, for the <defs>) and placed in its cells by <use>."""
    gx, gy = ox + _label_width(rows), 2 * FONT + 16
    out = [_text(gx + cols * CELL / 2, FONT, title)]
    out += [_text(gx + c * CELL + CELL / 2, 2 * FONT + 8, str(c + 1)) for c in range(cols)]
    out += [_text(gx - 6, gy + r * CELL + CELL / 2 + FONT * .35, str(r + 1), "end") for r in range(rows)]
    lines = "".join(f"M{gx:g} {gy + r * CELL:g}h{cols * CELL}" for r in range(rows + 1))
    lines += "".join(f"M{gx + c * CELL:g} {gy:g}v{rows * CELL}" for c in range(cols + 1))
    out += [f'<rect x="{gx:g}" y="{gy:g}" width="{cols * CELL}" height="{rows * CELL}" fill="#f7f7f7"/>',
            f'<path d="{lines}" stroke="#999" fill="none"/>']
    frames = []
    for r in range(rows):
        for c in range(cols):
            x, y = gx + c * CELL, gy + r * CELL
            stack = tuple(tuple(piece) for piece in cells.get(f"{r}:{c}", []))
            if stack:
                out.append(f'<use href="#{stacks.setdefault(stack, f"s{len(stacks)}")}" x="{x:g}" y="{y:g}"/>')
            if f"{r}:{c}" in marked:  # drawn last: on top of bridges reaching over the border
                frames.append(f'<rect x="{x + 1.5:g}" y="{y + 1.5:g}" width="{CELL - 3}" height="{CELL - 3}" fill="none" stroke="{MARK}" stroke-width="3"/>')
    return out + frames


def _legend_svg(y: float) -> list[str]:
    """Two lines under the grids: the shapes (grey), then the colours and the frame of a differing cell."""
    out, x, item = [], 0.0, FONT + 4
    for shape, name in (("washer", "washer"), ("nut", "nut"), ("screw", "screw"), ("bridge-h", "bridge")):
        out += [_piece_svg(shape, "grey", x + 2, y - FONT * .85, item - 4, item - 4), _text(x + item + 6, y, name, "start")]
        x += item + FONT * .6 * len(name) + 24
    x, y = 0.0, y + FONT + 12
    for color in FILL:
        out += [f'<rect x="{x + 2:g}" y="{y - FONT * .75:g}" width="{item - 8}" height="{item - 8}" fill="{FILL[color]}"/>',
                _text(x + item, y, color, "start")]
        x += item + FONT * .6 * len(color) + 8
    out += [f'<rect x="{x + 2:g}" y="{y - FONT * .75:g}" width="{item - 8}" height="{item - 8}" fill="none" stroke="{MARK}" stroke-width="3"/>',
            _text(x + item, y, "differs", "start")]
    return out


def differing_cells(target: Cells, built: Cells) -> set[str]:
    return {k for k in set(target) | set(built) if target.get(k) != built.get(k)}


def diff_svg(target: Cells, built: Cells, rows: int = DEFAULT_ROWS, cols: int = DEFAULT_COLS) -> str:
    """The target beside the built board, numbered rows and columns, the cells that differ framed
    in magenta on both, and a legend of shapes and colours underneath."""
    marked = differing_cells(target, built)
    grid_w = _label_width(rows) + cols * CELL
    width, grids_h = 2 * grid_w + GAP + 2, 2 * FONT + 16 + rows * CELL
    height = grids_h + 2 * FONT + 34
    stacks: dict[tuple[tuple[str, ...], ...], str] = {}
    body = (_grid_svg(target, rows, cols, 0, "target", marked, stacks)
            + _grid_svg(built, rows, cols, grid_w + GAP, "built", marked, stacks) + _legend_svg(grids_h + FONT + 8))
    defs = "".join(f'<g id="{ref}">{"".join(_stack_svg(list(stack), 0, 0))}</g>' for stack, ref in stacks.items())
    return (f'<svg xmlns="http://www.w3.org/2000/svg" width="{width:g}" height="{height:g}" viewBox="0 0 {width:g} {height:g}" '
            f'font-family="sans-serif" text-anchor="middle">'
            + (f"<defs>{defs}</defs>" if defs else "") + "".join(body) + "</svg>")

