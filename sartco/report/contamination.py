"""contamination.md / .csv of `sartco report` (issue 24 item 3): a model's ES on the published test
boards beside its ES on fresh boards (cobot_instruct_fresh, sartco.games.instruct.fresh).

Like with like: the two experiments of a row share the game, the board kind, the task, the
instruction source (template: the only source the fresh boards have), the prompt and its in-context
examples; they differ in the boards alone, drawn stratum by stratum (board kind, combination,
quadrant or arrangement) so that the fresh set has the published set's mix. The published
human- and model-written cells (cobot_instruct_published) and the seed-42 template cells
(cobot_instruct) are never compared with the fresh boards: another source or another board mix.
gap = ES(published) - ES(fresh), percentage points; a positive gap is what a model that has seen
the published boards would show. Intervals: 95 % percentile bootstrap (sartco.report.intervals),
the gap's by resampling both sets independently (they are different boards) from one generator.
"""
from __future__ import annotations

from collections import defaultdict
from pathlib import Path

import numpy as np

from . import intervals
from .charts import esc
from .files import markdown_table, write_csv

BOARDS = ("published", "fresh")
HEADER = ["model", "game", "board_type", "object_type", "task", "source", "fresh_seed", "published_episodes",
          "es_published", "es_published_lo", "es_published_hi", "fresh_episodes", "es_fresh", "es_fresh_lo",
          "es_fresh_hi", "gap", "gap_lo", "gap_hi"]


def boards_of(e: dict) -> str | None:
    """published | fresh for an episode of a contamination experiment, else None."""
    boards = (e.get("experiment_fields") or {}).get("boards")
    return boards if boards in BOARDS else None


def _gap(pub: np.ndarray, fresh: np.ndarray) -> tuple[float, float]:
    rng = np.random.default_rng(intervals.SEED)
    diff = intervals.resampled_means(pub, rng) - intervals.resampled_means(fresh, rng)
    lo, hi = np.percentile(diff, [50 * (1 - intervals.LEVEL), 50 * (1 + intervals.LEVEL)])
    return float(lo), float(hi)


def _row(key: tuple, pub: list[dict], fresh: list[dict]) -> dict:
    model, game, board, obj, task, source, seed = key
    row = {"model": model, "game": game, "board_type": board, "object_type": obj, "task": task, "source": source,
           "fresh_seed": seed}
    xs = {}
    for name, group in (("published", pub), ("fresh", fresh)):
        xs[name] = intervals.values(group, "es")
        lo, hi = intervals.interval(xs[name])
        row.update({f"{name}_episodes": len(group), f"es_{name}": round(100 * float(xs[name].mean()), 2),
                    f"es_{name}_lo": round(100 * lo, 2), f"es_{name}_hi": round(100 * hi, 2)})
    lo, hi = _gap(xs["published"], xs["fresh"])
    row.update(gap=round(row["es_published"] - row["es_fresh"], 2), gap_lo=round(100 * lo, 2),
               gap_hi=round(100 * hi, 2))
    return row


def rows(episodes: list[dict]) -> list[dict]:
    """One row per model and cell with both published and fresh episodes, then one per model over
    all its cells (board type "all")."""
    groups: dict[tuple, dict[str, list]] = defaultdict(lambda: {b: [] for b in BOARDS})
    for e in episodes:
        boards = boards_of(e)
        if boards is None or e["max_attempts"] > 1 or e["ablation"]:
            continue
        seed = (e.get("experiment_fields") or {}).get("fresh_seed")
        key = (e["model"], e["game"], e["board_type"], e["object_type"], e["task"], e["source"], seed)
        groups[key][boards].append(e)
    out, pooled = [], defaultdict(lambda: {b: [] for b in BOARDS})
    for key in sorted(groups, key=lambda k: tuple(str(v) for v in k)):
        g = groups[key]
        if g["published"] and g["fresh"]:
            out.append(_row(key, g["published"], g["fresh"]))
            for b in BOARDS:
                pooled[(key[0], key[1], key[6])][b] += g[b]
    for (model, game, seed), g in sorted(pooled.items(), key=lambda kv: tuple(str(v) for v in kv[0])):
        out.append(_row((model, game, "all", "all", "all", "template", seed), g["published"], g["fresh"]))
    return out


def _shown(r: dict, metric: str) -> str:
    return f"{r[metric]:.2f} [{r[metric + '_lo']:.2f}, {r[metric + '_hi']:.2f}]"


def markdown(table: list[dict]) -> str:
    body = [[r["model"], r["board_type"], r["object_type"], r["task"], r["source"], r["fresh_seed"],
             r["published_episodes"], _shown(r, "es_published"), r["fresh_episodes"], _shown(r, "es_fresh"),
             _shown(r, "gap")] for r in table]
    return ("# Contamination: published vs fresh boards (cobot_instruct_fresh)\n\n"
            "ES (%) on the published test boards and on fresh boards of the same strata (board kind, combination, "
            "quadrant or arrangement; in no published file and no seed-42 file), template instructions, the same "
            "prompt; gap = published - fresh (percentage points), each `x [lo, hi]` with its 95 % bootstrap "
            "interval. A gap above 0 whose interval excludes 0 is what a model that saw the published boards "
            "shows.\n\n" + markdown_table(["model", "board", "object", "task", "source", "fresh seed", "n published",
                                           "ES published", "n fresh", "ES fresh", "gap"], body))


def html(table: list[dict]) -> str:
    """The table for report.html (escaped)."""
    if not table:
        return ""
    head = "".join(f"<th>{h}</th>" for h in ("model", "board", "object", "task", "n published", "ES published",
                                                "n fresh", "ES fresh", "gap (pp)"))
    body = "".join("<tr>" + "".join(f"<td>{esc(v)}</td>" for v in (
        r["model"], r["board_type"], r["object_type"], r["task"], r["published_episodes"], _shown(r, "es_published"),
        r["fresh_episodes"], _shown(r, "es_fresh"), _shown(r, "gap"))) + "</tr>" for r in table)
    return (f"<h2 id='contamination'>Contamination: published vs fresh boards</h2><p>Template instructions, the same "
            f"prompt; the fresh boards of the published boards' strata (contamination.md).</p>"
            f"<table><tr>{head}</tr>{body}</table>")


def write(episodes: list[dict], out: Path) -> tuple[list[str], str]:
    """contamination.md / .csv when there are fresh-board episodes; (names written, html fragment)."""
    table = rows(episodes)
    if not table:
        return [], ""
    write_csv(out / "contamination.csv", HEADER, table)
    (out / "contamination.md").write_text(markdown(table), encoding="utf-8")
    return ["contamination.md", "contamination.csv"], html(table)
