"""The SVG charts of `sartco report` (report.html, dialogue_rounds.svg): plain SVG text, no script.

line_plot   ES (%) by round, one series per (model, mode): each series its own colour, marker and
            dash (COLOURS x MARKERS x DASHES: identical series stay visible side by side, slightly
            shifted), a legend below the plot that keeps full names and grows with the series.
stacked_bars  one horizontal bar per label, split into the counts of each category.
heat_map    a rows x cols grid of counts, darker = more; row and column numbers counted from 1.
Every text shown is escaped with `esc` (sartco.text.escape, then html.escape).
"""
from __future__ import annotations

import html
import math

from sartco.text import one_line

COLOURS = ("#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b", "#e377c2", "#17becf", "#7f7f7f", "#bcbd22")
MARKERS = ("circle", "square", "triangle", "diamond", "cross")
DASHES = ("", "6 3", "2 3", "8 3 2 3")
LEGEND_LINE = 16


def esc(text) -> str:
    """The one way a text reaches report.html or an SVG: sartco.text's escape, then HTML's."""
    return html.escape(one_line(str(text)))


def style(i: int) -> tuple[str, str, str]:
    """The colour, marker and dash of series i: no two of the first 200 series share all three; neighbours
    differ in all three."""
    return COLOURS[i % len(COLOURS)], MARKERS[(i + i // len(COLOURS)) % len(MARKERS)], \
        DASHES[(i // (len(COLOURS) * len(MARKERS)) + i) % len(DASHES)]


def marker(kind: str, x: float, y: float, colour: str, title: str = "") -> str:
    tip = f"<title>{esc(title)}</title>" if title else ""
    attrs = f'fill="{colour}" class="marker"'
    if kind == "circle":
        return f'<circle cx="{x:.1f}" cy="{y:.1f}" r="4" {attrs}>{tip}</circle>'
    if kind == "square":
        return f'<rect x="{x - 3.5:.1f}" y="{y - 3.5:.1f}" width="7" height="7" {attrs}>{tip}</rect>'
    shape = {"triangle": [(0, -5), (4.5, 3.5), (-4.5, 3.5)], "diamond": [(0, -5), (5, 0), (0, 5), (-5, 0)],
             "cross": [(-2, -5), (2, -5), (2, -2), (5, -2), (5, 2), (2, 2), (2, 5), (-2, 5), (-2, 2), (-5, 2),
                       (-5, -2), (-2, -2)]}[kind]
    points = " ".join(f"{x + dx:.1f},{y + dy:.1f}" for dx, dy in shape)
    return f'<polygon points="{points}" {attrs}>{tip}</polygon>'


def _open(width: float, height: float, kind: str) -> list[str]:
    return [f'<svg xmlns="http://www.w3.org/2000/svg" class="chart {kind}" width="{width:.0f}" height="{height:.0f}" '
            f'viewBox="0 0 {width:.0f} {height:.0f}" font-family="sans-serif" font-size="12">',
            f'<rect width="{width:.0f}" height="{height:.0f}" fill="white"/>']


def line_plot(series: dict[tuple[str, str], list[float]], width: int = 640, plot_height: int = 240) -> str:
    """ES (%) after round k, one series (class "series") per (model, mode), the legend underneath."""
    left, right, top, bottom = 48, 44, 24, 40
    rounds = max((len(v) for v in series.values()), default=1)
    n = len(series)
    step = min(0.05, 0.3 / max(n, 1))  # identical series side by side (a shift of its markers), not on top
    def x(k, i=None):
        shift = 0.0 if i is None else (i - (n - 1) / 2) * step
        return left + 20 + (width - left - right - 40) * ((k + shift) / (rounds - 1) if rounds > 1 else 0.5 + shift)
    def y(v): return top + plot_height * (1 - v / 100.0)
    height = top + plot_height + bottom + LEGEND_LINE * len(series) + 8
    out = _open(width, height, "line-plot")
    for v in range(0, 101, 25):
        out.append(f'<line x1="{left}" y1="{y(v):.1f}" x2="{width - right}" y2="{y(v):.1f}" stroke="#ddd"/>')
        out.append(f'<text x="{left - 6}" y="{y(v) + 4:.1f}" text-anchor="end">{v}</text>')
    base = top + plot_height
    for k in range(rounds):
        out.append(f'<text x="{x(k):.1f}" y="{base + 16}" text-anchor="middle">{k}</text>')
    out.append(f'<text x="{(left + width - right) / 2:.1f}" y="{base + 32}" text-anchor="middle">'
               f'round (corrections sent before the build)</text>')
    out.append(f'<text x="12" y="{top + plot_height / 2:.1f}" text-anchor="middle" '
               f'transform="rotate(-90 12 {top + plot_height / 2:.1f})">ES (%)</text>')
    for i, ((model, mode), values) in enumerate(series.items()):
        colour, kind, dash = style(i)
        dashed = f' stroke-dasharray="{dash}"' if dash else ""
        points = [(x(k, i), y(v), k, v) for k, v in enumerate(values) if not math.isnan(v)]
        out.append(f'<g class="series" data-name="{esc(model)} {esc(mode)}">')
        if len(points) > 1:
            out.append(f'<polyline points="{" ".join(f"{px:.1f},{py:.1f}" for px, py, _, _ in points)}" fill="none" '
                       f'stroke="{colour}" stroke-width="{2 + 4 * (n - 1 - i) / max(n - 1, 1):.1f}"{dashed}/>')  # nested bands
        out += [marker(kind, px, py, colour, f"{model} {mode} round {k}: {v:.1f}") for px, py, k, v in points]
        ly = base + bottom + LEGEND_LINE * i + 8
        out.append(f'<line x1="{left}" y1="{ly:.1f}" x2="{left + 28}" y2="{ly:.1f}" stroke="{colour}" '
                   f'stroke-width="2"{dashed}/>' + marker(kind, left + 14, ly, colour))
        out.append(f'<text class="legend" x="{left + 36}" y="{ly + 4:.1f}">{esc(model)} — {esc(mode)}</text></g>')
    out.append("</svg>")
    return "\n".join(out) + "\n"


def stacked_bars(bars: list[tuple[str, dict[str, int]]], categories: list[str], colours: dict[str, str],
                 plot_w: int = 420) -> str:
    """One horizontal bar (class "bar") per (label, counts), a segment (class "segment") per category
    counted, lengths as shares of the bar's episodes; the legend of the categories on top."""
    label_w, line = min(12 + 7 * max((len(label) for label, _ in bars), default=0), 720), 20
    width = label_w + plot_w + 60
    legend, lx, ly = [], 8, 6
    for c in categories:  # the legend of the categories, wrapped to the chart's width
        if lx + 24 + 7 * len(c) > width and lx > 8:
            lx, ly = 8, ly + 18
        legend.append(f'<rect x="{lx}" y="{ly}" width="10" height="10" fill="{colours[c]}"/>'
                      f'<text x="{lx + 14}" y="{ly + 9}">{esc(c)}</text>')
        lx += 24 + 7 * len(c)
    top = ly + 22
    out = _open(width, top + line * len(bars) + 8, "stacked-bars") + legend
    for i, (label, counts) in enumerate(bars):
        total = sum(counts.values()) or 1
        y0 = top + line * i
        out.append(f'<g class="bar"><text x="{label_w - 6}" y="{y0 + 13}" text-anchor="end">{esc(label)}</text>')
        x0 = float(label_w)
        for c in categories:
            if counts.get(c):
                w = plot_w * counts[c] / total
                out.append(f'<rect class="segment" x="{x0:.1f}" y="{y0 + 2}" width="{w:.1f}" height="{line - 5}" '
                           f'fill="{colours[c]}"><title>{esc(label)}: {esc(c)} {counts[c]} of {total}</title></rect>')
                x0 += w
        out.append(f'<text x="{label_w + plot_w + 4}" y="{y0 + 13}">{total}</text></g>')
    out.append("</svg>")
    return "\n".join(out) + "\n"


def heat_map(counts: dict[tuple[int, int], int], rows: int, cols: int, cell: int = 34) -> str:
    """rows x cols squares (class "heat"), shade by count (the most = darkest), the count inside;
    row and column numbers counted from 1, as the instructions count them."""
    left, top = 28, 22
    most = max(counts.values(), default=0) or 1
    out = _open(left + cols * cell + 8, top + rows * cell + 8, "heat-map")
    for c in range(cols):
        out.append(f'<text x="{left + c * cell + cell / 2:.0f}" y="15" text-anchor="middle">{c + 1}</text>')
    for r in range(rows):
        out.append(f'<text x="{left - 6}" y="{top + r * cell + cell / 2 + 4:.0f}" text-anchor="end">{r + 1}</text>')
        for c in range(cols):
            n = counts.get((r, c), 0)
            shade = 1 - 0.85 * n / most
            fill = f"rgb(255,{int(255 * shade)},{int(255 * shade)})"
            text = "#fff" if n / most > 0.6 else "#000"
            out.append(f'<rect class="heat" data-count="{n}" x="{left + c * cell}" y="{top + r * cell}" width="{cell}" '
                       f'height="{cell}" fill="{fill}" stroke="#ccc"><title>row {r + 1}, column {c + 1}: {n}</title>'
                       f'</rect><text x="{left + c * cell + cell / 2:.0f}" y="{top + r * cell + cell / 2 + 4:.0f}" '
                       f'text-anchor="middle" fill="{text}">{n or ""}</text>')
    out.append("</svg>")
    return "\n".join(out) + "\n"
