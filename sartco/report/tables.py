"""`sartco report -r RESULTS [--out scores/]`: the paper's tables from a clemcore results folder.

Reads every episode's scores.json (written by `clem score`) and its experiment.json, and writes,
as Markdown and CSV:
  table3.md / table3.csv      board type, object type, task, instruction source, model: EM, CB, ES, FG
                              (the paper's Table 3; test-split experiments without ablation; the
                              cobot_instruct_published rows under cobot_instruct, TABLE3_GAME)
  paper_table3.md / .csv      Table 3 in the paper protocol beside the paper's figures, then table3.md
                              (sartco.report.paper_table; only when there are paper-protocol episodes)
  ablations.md / ablations.csv  the val-split ablations (in-context examples, removed prompt sections)
  errors.md / errors.csv      episodes per error category, per model and experiment
  repair.md / repair.csv      feedback experiments (experiment field `attempts` N > 1), per model
                              and experiment: ES@1, ES@N, the share of first-attempt failures
                              repaired, mean attempts used (only when there are such episodes)
  dialogue.md / .csv / dialogue_rounds.svg   cobot_describe's dialogue scores (sartco.report.dialogue_table)
  harness.md / harness.csv    episodes per model and game in which the harness failed, not the
                              model (harness_error; sartco.report.harness_table)
Numbers are percentages over all episodes of a cell; an aborted episode (no code found) counts
as 0 for EM, CB and ES, and is listed as parse_error in the error tables. A harness_error episode
is no measurement of the model: it is left out of every table but errors.md and harness.md, and
the report then exits with status 3 (harness_table.HARNESS_STATUS; the tables are written). Feedback experiments
and cobot_describe's dialogue modes are kept out of table3 and the ablations (they are not the
paper's protocol).
"""
from __future__ import annotations

import argparse
import re
from collections import Counter, defaultdict
from pathlib import Path

from sartco.dataset import SOURCES as SOURCE_ORDER, TASKS as TASK_ORDER

from . import (completeness, contamination, dialogue_table, harness_table, html, html_tables, intervals, paper_table,
               passk, robustness)
from .files import markdown_table, percent, replace_stale, write_csv
from .rows import TASK_NAMES, collect

# clemgame entries whose cells are rows of another game's Table 3 (the published human- and
# model-written instructions beside the template ones, as in the paper); every other game name
# (cobot_instruct_ablations, _feedback, ...) is reported under its own name
TABLE3_GAME = {"cobot_instruct_published": "cobot_instruct"}



def configure(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("-r", "--results", required=True, type=Path, help="clemcore results folder")
    parser.add_argument("--out", type=Path, default=Path("scores"), help="folder for the tables (default: scores/)")
    parser.add_argument("-g", "--game", action="append", default=None,
                        help="only this game (repeatable; default: every game with SARTCo experiments)")


def _summarise(group: list[dict]) -> dict:
    return {"episodes": len(group), "played": percent([1.0 - e["aborted"] for e in group]),
            "em": percent([e["em"] for e in group]), "cb": percent([e["cb"] for e in group]),
            "es": percent([e["es"] for e in group]), "f1": percent([e["f1"] for e in group]),
            "fg": percent([e["fg"] for e in group]) if any(e["probed"] for e in group) else float("nan"),
            **intervals.bounds(group), **completeness.cell(group)}  # 95 % bootstrap intervals: <rate>_lo, <rate>_hi


def _order(key: tuple) -> tuple:
    game, board, obj, task, source = key[:5]
    return (game, board != "simple", obj != "simple", TASK_ORDER.index(task) if task in TASK_ORDER else 99,
            SOURCE_ORDER.index(source) if source in SOURCE_ORDER else 99, source) + tuple(str(k) for k in key[5:])


def _natural(key: tuple) -> list:
    """Sort key of (model, game, experiment): numbers inside names in numeric order."""
    return [int(t) if t.isdigit() else t for t in re.split(r"(\d+)", "/".join(key))]


def table3(episodes: list[dict]) -> tuple[list[str], list[dict]]:
    """Long rows (one per cell and model) of the paper's Table 3."""
    groups: dict[tuple, list] = defaultdict(list)
    for e in episodes:
        if e["ablation"] or e["max_attempts"] > 1 or e["mode"] != "oneshot" or contamination.boards_of(e):
            continue
        if paper_table.is_paper_episode(e):  # scored once, in the paper protocol: paper_table3.md
            continue
        game = TABLE3_GAME.get(e["game"], e["game"])
        groups[(game, e["board_type"], e["object_type"], e["task"], e["source"], e["split"], e["model"])].append(e)
    rows = []
    for key in sorted(groups, key=_order):
        game, board, obj, task, source, split, model = key
        rows.append({"game": game, "board_type": board, "object_type": obj, "task": task, "source": source,
                     "split": split, "model": model, **_summarise(groups[key])})
    return intervals.columns(["game", "board_type", "object_type", "task", "source", "split", "model", "episodes",
                              "episodes_expected", "episodes_scored", "played", "em", "cb", "es", "fg", "f1"]), rows


def ablations(episodes: list[dict]) -> tuple[list[str], list[dict]]:
    groups: dict[tuple, list] = defaultdict(list)
    for e in episodes:
        if not e["ablation"] or e["max_attempts"] > 1:
            continue
        ab = e["ablation"]
        groups[(e["game"], e["board_type"], e["object_type"], e["task"], e["source"], ab.get("kind", ""),
                str(ab.get("value", "")), e["model"])].append(e)
    def order(key):
        kind, value = key[5], key[6]
        return _order(key[:5]) + (kind, int(value) if value.isdigit() else 99, value, key[7])
    rows = []
    for key in sorted(groups, key=order):
        game, board, obj, task, source, kind, value, model = key
        rows.append({"game": game, "board_type": board, "object_type": obj, "task": task, "source": source,
                     "ablation": kind, "value": value, "model": model, **_summarise(groups[key])})
    return intervals.columns(["game", "board_type", "object_type", "task", "source", "ablation", "value", "model",
                              "episodes", "episodes_expected", "episodes_scored", "played", "em", "cb", "es",
                              "fg", "f1"]), rows


def errors(episodes: list[dict]) -> tuple[list[str], list[dict]]:
    counts: dict[tuple, Counter] = defaultdict(Counter)
    for e in episodes:
        counts[(e["model"], e["game"], e["experiment"])][e["category"]] += 1
    categories = sorted({c for counter in counts.values() for c in counter}, key=lambda c: (c != "success", c))
    rows = []
    for (model, game, experiment) in sorted(counts, key=_natural):
        counter = counts[(model, game, experiment)]
        rows.append({"model": model, "game": game, "experiment": experiment,
                     "episodes": sum(counter.values()), **{c: counter.get(c, 0) for c in categories}})
    return ["model", "game", "experiment", "episodes", *categories], rows


def repair(episodes: list[dict]) -> tuple[list[str], list[dict]]:
    """Feedback experiments, per model and experiment: ES@1 and ES@N (% of episodes; aborted
    = 0), first-attempt failures, how many of them were repaired and their share (%), mean
    attempts used."""
    groups: dict[tuple, list] = defaultdict(list)
    for e in episodes:
        if e["max_attempts"] > 1:
            groups[(e["model"], e["game"], e["experiment"])].append(e)
    rows = []
    for key in sorted(groups, key=_natural):
        model, game, experiment = key
        group = groups[key]
        first = sum(1 for e in group if e["es1"])
        last = sum(1 for e in group if e["es"])
        failures = len(group) - first
        used = [e["attempts_used"] for e in group if e["attempts_used"] is not None]
        rows.append({"model": model, "game": game, "experiment": experiment, "feedback_of": group[0]["feedback_of"],
                     "attempts": group[0]["max_attempts"], "episodes": len(group),
                     "es_at_1": percent([e["es1"] for e in group]), "es_at_n": percent([e["es"] for e in group]),
                     "first_failures": failures, "repaired": last - first,
                     "repaired_share": round(100.0 * (last - first) / failures, 2) if failures else float("nan"),
                     "mean_attempts": round(sum(used) / len(used), 2) if used else float("nan")})
    return ["model", "game", "experiment", "feedback_of", "attempts", "episodes", "es_at_1", "es_at_n",
            "first_failures", "repaired", "repaired_share", "mean_attempts"], rows


def table3_markdown(rows: list[dict], title: str, keys: list[str]) -> str:
    """The paper's layout, narrow: one table per metric (EM, CB, ES), a line per cell, a column per model."""
    models = sorted({r["model"] for r in rows})
    cells: dict[tuple, dict] = {}
    for r in rows:
        cells.setdefault(tuple(r[k] for k in keys), {})[r["model"]] = r
    header = [k.replace("_", " ") for k in keys] + models
    tables = []
    for x, name in (("em", "EM"), ("cb", "CB"), ("es", "ES"), ("fg", "FG")):
        body = [[TASK_NAMES.get(v, v) if k == "task" else v for k, v in zip(keys, key)]
                + [completeness.mark(intervals.shown(by_model[m], x), by_model[m]) if m in by_model else "not run"
                   for m in models] for key, by_model in cells.items()]
        tables.append(f"### {title}: {name}\n\n" + markdown_table(header, body))
    played = {m: [r for r in rows if r["model"] == m] for m in models}
    note = "; ".join(f"{m}: {sum(r['episodes'] for r in rs)} episodes, " + intervals.shown_counts(
        round(sum(r["played"] * r["episodes"] / 100 for r in rs)), sum(r["episodes"] for r in rs)) + "% played"
        for m, rs in played.items())
    return (f"## {title}\n\nEM = exact match, CB = CodeBLEU, ES = execution success (%), FG = function "
            f"generalisation (% of function probes built exactly; n/a: a cell without probes), each `x [lo, hi]` "
            f"with its 95 % bootstrap interval; \"not run\": a cell the model did not play. {note}.\n\n"
            + "\n".join(tables))


def run(args: argparse.Namespace) -> int:
    if passk.samples_only(args.results):  # nothing but `sartco sample`'s runs
        return passk.write_alone(args.results, args.out)
    everything = collect(args.results, args.game)
    found = completeness.check(args.results, args.game, {e["game"] for e in everything})
    found.annotate(everything)
    episodes = [e for e in everything if not harness_table.is_harness(e)]  # the model's measurements
    out: Path = args.out
    out.mkdir(parents=True, exist_ok=True)
    written = []
    header, rows = table3(episodes)
    cells = rows
    write_csv(out / "table3.csv", header, rows)
    md = "# SARTCo results (paper Table 3 layout)\n\n"
    if not rows:
        md += "No episodes in the SARTCo protocol's Table 3 cells (paper protocol: paper_table3.md; feedback: repair.md; dialogue modes: dialogue.md).\n"
    for game in sorted({r["game"] for r in rows}):
        md += table3_markdown([r for r in rows if r["game"] == game], f"{game} (SARTCo protocol)",
                              ["board_type", "object_type", "task", "source"]) + "\n"
    (out / "table3.md").write_text(md, encoding="utf-8")
    written += ["table3.md", "table3.csv"]
    files, paper_md = paper_table.write(episodes, out, md)  # the paper protocol's Table 3, beside the paper's
    written += files
    header, rows = ablations(episodes)
    ablation_rows = rows
    if rows:
        write_csv(out / "ablations.csv", header, rows)
        md = "# Ablations (val split)\n\n"
        for game in sorted({r["game"] for r in rows}):
            md += table3_markdown([r for r in rows if r["game"] == game], game,
                                  ["board_type", "object_type", "task", "source", "ablation", "value"]) + "\n"
        (out / "ablations.md").write_text(md, encoding="utf-8")
        written += ["ablations.md", "ablations.csv"]
    header, rows = repair(episodes)
    extra = html_tables.sections(episodes, ablation_rows, rows)  # report.html's further tables
    if rows:
        write_csv(out / "repair.csv", header, rows)
        md = ("# Repair after execution feedback (feedback experiments)\n\n"
              "ES@1 / ES@N = execution success (%) after the first / the last attempt (aborted = 0); "
              "repaired share = (successes at N - successes at 1) / first-attempt failures (%; "
              "nan when nothing failed); mean attempts = attempts used per episode.\n\n")
        md += markdown_table(["model", "game", "experiment", "of", "N", "episodes", "ES@1", "ES@N", "failed@1", "repaired",
                   "repaired share", "mean attempts"], [[r[h] for h in header] for r in rows])
        (out / "repair.md").write_text(md, encoding="utf-8")
        written += ["repair.md", "repair.csv"]
    written += dialogue_table.write(episodes, out)  # cobot_describe's dialogue modes
    files, after = contamination.write(episodes, out)  # published vs fresh boards; robustness across sources
    more, after_robust = robustness.write(args.results, episodes, out)
    written += files + more
    files, sample_faults = passk.write(args.results, out)  # pass@k of `sartco sample`'s runs (RESULTS/samples/s1..sN)
    written += files
    header, rows = errors(everything)
    write_csv(out / "errors.csv", header, rows)
    md = "# Error categories (episodes per category)\n\n" + markdown_table(header, [[r[h] for h in header] for r in rows])
    (out / "errors.md").write_text(md, encoding="utf-8")
    written += ["errors.md", "errors.csv"]
    files, faults = harness_table.write(everything, out, args.results)
    written += files
    if paper_md:
        print(paper_md)
    written += completeness.write(found, out)
    written += html.write(args.results, out, everything, cells, rows, header[4:], found, harness_table.rows(everything),
                          extra, after + after_robust)
    stale = replace_stale(out, written)
    print(f"sartco report: {len(everything)} episodes -> " + ", ".join(str(out / w) for w in written)
          + (f"; removed {len(stale)} stale files of an earlier report: " + ", ".join(stale) if stale else ""))
    status = completeness.finish(found, out, written)
    return status or (harness_table.HARNESS_STATUS if faults or sample_faults else 0)
