"""`sartco compare -r RESULTS A B`: model A against model B on the same episodes.

Per (game, experiment) and overall, over the episodes both models have scores for (matched by
game, experiment and episode folder): the paired difference A - B of every rate (percentage
points) with its 95 % percentile bootstrap interval (the episodes resampled in pairs; method,
seed and resamples as sartco.report.intervals), and for execution success the exact McNemar
test: a two-sided binomial test (p = 1/2) on the discordant pairs, b = episodes only A solved,
c = episodes only B solved, p = min(1, 2 P(X <= min(b, c))), X ~ Binomial(b + c, 1/2); p = 1 when
there is no discordant pair. Written as compare.md / compare.csv in --out and printed.
"""
from __future__ import annotations

import argparse
from collections import defaultdict
from fractions import Fraction
from math import comb
from pathlib import Path

import numpy as np

from sartco.errors import UserError

from . import intervals
from .files import markdown_table, write_csv
from .rows import collect


def configure(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("-r", "--results", required=True, type=Path, help="clemcore results folder")
    parser.add_argument("a", help="model A (its folder name in the results, e.g. the first half of A--A)")
    parser.add_argument("b", help="model B")
    parser.add_argument("--out", type=Path, default=Path("scores"), help="folder for compare.md/.csv (default: scores/)")
    parser.add_argument("-g", "--game", action="append", default=None, help="only this game (repeatable)")


def mcnemar_p(b: int, c: int) -> float:
    """Exact two-sided McNemar p-value from the discordant counts b and c (exact as a fraction; a
    value below a float's range, e.g. 2 * 2**-1264, becomes 0.0, shown "< 1e-300" in compare.md)."""
    n = b + c
    if n == 0:
        return 1.0
    tail = Fraction(sum(comb(n, i) for i in range(min(b, c) + 1)), 2 ** n)
    return float(min(Fraction(1), 2 * tail))


def _model_matches(folder: str, name: str) -> bool:
    return folder == name or folder.split("--")[0] == name


def pairs(episodes: list[dict], a: str, b: str) -> dict[tuple, list[tuple[dict, dict]]]:
    """(game, experiment) -> [(A's episode, B's episode)] for the episodes both played."""
    by_model: dict[str, dict[tuple, dict]] = {a: {}, b: {}}
    for e in episodes:
        for name in (a, b):
            if _model_matches(e["model"], name):
                by_model[name][(e["game"], e["experiment"], e["episode"])] = e
    out: dict[tuple, list] = defaultdict(list)
    for key in sorted(by_model[a].keys() & by_model[b].keys()):
        out[key[:2]].append((by_model[a][key], by_model[b][key]))
    return out


def row(label: tuple, matched: list[tuple[dict, dict]]) -> dict:
    out = {"game": label[0], "experiment": label[1], "episodes": len(matched)}
    for metric in intervals.RATES:
        d = intervals.values([x for x, _ in matched], metric) - intervals.values([y for _, y in matched], metric)
        lo, hi = intervals.interval(d)
        out[f"d_{metric}"] = round(100 * float(np.mean(d)), 2)
        out[f"d_{metric}_lo"], out[f"d_{metric}_hi"] = round(100 * lo, 2), round(100 * hi, 2)
    only_a = sum(1 for x, y in matched if x["es"] == 1 and y["es"] != 1)
    only_b = sum(1 for x, y in matched if x["es"] != 1 and y["es"] == 1)
    out.update(es_only_a=only_a, es_only_b=only_b, mcnemar_p=mcnemar_p(only_a, only_b))
    return out


def compare(episodes: list[dict], a: str, b: str) -> list[dict]:
    matched = pairs(episodes, a, b)
    if not matched:
        raise UserError(f"no episodes played by both {a!r} and {b!r} "
                        f"(models: {', '.join(sorted({e['model'] for e in episodes}))})")
    rows = [row(label, group) for label, group in matched.items()]
    rows.append(row(("all", "all"), [p for group in matched.values() for p in group]))
    return rows


def run(args: argparse.Namespace) -> int:
    rows = compare(collect(args.results, args.game), args.a, args.b)
    header = list(rows[0])
    args.out.mkdir(parents=True, exist_ok=True)
    write_csv(args.out / "compare.csv", header, rows)
    shown = ["game", "experiment", "episodes"] + [f"Δ{m.upper()}" for m in intervals.RATES] + ["only A", "only B", "McNemar p"]
    body = [[r["game"], r["experiment"], r["episodes"]]
            + [intervals.shown({k[2:]: v for k, v in r.items() if k.startswith("d_")}, m) for m in intervals.RATES]
            + [r["es_only_a"], r["es_only_b"], f"{r['mcnemar_p']:.4g}" if r["mcnemar_p"] else "< 1e-300"] for r in rows]
    md = (f"# {args.a} - {args.b} on the same episodes\n\nDifferences in percentage points, each `x [lo, hi]` with its "
          "95 % paired bootstrap interval; only A / only B = episodes only that model executed successfully; "
          "McNemar p = exact two-sided test on those discordant pairs (execution success).\n\n" + markdown_table(shown, body))
    (args.out / "compare.md").write_text(md, encoding="utf-8")
    print(md)
    return 0
