"""robustness.md / .csv of `sartco report` (issue 24 item 4): is a board solved under every
description of it?

The published data describes each test board by a template and a human (and the optimal-function
and regular-simple boards also by CodeLlama, GPT-4 and Claude); every description of one board
is one episode with the board's id (instance.json `board_id`) in one experiment per source. Episodes
are matched on (model, task, board id) across the games of one protocol (GAMES: the template cells
of the published boards are played in cobot_instruct_fresh, the human- and model-written ones in
cobot_instruct_published; the one-shot test cells only: no ablation, feedback or dialogue). A
board counts when it was played under at least two sources; it is solved under a source when its
ES is 1 (two episodes of one source: their mean).

Per model, per board kind and task and over all ("all"): boards; the share solved under every
source (`all`, with its 95 % bootstrap interval), under some but not every source (`some`) and
under none (`none`); the ES (%) of each source over those boards, and the spread: the highest
source ES minus the lowest (percentage points; 0 when every source scores alike).
"""
from __future__ import annotations

import json
from collections import defaultdict
from pathlib import Path

from sartco.dataset import SOURCES

from . import intervals
from .charts import esc
from .files import markdown_table, write_csv

GAMES = ("cobot_instruct", "cobot_instruct_published", "cobot_instruct_fresh")
HEADER = ["model", "board_type", "object_type", "task", "boards", "sources", "all", "all_lo", "all_hi", "some",
          "none", *(f"es_{s}" for s in SOURCES), "spread"]


def board_id(results: Path, e: dict) -> str | None:
    path = results / e["model"] / e["game"] / e["experiment"] / e["episode"] / "instance.json"
    try:
        return json.loads(path.read_text(encoding="utf-8")).get("board_id")
    except (OSError, ValueError, AttributeError):
        return None


def solved_by_source(results: Path, episodes: list[dict]) -> dict[tuple, dict[str, float]]:
    """(model, board type, object type, task, board id) -> source -> ES in [0, 1]."""
    found: dict[tuple, dict[str, list]] = defaultdict(lambda: defaultdict(list))
    for e in episodes:
        if e["game"] not in GAMES or e["ablation"] or e["max_attempts"] > 1 or e["mode"] != "oneshot" \
                or e["split"] != "test" or not e["source"]:
            continue
        bid = board_id(results, e)
        if bid is not None:
            found[(e["model"], e["board_type"], e["object_type"], e["task"], bid)][e["source"]].append(e["es"] or 0.0)
    return {k: {s: sum(v) / len(v) for s, v in per.items()} for k, per in found.items() if len(per) >= 2}


def _row(model: str, cell: tuple, boards: list[dict[str, float]]) -> dict:
    n = len(boards)
    every = sum(all(v == 1.0 for v in b.values()) for b in boards)
    none = sum(all(v == 0.0 for v in b.values()) for b in boards)
    lo, hi = intervals.interval([1.0] * every + [0.0] * (n - every))
    sources = [s for s in SOURCES if any(s in b for b in boards)]
    es = {s: 100 * sum(b[s] for b in boards if s in b) / sum(s in b for b in boards) for s in sources}
    return {"model": model, "board_type": cell[0], "object_type": cell[1], "task": cell[2], "boards": n,
            "sources": " ".join(sources), "all": round(100 * every / n, 2), "all_lo": round(100 * lo, 2),
            "all_hi": round(100 * hi, 2), "some": round(100 * (n - every - none) / n, 2),
            "none": round(100 * none / n, 2), **{f"es_{s}": round(es[s], 2) if s in es else "" for s in SOURCES},
            "spread": round(max(es.values()) - min(es.values()), 2)}


def rows(results: Path, episodes: list[dict]) -> list[dict]:
    cells: dict[tuple, list] = defaultdict(list)
    for (model, board, obj, task, _), per in sorted(solved_by_source(results, episodes).items()):
        cells[(model, (board, obj, task))].append(per)
    out = []
    for model in sorted({m for m, _ in cells}):
        mine = sorted(c for m, c in cells if m == model)
        out += [_row(model, c, cells[(model, c)]) for c in mine]
        out.append(_row(model, ("all", "all", "all"), [b for c in mine for b in cells[(model, c)]]))
    return out


def markdown(table: list[dict]) -> str:
    body = [[r["model"], r["board_type"], r["object_type"], r["task"], r["boards"], r["sources"],
             f"{r['all']:.2f} [{r['all_lo']:.2f}, {r['all_hi']:.2f}]", r["some"], r["none"],
             " / ".join(f"{s} {r[f'es_{s}']:.2f}" for s in SOURCES if r[f"es_{s}"] != ""), r["spread"]]
            for r in table]
    return ("# Robustness to the instruction source (paraphrases of one board)\n\n"
            "Boards played under at least two instruction sources (template, human, codellama, gpt4, claude); "
            "all / some / none = share (%) of them solved (ES = 1) under every source / some but not every / no "
            "source (all with its 95 % bootstrap interval); ES per source over the same boards; spread = highest "
            "minus lowest source ES (percentage points).\n\n"
            + markdown_table(["model", "board", "object", "task", "boards", "sources", "all", "some", "none",
                              "ES per source", "spread"], body))


def html(table: list[dict]) -> str:
    if not table:
        return ""
    head = "".join(f"<th>{h}</th>" for h in ("model", "board", "object", "task", "boards", "all (%)", "some (%)",
                                                "none (%)", "ES per source", "spread (pp)"))
    body = "".join("<tr>" + "".join(f"<td>{esc(v)}</td>" for v in (
        r["model"], r["board_type"], r["object_type"], r["task"], r["boards"],
        f"{r['all']:.2f} [{r['all_lo']:.2f}, {r['all_hi']:.2f}]", r["some"], r["none"],
        " / ".join(f"{s} {r[f'es_{s}']:.2f}" for s in SOURCES if r[f"es_{s}"] != ""), r["spread"])) + "</tr>"
        for r in table)
    return (f"<h2 id='robustness'>Robustness to the instruction source</h2><p>Boards described by several "
            f"sources: solved under all, some or none of them (robustness.md).</p><table><tr>{head}</tr>{body}</table>")


def write(results: Path, episodes: list[dict], out: Path) -> tuple[list[str], str]:
    """robustness.md / .csv when some board was played under two sources; (names written, html)."""
    table = rows(results, episodes)
    if not table:
        return [], ""
    write_csv(out / "robustness.csv", HEADER, table)
    (out / "robustness.md").write_text(markdown(table), encoding="utf-8")
    return ["robustness.md", "robustness.csv"], html(table)
