"""report.html of `sartco report`: one self-contained page (inline SVG and CSS, no script, no network).

Per game: the Table 3 cells x models with `x [lo, hi]` intervals (EM / CB / ES / FG), a stacked bar of the
error categories per model and experiment, the ES-by-round plot of the dialogue modes, a heat map of
the grid cells that differ between the built and the target board in the failed episodes (the
build record `sartco_build` of interactions.json: its `cells` and `target`), and one example
transcript per (model, experiment, error category). Then the generation settings and provenance of
every run.json, and on top a warning for incomplete experiments and harness errors.
Transcript links are relative to the report's folder and assume the results folder stays where it
was, relative to the report, when the report was written (the page names that place).
"""
from __future__ import annotations

import json
import os
import urllib.parse
from collections import Counter, defaultdict
from pathlib import Path

from sartco.episode import BUILD_KEY

from . import charts, dialogue_table
from .charts import esc
from .rows import TASK_NAMES
from .completeness import INCOMPLETE_MARK, RUN_HEADER, Completeness, run_row

NAME = "report.html"
CATEGORY_COLOURS = ("#d62728", "#ff7f0e", "#9467bd", "#8c564b", "#e377c2", "#bcbd22", "#17becf", "#1f77b4",
                    "#7f7f7f", "#aec7e8", "#ffbb78", "#c5b0d5", "#c49c94", "#f7b6d2", "#dbdb8d", "#9edae5")
STYLE = """body{font-family:sans-serif;margin:24px;max-width:1200px;color:#222}
table{border-collapse:collapse;margin:8px 0 16px}td,th{border:1px solid #ccc;padding:3px 6px;font-size:13px;
vertical-align:top}th{background:#f3f3f3}.warning{background:#fff3cd;border:2px solid #d39e00;padding:8px 12px;
margin:12px 0}.warning h2{margin:0 0 6px;font-size:18px}.notrun{color:#999}.incomplete{background:#fff3cd}
code,pre{font-family:monospace}pre{white-space:pre-wrap;overflow-wrap:anywhere}.rounds{white-space:nowrap}"""


def category_colours(categories: list[str]) -> dict[str, str]:
    colours = {"success": "#2ca02c"}
    for c in categories:
        colours.setdefault(c, CATEGORY_COLOURS[(len(colours) - 1) % len(CATEGORY_COLOURS)])
    return colours


def episode_dir(results: Path, e: dict) -> Path:
    return results / e["model"] / e["game"] / e["experiment"] / e["episode"]


def failed_cells(results: Path, episodes: list[dict]) -> tuple[Counter, int, int, int]:
    """(row, col) -> failed episodes whose built board differs from the target there; rows; cols;
    the failed episodes counted (those with a build record)."""
    counts: Counter = Counter()
    rows = cols = 8
    counted = 0
    for e in episodes:
        if e["es"] or e["aborted"]:
            continue
        try:
            record = json.loads((episode_dir(results, e) / "interactions.json").read_text(encoding="utf-8")).get(BUILD_KEY)
        except (OSError, ValueError):
            continue
        if not isinstance(record, dict) or not isinstance(record.get("target"), dict):
            continue
        built, target = record.get("cells") or {}, record["target"]
        rows, cols = int(record.get("rows", rows)), int(record.get("cols", cols))
        counted += 1
        for key in set(built) | set(target):
            if built.get(key) != target.get(key):
                r, _, c = key.partition(":")
                if r.isdigit() and c.isdigit():
                    counts[(int(r), int(c))] += 1
    return counts, rows, cols, counted


def cells_table(rows: list[dict]) -> str:
    """Table 3 cells (board, object, task, source) x models: EM / CB / ES (and FG, function
    generalisation, in probed cells) `x [lo, hi]`; "not run" when unplayed."""
    keys = ["board_type", "object_type", "task", "source"]
    models = sorted({r["model"] for r in rows})
    cells: dict[tuple, dict] = {}
    for r in rows:
        cells.setdefault(tuple(r[k] for k in keys), {})[r["model"]] = r
    out = ["<table class='cells'><tr>" + "".join(f"<th>{esc(k.replace('_', ' '))}</th>" for k in keys)
           + "".join(f"<th>{esc(m)}</th>" for m in models) + "</tr>"]
    for key, by_model in cells.items():
        line = "".join(f"<td>{esc(TASK_NAMES.get(v, v) if k == 'task' else v)}</td>" for k, v in zip(keys, key))
        for m in models:
            r = by_model.get(m)
            if r is None:
                line += "<td class='notrun'>not run</td>"
                continue
            short = r["episodes_scored"] < r["episodes_expected"]
            mark = INCOMPLETE_MARK if short else ""
            line += (f"<td{' class=incomplete' if short else ''}>" + "<br>".join(
                f"{name} {r[x]:.1f} [{r[x + '_lo']:.1f}, {r[x + '_hi']:.1f}]{mark}"
                for name, x in (("EM", "em"), ("CB", "cb"), ("ES", "es"), ("FG", "fg")) if r[x] == r[x])
                + f"<br><small>n = {r['episodes']}</small></td>")
        out.append(f"<tr>{line}</tr>")
    return "\n".join(out) + "</table>\n"


def examples(results: Path, out: Path, episodes: list[dict]) -> str:
    """One transcript link per (model, experiment, error category): the first such episode's."""
    first: dict[tuple, dict] = {}
    for e in sorted(episodes, key=lambda e: (e["model"], e["experiment"], e["category"], e["episode"])):
        first.setdefault((e["model"], e["experiment"], e["category"]), e)
    items = []
    for (model, experiment, category), e in first.items():
        target = episode_dir(results, e) / "transcript.html"
        if not target.is_file():
            continue
        href = urllib.parse.quote(Path(os.path.relpath(target, out)).as_posix())
        items.append(f"<li>{esc(model)} / {esc(experiment)} / {esc(category)}: "
                     f"<a class='transcript' href='{esc(href)}'>{esc(e['episode'])}</a></li>")
    return "<ul class='examples'>\n" + "\n".join(items) + "\n</ul>\n" if items else "<p>No transcripts found.</p>\n"


def warnings(found: Completeness, harness_rows: list[dict]) -> str:
    incomplete = [k for k in sorted(found.expected) if found.scored(k) < found.expected[k]]
    faults = [r for r in harness_rows if r["harness_errors"]]
    if not (incomplete or faults or found.unverifiable):
        return ""
    items = [f"<li>incomplete ({INCOMPLETE_MARK}): {esc(' / '.join(k))}: {found.scored(k)} of {found.expected[k]} "
             f"episodes scored</li>" for k in incomplete]
    items += [f"<li>harness errors (the harness failed, not the model; left out of the scores): {esc(r['model'])} / "
              f"{esc(r['game'])}: {r['harness_errors']} of {r['episodes']} episodes"
              + (f"; first: {esc(r['first_reason'])}" if r["first_reason"] else "") + "</li>"
              for r in faults]
    items += [f"<li>not checked: {esc(note)}</li>" for note in found.unverifiable]
    return ("<div class='warning' id='warning'><h2>Warning: these results are incomplete or hold harness errors</h2>"
            "<ul>" + "\n".join(items) + "</ul>See completeness.md and harness.md.</div>\n")


def provenance(found: Completeness) -> str:
    if not found.runs:
        return "<p>No run.json found: generation settings and provenance unknown.</p>\n"
    out = ["<table class='provenance'><tr>" + "".join(f"<th>{h}</th>" for h in RUN_HEADER) + "</tr>"]
    for (model, game), run in sorted(found.runs.items()):
        out.append("<tr>" + "".join(f"<td>{esc('' if v is None else v)}</td>" for v in run_row(model, game, run)) + "</tr>")
    return "\n".join(out) + "</table>\n"


def game_section(game: str, results: Path, out: Path, episodes: list[dict], table_rows: list[dict],
                 error_rows: list[dict], colours: dict[str, str], tables: list[str]) -> str:
    own = [e for e in episodes if e["game"] == game]
    parts = [f"<h2 id='{esc(game)}'>{esc(game)}</h2>"]
    if table_rows:
        parts.append("<h3>Cells x models: EM / CB / ES / FG (function generalisation) (%) with 95 % bootstrap "
                     "intervals (SARTCo protocol)</h3>" + cells_table(table_rows))
    parts += tables  # sartco.report.html_tables: paper protocol, dialogue modes, ablations, repair
    errs = [r for r in error_rows if r["game"] == game]
    if errs:
        cats = [c for c in colours if any(r.get(c) for r in errs)]
        bars = [(f"{r['model']} / {r['experiment']}", {c: r.get(c, 0) for c in cats}) for r in errs]
        parts.append("<h3>Error categories per model and experiment (share of episodes)</h3>"
                     + charts.stacked_bars(bars, cats, colours))
    dialogue = [d for d in dialogue_table.dialogue_episodes(own) if d["mode"] != "oneshot"]  # one round: no curve
    if dialogue:
        parts.append("<h3>ES by round of the dialogue modes</h3>" + charts.line_plot(dialogue_table.curves(dialogue)))
    counts, rows, cols, counted = failed_cells(results, [e for e in own if e["category"] != "harness_error"])
    if counted:
        parts.append(f"<h3>Where the failed builds differ from the target ({counted} failed episodes; rows and "
                     f"columns counted from 1)</h3>" + charts.heat_map(counts, rows, cols))
    parts.append("<h3>Example transcripts (one per model, experiment and error category)</h3>"
                 + examples(results, out, own))
    return "\n".join(parts)


def write(results: Path, out: Path, everything: list[dict], table_rows: list[dict], error_rows: list[dict],
          categories: list[str], found: Completeness, harness_rows: list[dict],
          tables: dict[str, list[str]] | None = None, after: str = "") -> list[str]:
    """Write out/report.html; the names written. tables: game -> further HTML tables (sartco.report.html_tables);
    after: sections (HTML, escaped) after the games' (contamination, robustness)."""
    tables = tables or {}
    colours = category_colours(categories)
    where = Path(os.path.relpath(results.resolve(), out.resolve())).as_posix()
    by_game: dict[str, list] = defaultdict(list)
    for r in table_rows:
        by_game[r["game"]].append(r)
    games = sorted({e["game"] for e in everything} | set(by_game))
    body = [f"<h1>SARTCo report</h1><p>{len(everything)} episodes from <code>{esc(results)}</code>. Transcript links "
            f"assume the results folder at <code>{esc(where)}</code> relative to this file.</p>",
            warnings(found, harness_rows),
            "<p>Games: " + ", ".join(f"<a href='#{esc(g)}'>{esc(g)}</a>" for g in games) + "</p>"]
    body += [game_section(g, results, out, everything, by_game.get(g, []), error_rows, colours, tables.get(g, []))
             for g in games]
    body.append(after)
    body.append("<h2>Generation settings and provenance (run.json)</h2>" + provenance(found))
    page = (f"<!DOCTYPE html>\n<html lang='en'><head><meta charset='utf-8'><title>SARTCo report</title>"
            f"<style>{STYLE}</style></head><body>\n" + "\n".join(body) + "\n</body></html>\n")
    (out / NAME).write_text(page, encoding="utf-8")
    return [NAME]
