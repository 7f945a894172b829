"""Renderers, all from the canonical cells form: the paper's text grid and grid explanation for
prompts, and the picture of a target beside a built board (SVG) for transcripts."""
from __future__ import annotations

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

FILL = {"red": "#d62728", "green": "#2ca02c", "blue": "#1f77b4", "yellow": "#f2c318"}
CELL = 44


def _piece_svg(shape: str, color: str, x: float, y: float, size: float, cell: tuple[float, float]) -> str:
    """One piece inset in its cell; a bridge reaches the cell's edges along its axis, so the two
    halves of a bridge join into one bar across the cell border."""
    fill = FILL.get(color, "#888888")
    cx, cy, h = x + size / 2, y + size / 2, size / 2
    if shape == "washer":  # a diamond
        return f'<polygon points="{cx},{y} {x + size},{cy} {cx},{y + size} {x},{cy}" fill="{fill}" stroke="#222"/>'
    if shape == "nut":  # a hexagon
        pts = " ".join(f"{cx + h * dx:.1f},{cy + h * dy:.1f}" for dx, dy in
                       ((-1, 0), (-.5, -.87), (.5, -.87), (1, 0), (.5, .87), (-.5, .87)))
        return f'<polygon points="{pts}" fill="{fill}" stroke="#222"/>'
    if shape == "screw":  # a circle
        return f'<circle cx="{cx}" cy="{cy}" r="{h * .8:.1f}" fill="{fill}" stroke="#222"/>'
    if shape == "bridge-h":  # a bar along the bridge
        return f'<rect x="{cell[0]}" y="{cy - h * .35:.1f}" width="{CELL}" height="{h * .7:.1f}" fill="{fill}" stroke="{fill}"/>'
    if shape == "bridge-v":
        return f'<rect x="{cx - h * .35:.1f}" y="{cell[1]}" width="{h * .7:.1f}" height="{CELL}" fill="{fill}" stroke="{fill}"/>'
    return f'<text x="{cx}" y="{cy}" font-size="9" text-anchor="middle">{escape(shape[:6])}</text>'


def _grid_svg(cells: Cells, rows: int, cols: int, ox: float, title: str, marked: set[str]) -> list[str]:
    out = [f'<text x="{ox + cols * CELL / 2}" y="16" font-family="sans-serif" font-size="13" text-anchor="middle">{escape(title)}</text>']
    for r in range(rows):
        for c in range(cols):
            x, y = ox + c * CELL, 24 + r * CELL
            stroke = ' stroke="#e0007a" stroke-width="3"' if f"{r}:{c}" in marked else ' stroke="#999"'
            out.append(f'<rect x="{x}" y="{y}" width="{CELL}" height="{CELL}" fill="#f7f7f7"{stroke}/>')
            stack = cells.get(f"{r}:{c}", [])
            for level, (shape, color) in enumerate(stack):  # draw bottom to top, shrinking upwards
                inset = 3 + level * 4.5
                out.append(_piece_svg(shape, color, x + inset, y + inset, CELL - 2 * inset, (x, y)))
            if len(stack) > 1:
                out.append(f'<text x="{x + CELL - 3}" y="{y + CELL - 3}" font-size="9" text-anchor="end">{len(stack)}</text>')
    return out


def differing_cells(target: Cells, built: Cells) -> set[str]:
    return {k for k in set(target) | set(built) if target.get(k) != built.get(k)}


def diff_svg(target: Cells, built: Cells, rows: int = DEFAULT_ROWS, cols: int = DEFAULT_COLS) -> str:
    """The target beside the built board, the cells that differ framed in magenta on both."""
    marked = differing_cells(target, built)
    width, height = 2 * cols * CELL + 30, rows * CELL + 26
    body = _grid_svg(target, rows, cols, 1, "target", marked) + _grid_svg(built, rows, cols, cols * CELL + 28, "built", marked)
    return f'<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{height}">' + "".join(body) + "</svg>"
