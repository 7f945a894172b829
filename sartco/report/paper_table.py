"""Table 3 in the paper protocol, beside the paper's own figures (part of `sartco report`).

Reads the paper's Table 3 (`table3.json` in ../shared/sartco-data/paper-protocol, at run time)
and the episodes of paper-protocol experiments (experiment field `protocol: "paper"`, game entry
cobot_instruct_paper) from the rows of sartco.report.rows.collect, and writes
  paper_table3.md / paper_table3.csv
one line per Table 3 cell and instruction source, in the paper's order: the paper's EM, CB, ES for
CodeLlama-34B, GPT-4 and Claude-3, then the same for each model of the results (the mean over the
cell's episodes of "Paper EM", "Paper CB", "Paper ES", shares 0..1, as the paper prints them), and
beyond the paper "Paper ES Leak-free" and "Function Generalisation" (no paper figure).
The paper's model-written rows belong to the CodeLlama-written files (table3.json's note); the
GPT-4- and Claude-written files have no figure in the paper. Cells in the results that Table 3
does not have come last. A model run with other generation settings than the paper's
(table3.json "settings": temperature 0, 250 new tokens; clemcore records them per episode in
scores.json "player_models") is marked "(!)" and named under the table. The project-protocol
Table 3 (report's table3.md) follows in the same file, so both are seen at one glance.
"""
from __future__ import annotations

from pathlib import Path

from sartco.dataset import SOURCES as SOURCE_ORDER
from sartco.episode import FUNCTION_GENERALISATION, LEAK_FREE_ES, PAPER_SCORES
from sartco.paper import PROTOCOL
from sartco.paper.table3 import CELL_KEYS, TABLE3, cell_key as _key, cell_source as _source, generation, load_table3

from .files import write_csv

FLAG = "(!)"
# beyond the paper: the leak-free ES (the answer without the gold function in front) and the function
# probes' share (probed cells only), as shares 0..1; the paper has no figure for them
OURS = {"es_leak_free": LEAK_FREE_ES, "fg": FUNCTION_GENERALISATION}
METRICS = {**PAPER_SCORES, **OURS}
NAMES = ("EM", "CB", "ES", "ES leak-free", "FG")


def is_paper_episode(e: dict) -> bool:
    """A report row (sartco.report.rows.collect) of an episode played in the paper protocol."""
    return e["experiment_fields"].get("protocol") == PROTOCOL


def paper_episodes(episodes: list[dict]) -> list[dict]:
    """The report rows of paper-protocol episodes, with their cell, scores and generation settings."""
    out = []
    for e in episodes:
        exp = e["experiment_fields"]
        if not is_paper_episode(e):
            continue
        scores = e["scores"]
        models = e["player_models"] or {}
        out.append({"model": e["model"], "instructions": exp.get("instructions", ""), "board": exp["board_type"],
                    "object": exp["object_type"], "task": exp["task"], "variant": exp.get("variant", ""),
                    "source": exp.get("source", ""),
                    **{k: float(scores.get(name) or 0.0) for k, name in PAPER_SCORES.items()},
                    "es_leak_free": float(scores.get(LEAK_FREE_ES) or 0.0),
                    "fg": float(scores.get(FUNCTION_GENERALISATION) or 0.0) if FUNCTION_GENERALISATION in scores else None,
                    "gen_args": [dict(m.get("gen_args") or {}) for m in models.values()]})
    return out


def settings_note(rows: list[dict], wanted: dict) -> dict[str, str]:
    """model -> why its runs are not comparable with the paper's (absent when they are)."""
    seen: dict[str, list] = {}
    for r in rows:
        for args in r["gen_args"] or [{}]:
            got = {k: args.get(k) for k in wanted}
            if got not in seen.setdefault(r["model"], []):
                seen[r["model"]].append(got)
    notes = {}
    for model, settings in seen.items():
        bad = [s for s in settings if any(s[k] is None or float(s[k]) != float(v) for k, v in wanted.items())]
        if bad:
            shown = "; ".join(", ".join(f"{k} {'not recorded' if v is None else v}" for k, v in s.items()) for s in bad)
            notes[model] = f"run with {shown}"
    return notes


def table(table3: dict, rows: list[dict]) -> tuple[list[str], list[dict]]:
    """Long rows: one per cell, source and model (the paper's models first)."""
    paper_models = list(table3["models"])
    cells = {}
    for cell in table3["cells"]:
        cells[_key({**cell, "source": _source(cell)})] = cell
    means: dict[tuple, dict[str, list]] = {}
    for r in rows:
        key = _key(r)
        cells.setdefault(key, None)
        means.setdefault(key, {}).setdefault(r["model"], []).append(r)
    models = sorted({r["model"] for r in rows})
    positions = {k[:len(CELL_KEYS)]: i for i, k in reversed(list(enumerate(cells)))}

    def order(key):  # Table 3's order; another source of the same cell beside it; other cells last
        source = key[-1]
        return (positions.get(key[:len(CELL_KEYS)], len(positions)), key[:len(CELL_KEYS)],
                SOURCE_ORDER.index(source) if source in SOURCE_ORDER else len(SOURCE_ORDER), source)
    out = []
    for key in sorted(cells, key=order):
        cell = cells[key]
        base = dict(zip(CELL_KEYS + ("source",), key))
        for m in paper_models:
            scores = (cell or {}).get("scores", {}).get(m)
            out.append({**base, "model": f"paper {table3['models'][m]}", "paper": 1, "episodes": "",
                        **({k: v for k, v in zip(PAPER_SCORES, scores)} if scores else dict.fromkeys(PAPER_SCORES)),
                        **dict.fromkeys(OURS)})
        for m in models:
            group = means.get(key, {}).get(m, [])
            out.append({**base, "model": m, "paper": 0, "episodes": len(group),
                        **{k: _mean([r[k] for r in group]) for k in METRICS}})
    return [*CELL_KEYS, "source", "model", "paper", "episodes", *METRICS], out


def _mean(values: list) -> float | None:
    """The mean over a group (None: no episode, or a rate none of them has, as FG of unprobed cells)."""
    values = [v for v in values if v is not None]
    return sum(values) / len(values) if values else None


def column_label(row: dict, notes: dict[str, str]) -> str:
    """A model's column: the paper's ("paper GPT-4") or these results' in the paper protocol, flagged when
    its generation settings were not the paper's."""
    return row["model"] + ("" if row["paper"] else ", paper protocol") + (f" {FLAG}" if row["model"] in notes else "")


def markdown(header_rows: tuple[list[str], list[dict]], notes: dict[str, str], wanted: dict) -> str:
    _, rows = header_rows
    columns = []  # (model name, label) in first-seen order
    for r in rows:
        label = column_label(r, notes)
        if (r["model"], label) not in columns:
            columns.append((r["model"], label))
    lines: dict[tuple, dict] = {}
    for r in rows:
        lines.setdefault(tuple(r[k] for k in (*CELL_KEYS, "source")), {})[r["model"]] = r
    head = ["instructions", "board", "object", "task", "source"] + [label for _, label in columns]
    tables = []
    for metric, name in zip(METRICS, NAMES):  # one narrow table per metric
        out = [f"### {name}\n", "| " + " | ".join(head) + " |", "|" + "|".join("---" for _ in head) + "|"]
        for key, by_model in lines.items():
            cell = [key[0], key[1], key[2], f"{key[3]} ({key[4]})", key[5]]
            cell += [shown_score(by_model.get(model), metric) for model, _ in columns]
            out.append("| " + " | ".join(cell) + " |")
        tables.append("\n".join(out) + "\n")
    text = ("## cobot_instruct_paper: Table 3 in the paper protocol\n\n"
            "EM, CB (CodeBLEU > 0.5 pass rate), ES as shares 0..1, per turn and averaged over a cell's "
            "episodes, as the paper measured them; the paper's figures are the first columns (\"paper ...\"), "
            "the models of these results follow (\"..., paper protocol\": played and scored by the authors' rules; "
            "these runs appear in no SARTCo-protocol table below, so each figure is shown once). The paper's model-written rows used the CodeLlama-written "
            "instructions; GPT-4- and Claude-written instructions have no figure in the paper (\"no figure\"); "
            "\"not run\": a cell these results do not hold. Beyond the paper: \"ES leak-free\" runs each answer "
            "without the gold object function the paper puts in front of it (regular cells; elsewhere it "
            "equals ES), \"FG\" is the share of function probes built exactly (sartco.clem.core.probes; \"n/a\": a "
            "cell without probes); the paper's ES stays the paper's.\n\n")
    text += "\n".join(tables)
    if notes:
        text += (f"\n{FLAG} not comparable with the paper, which generated with temperature "
                 f"{wanted['temperature']:g} and at most {wanted['max_tokens']} new tokens "
                 f"(`clem run -t {wanted['temperature']:g} -l {wanted['max_tokens']}`): "
                 + "; ".join(f"{m}: {why}" for m, why in sorted(notes.items())) + ".\n")
    return text


def shown_score(row: dict | None, metric: str) -> str:
    if row is None or (not row["paper"] and not row["episodes"]):
        return "not run"
    if row[metric] is None:
        return "no figure" if row["paper"] else "n/a"
    return f"{row[metric]:.2f}"


def write(episodes: list[dict], out: Path, project_markdown: str, table3_path: Path = TABLE3):
    """Write paper_table3.md (the paper-protocol table, then `project_markdown`) and .csv when the
    results hold paper-protocol episodes. Returns (file names written, the paper table's Markdown
    or None)."""

    rows = paper_episodes(episodes)
    if not rows:
        return [], None
    table3 = load_table3(table3_path)
    wanted = generation(table3)
    header, long_rows = table(table3, rows)
    md = markdown((header, long_rows), settings_note(rows, wanted), wanted)
    write_csv(out / "paper_table3.csv", header, long_rows)
    (out / "paper_table3.md").write_text("# SARTCo results: the paper's protocol and ours\n\n" + md + "\n"
                                         + project_markdown, encoding="utf-8")
    return ["paper_table3.md", "paper_table3.csv"], md
