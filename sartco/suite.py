"""`sartco suite`: many `clem run`s and what follows them, in one command, on every core.

    sartco suite -r results --out scores                      # make main's job (scripts/main.sh)
    sartco suite -r results-mine --out scores-mine -m my-model --erring -l 512   # your own model

does what these commands, one after another, would do, and writes the same files:

    sartco import <data>/published --out instances/published --quiet
    python games/cobot_instruct/instancegenerator.py --published instances/published
    python games/cobot_instruct/instancegenerator.py --protocol paper
    python games/cobot_instruct/instancegenerator.py --fresh 7
    clem run -g GAME -m MODEL -r RESULTS -t T -l L -b B     # for each (game, model) of `plan`;
                                                            # the paper protocol: -t 0 -l 250
    clem score -r RESULTS; clem transcribe -r RESULTS
    rm RESULTS/raw.csv; clem eval -r RESULTS -g GAME -m MODEL  # for each pair, in plan order
    sartco report -r RESULTS --out SCORES

What makes it faster, with the same results (scripts/compare_results.py compares every file):
- one process per core (`-j`, default: the CPUs), each importing clemcore once (about 4 s a
  command otherwise), driving clemcore's own API: `clemcore.cli.run` (with the run's options in
  the game selector, sartco.clem.core.benchmark.run_selector), `GameBenchmark.compute_scores`
  and `build_transcripts` on the pair's own folder, right after its play;
- independent tasks side by side: a pair waits only for the instance file it plays; every pair is
  played into a folder of its own (RESULTS/.suite/<n>), so that clemcore's results/<model>/run.json
  is never written by two processes at once, and then moved into place; the run.json files are
  merged in plan order (what the runs one after another would have left: sessions, timings);
- a process keeps the sandbox's verdicts of repeated programs (sartco.program.pool: the probes
  of a board are the same programs for every answer to it);
- the tables of `clem eval` from one pass over the score files (sartco.clem.tooling.evaluate).

The terminal gets one line per task (wall and CPU seconds; a failed task's last error line) and
the totals, and where report.html is; clemcore's logs and progress bars go to RESULTS/main.log.

Before anything is played, the models, the games and the instance file are checked (exit 2, one
line: sartco.clem.tooling.selectors), and a results folder that holds runs already is refused
(exit 2): a suite's tables (clem eval's results.csv beside `sartco report`'s) hold exactly its own
runs, so a second suite goes into a folder of its own. Ctrl-C stops it (one line, exit 130) and
keeps every episode played, in RESULTS/.suite beside the pairs already in place; the same command
again (the plan RESULTS/.suite/plan.json must be the same) plays only what is missing: a pair in
place is kept, a pair half played is completed by `sartco resume` in its stage folder, the rest is
played; the results equal an uninterrupted run's (tests/cli/test_suite_own_models.py). A failed
task leaves the same state: fix what its line names and run the command again. Exit 1 when a task
fails (its last error line and the log's path); else `sartco report`'s status (3: harness errors
or missing episodes, named in SCORES/harness.md and completeness.md).
"""
from __future__ import annotations

import argparse
import contextlib
import json
import os
import re
import shutil
import sys
import time
import traceback
from dataclasses import replace
from pathlib import Path

from sartco.errors import UserError
from sartco.clock import cpu_seconds
from sartco.schedule import CLEM_SETTINGS, LOG, Done, Task, schedule
from sartco.suite_worker import STAGE, run as play_or_prepare

PAPER_SETTINGS = (0.0, 250)   # the paper protocol's -t and -l
# the order in which ready plays start (the longest first), by game; the plan's order is clem eval's
PRIORITY = ("cobot_instruct_paper", "cobot_instruct_published", "cobot_instruct_fresh", "cobot_instruct",
            "cobot_describe_dialogue", "cobot_describe", "cobot_instruct_feedback", "cobot_instruct_ablations")
# the games whose probes draw on the same boards (the same gold programs and board ids): a worker
# keeps to one group, so that its process computes each board's draws once (sartco.clem.core.probes)
BOARDS = {"cobot_instruct": "generated", "cobot_instruct_feedback": "generated", "cobot_describe": "generated",
          "cobot_describe_dialogue": "generated", "cobot_instruct_published": "published",
          "cobot_instruct_fresh": "published"}




def plan(models: list[str], erring: list[str], fresh_seed: int, data: str, settings: tuple = CLEM_SETTINGS,
         batch_size: int = 1) -> list[Task]:
    """make main's steps (scripts/main.sh's order: the plays in the order clem eval adds them);
    `settings` (temperature, max_tokens) for every play but the paper protocol's (PAPER_SETTINGS)."""
    tasks = [Task("import", "prepare", ("sartco", "import", f"{data}/published", "--out", "instances/published", "--quiet")),
             Task("published instances", "prepare", ("instancegen", "--published", "instances/published"), after=("import",)),
             Task("paper instances", "prepare", ("instancegen", "--protocol", "paper"), after=("import",)),
             Task("fresh instances", "prepare", ("instancegen", "--fresh", str(fresh_seed)), after=("import",))]
    needs = {"cobot_instruct_published": ("published instances",), "cobot_instruct_paper": ("paper instances",),
             "cobot_instruct_fresh": ("fresh instances",)}
    pairs: list[tuple[str, str, tuple]] = []
    for model in models:
        pairs += [(g, model, settings) for g in ("cobot_instruct", "cobot_instruct_published", "cobot_describe",
                                                 "cobot_describe_dialogue")]
    pairs += [("cobot_instruct_fresh", model, settings) for model in models]
    if models:
        first = models[0]
        pairs += [("cobot_instruct_paper", first, PAPER_SETTINGS), ("cobot_instruct_ablations", first, settings),
                  ("cobot_instruct_feedback", first, settings)]
    for model in erring:
        pairs += [("cobot_instruct_feedback", model, settings), ("cobot_describe_dialogue", model, settings)]
    tasks += [Task(f"{game} ({model})", "play", game=game, model=model, settings=s, after=needs.get(game, ()), index=n,
                   group=BOARDS.get(game, game), batch_size=batch_size) for n, (game, model, s) in enumerate(pairs)]
    return tasks


def only(tasks: list[Task], games: list[str] | None) -> list[Task]:
    """The plays of `games` (None: all) and the preparations they wait for."""
    if games is None:
        return tasks
    unknown = sorted(set(games) - {t.game for t in tasks if t.kind == "play"})
    if unknown:
        raise UserError(f"-g {' '.join(unknown)}: not in the plan (its games: "
                        f"{', '.join(dict.fromkeys(t.game for t in tasks if t.kind == 'play'))})")
    keep = {t.name for t in tasks if t.kind == "play" and t.game in games}
    for t in reversed(tasks):
        if t.name in keep:
            keep.update(t.after)
    return [t for t in tasks if t.name in keep]


# ---- in the parent -------------------------------------------------------------------------------

def merge_run_files(results: Path, tasks: list[Task]) -> None:
    """clemcore's results/<model>/run.json as the runs one after another would leave it: the first
    run's file, with every game's entry in plan order."""
    merged: dict[str, dict] = {}
    for task in tasks:
        if task.kind != "play":
            continue
        for path in sorted((results / STAGE / str(task.index)).glob("*/run.json")):
            data = json.loads(path.read_text())
            if path.parent.name in merged:
                merged[path.parent.name]["games"].update(data.get("games", {}))
            else:
                merged[path.parent.name] = data
    for model, data in merged.items():
        (results / model).mkdir(parents=True, exist_ok=True)
        with open(results / model / "run.json", "w") as f:
            json.dump(data, f, indent=2)  # clemcore's store_json


def _timed(name: str, step, log: Path) -> tuple[str, int]:
    """step() (-> an exit status; None: 0) with its output in the log; the terminal's line for it."""
    t0, c0 = time.monotonic(), cpu_seconds()
    with open(log, "a") as out, contextlib.redirect_stdout(out), contextlib.redirect_stderr(out):
        try:
            status = step()
            status = 0 if status is None else int(status)
        except Exception:  # noqa: BLE001 - named on the terminal, the traceback in the log
            traceback.print_exc()
            status = 1
    return f"== {name}: exit {status} in {time.monotonic() - t0:.1f} s ({cpu_seconds() - c0:.1f} s CPU)", status


def _tables(results: Path, out: Path, pairs: list[tuple[str, str]]) -> int:
    """clem eval's tables (in a forked process) beside `sartco report`; report's exit status, or 1
    when the tables failed."""
    import multiprocessing

    from sartco import cli
    from sartco.clem.tooling.evaluate import evaluate

    receive, send = multiprocessing.get_context("fork").Pipe(duplex=False)

    def write() -> None:
        evaluate(results, pairs)

    def tables() -> None:
        send.send(_timed("clem eval's tables (raw.csv, results.csv, results.html)", write, results / LOG))

    process = multiprocessing.get_context("fork").Process(target=tables)
    process.start()
    send.close()  # the child's end alone: a child that dies unanswered is an EOF here
    report = _timed("sartco report", lambda: cli.main(["report", "-r", str(results), "--out", str(out)]), results / LOG)
    try:
        line, status = receive.recv()
    except EOFError:
        line, status = "", 1
    process.join()
    line = line or f"== clem eval's tables: ended without a result (exit code {process.exitcode})"
    print(line, flush=True)
    print(report[0], flush=True)
    return report[1] if status == 0 else 1


PLAN = "plan.json"  # RESULTS/.suite/plan.json: the tasks of a suite that has not finished


def _plan_text(tasks: list[Task]) -> str:
    return json.dumps([[t.name, list(t.argv), t.game, t.model, list(t.settings), t.batch_size, t.instances, t.index]
                       for t in tasks], indent=1)


def _again(results: Path, tasks: list[Task]) -> bool:
    """True when RESULTS holds an unfinished suite of these tasks (the command again: play what is
    missing); False for a folder without runs; UserError for a folder with other runs."""
    plan_file = results / STAGE / PLAN
    if plan_file.is_file():
        if plan_file.read_text() != _plan_text(tasks):
            raise UserError(f"{results / STAGE} holds an unfinished suite with other options (its tasks: {plan_file}): "
                            f"run that suite's command again to finish it, or give another -r")
        return True
    held = sorted(p for p in results.glob("*/*") if p.is_dir() and p.parent.name != STAGE)  # <model>/<game>
    if held:
        raise UserError(f"{held[0]} exists: a suite plays into a results folder of its own, so that every table holds "
                        f"exactly its runs (give another -r, or remove the folder: make clean-results RESULTS={results})")
    return False


def configure(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("-r", "--results", type=Path, default=Path("results"), help="the results folder (results)")
    parser.add_argument("--out", type=Path, default=Path("scores"), help="the tables' folder (scores)")
    parser.add_argument("-m", "--models", nargs="+", default=["mock", "rulebased"],
                        help="the models of every game (mock rulebased); the first also plays the paper protocol, "
                             "the ablations and the feedback experiment")
    parser.add_argument("--erring", nargs="*", default=["erring"],
                        help="the models of the repair and dialogue tables only (erring); none: --erring")
    parser.add_argument("--fresh-seed", type=int, default=7, help="the fresh boards' seed (7)")
    parser.add_argument("-g", "--games", nargs="+", default=None,
                        help="only these games of the plan (and the instance files they need); default: all")
    parser.add_argument("-i", "--instances", default=None, metavar="NAME",
                        help="the instance file every game plays (clem run's -i, e.g. instances_smoke; with -g)")
    parser.add_argument("-t", "--temperature", type=float, default=CLEM_SETTINGS[0],
                        help=f"clem run's -t for every play but the paper protocol's ({CLEM_SETTINGS[0]})")
    parser.add_argument("-l", "--max_tokens", type=int, default=CLEM_SETTINGS[1],
                        help=f"clem run's -l for every play but the paper protocol's, which keeps -l "
                             f"{PAPER_SETTINGS[1]} ({CLEM_SETTINGS[1]}; the README recommends 512 for your own model)")
    parser.add_argument("-b", "--batch_size", type=int, default=1, help="clem run's -b for every play (1)")
    parser.add_argument("-j", "--workers", type=int, default=os.cpu_count() or 1, help="processes (the CPUs)")


def run(args: argparse.Namespace) -> int:
    from sartco import settings

    import clemcore.cli  # noqa: F401 - once, before the workers fork

    data = settings.DATA
    if data is None or not (data / "published").is_dir():
        raise UserError(f"{data}/published: no such folder (set SARTCO_DATA to the SARTCo data folder)")
    if args.max_tokens < 1 or args.batch_size < 1:
        raise UserError(f"-l {args.max_tokens} -b {args.batch_size}: both must be at least 1")
    tasks = only(plan(args.models, args.erring, args.fresh_seed, str(data), (args.temperature, args.max_tokens),
                      args.batch_size), args.games)
    if args.instances:
        if not args.games:
            raise UserError("-i names one instance file for every game played: give the games with -g")
        tasks = [replace(t, instances=args.instances, after=()) if t.kind == "play" else t for t in tasks]
        tasks = [t for t in tasks if t.kind == "play"]
    plays = [t for t in tasks if t.kind == "play"]
    if len(plays) < len(tasks) and not Path("games/cobot_instruct").is_dir():
        raise UserError("run it in the checkout's root folder (games/cobot_instruct not found here; it writes "
                        "instance files there)")
    from sartco.clem.tooling.selectors import check_instances, check_models

    check_models(dict.fromkeys(t.model for t in plays))
    for game in dict.fromkeys(t.game for t in plays if args.instances):
        check_instances(game, args.instances)
    results: Path = args.results
    again = _again(results, tasks)
    results.mkdir(parents=True, exist_ok=True)
    (results / STAGE).mkdir(exist_ok=True)
    (results / STAGE / PLAN).write_text(_plan_text(tasks))
    with open(results / LOG, "a" if again else "w") as log:
        log.write("== suite: the same command again: what is missing\n" if again else "")
    start, cpu = time.monotonic(), cpu_seconds()

    def say(d: Done) -> None:
        print(f"== {d.name}: {'done' if d.ok else 'FAILED'} in {d.wall:.1f} s ({d.cpu:.1f} s CPU)"
              + (f": {d.message}" if d.message else ""), flush=True)
        if d.name == "fresh instances":  # how many, and the overlap with the published and seed-42 boards
            lines = re.findall(r"fresh boards \(seed[^\r\n]*", (results / LOG).read_text(errors="replace"))
            print(lines[-1] if lines else "fresh boards: the generator's line is not in the log", flush=True)

    try:
        finished = schedule(play_or_prepare, tasks, max(1, args.workers), results, say, PRIORITY)
    except KeyboardInterrupt:
        raise KeyboardInterrupt(f"the episodes played are kept in {results}; the same command again plays only "
                                f"what is missing") from None
    failed = [d for d in finished if not d.ok] or ([] if len(finished) == len(tasks) else [Done("?", False, 0, 0)])
    if failed:
        print(f"sartco suite: {failed[0].name} failed: {failed[0].message} (full log: {results / LOG}); fix it and "
              f"run the same command again: it plays only what is missing", file=sys.stderr)
        return 1
    merge_run_files(results, tasks)
    try:
        status = _tables(results, args.out, [(t.game, t.model) for t in plays])
    except KeyboardInterrupt:
        raise KeyboardInterrupt("every episode is played; the same command again writes the tables") from None
    shutil.rmtree(results / STAGE)
    print(f"== suite: {len(tasks)} tasks in {time.monotonic() - start:.1f} s wall, {cpu_seconds() - cpu:.1f} s CPU "
          f"on {args.workers} processes", flush=True)
    report = args.out / "report.html"
    if report.is_file():
        print(f"sartco suite: the report to look at: {report.resolve()}", flush=True)
    return status
