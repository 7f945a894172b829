"""`sartco bench-reward`: rewards per second of sartco.reward.score on this machine.

The answers: for every episode of the instance files (default: cobot_instruct's instances.json
and, when it was made, instances_published.json: the published boards and gold), the gold answer
(what `-m mock` says: the gold code in the task's style, fenced) and the erring player's
(`-m erring`: the rule-based follower with seeded slips). Single-turn episodes (the function and
repetition cells: one completion each, what a GRPO step scores) are timed apart from multi-turn
ones (first_order: one answer per instruction, joined into one program as the game does).

Each set is scored in batches of --batch pairs (a GRPO step's B x G completions), with the
function probes (what the game does: K more programs per optimal_function or repetition answer)
and without them (ES, cell F1, category and puts only); the sandbox's workers are restarted
before each run (no verdict cached from the run before) and started before the clock; the best
of --repeat runs is printed. The gold probe draws of every probed episode are computed once
before (they depend on the episode alone and are kept by `Episodes`) and timed apart.

The CPU of each run is this process's and its sandbox's (sartco.program.costs); the last line
gives the single-turn answers' CPU per reward in its parts: this process (reading the answers,
compiling the programs, deciding the boards, scoring), the templates' own work, their zygotes'
(a fork per answer) and the programs' processes.
"""
from __future__ import annotations

import os
import time
from pathlib import Path

from sartco.clock import cpu_seconds
from sartco.clem.core.probes import probed
from sartco.clem.core.sandbox import restart, run_many
from sartco.clem.players.answers import instruct_answers
from sartco.errors import UserError
from sartco.program.costs import templates_roles
from sartco.protocols import INSTANCE_FILES, INSTANCES_DIR

from .core import Episodes, score

PLAYERS = {"gold": "mock", "erring": "erring"}  # label -> the built-in player whose answers are scored
ROLES = ("this process", "templates", "zygotes", "programs' processes")  # _cpu's parts
TARGETS = (500, 2000)  # rewards/s wanted for single-turn answers on two cores, with probes and without (issue 46)


def configure(parser) -> None:
    parser.add_argument("--instances", type=Path, action="append", default=None, metavar="FILE",
                        help="cobot_instruct instance file (repeatable; default: in/instances.json and "
                             "in/instances_published.json when present)")
    parser.add_argument("--batch", type=int, default=512, help="pairs per score() call (default %(default)s)")
    parser.add_argument("--repeat", type=int, default=3, help="runs per set; the best is printed (default %(default)s)")
    parser.add_argument("--limit", type=int, default=None, metavar="N",
                        help="only the first N episodes of each experiment (a quick run)")


def instance_files(given: list[Path] | None) -> list[Path]:
    if given:
        missing = [str(p) for p in given if not Path(p).is_file()]
        if missing:
            raise UserError(f"no such instance file: {', '.join(missing)}")
        return list(given)
    present = [INSTANCES_DIR / name for name in INSTANCE_FILES if (INSTANCES_DIR / name).is_file()]
    if not present:
        raise UserError(f"{INSTANCES_DIR}: no {INSTANCE_FILES[0]} (give --instances FILE)")
    return present


def answer_sets(episodes: Episodes) -> dict[tuple[str, str], list[tuple[str, object]]]:
    """(player label, "single-turn" | "multi-turn") -> (episode id, completion) pairs."""
    sets: dict[tuple[str, str], list] = {}
    for key, instance in episodes.items():
        turns = len(instance["turns"])
        kind = "single-turn" if turns == 1 else "multi-turn"
        for label, player in PLAYERS.items():
            source = instruct_answers(player, instance)
            answers = [source.answer(t) for t in range(turns)]
            sets.setdefault((label, kind), []).append((key, answers[0] if turns == 1 else answers))
    return sets


def best_rate(pairs: list, episodes: Episodes, *, batch: int, repeat: int, probes: bool) -> tuple[float, list[float]]:
    """(rewards per wall second, CPU ms per reward of this process, its templates, their zygotes
    and the programs' processes (costs.roles)) of the fastest of `repeat` runs, each on freshly
    started workers (their start and end are not counted)."""
    best = (float("inf"), [0.0] * 4)
    for _ in range(repeat):
        started()
        cpu = _cpu()
        start = time.perf_counter()
        for i in range(0, len(pairs), batch):
            score(pairs[i:i + batch], episodes, probes=probes)
        elapsed = time.perf_counter() - start
        best = min(best, (elapsed, [1000 * (b - a) / len(pairs) for a, b in zip(cpu, _cpu())]))
    restart()
    return len(pairs) / best[0], best[1]


def _cpu() -> list[float]:
    return [cpu_seconds(), *templates_roles()]


def started() -> None:
    """Fresh workers, started (before the clock)."""
    restart()
    run_many([f"x = {i}" for i in range(64)], 8, 8)


def run(args) -> int:
    if args.batch < 1 or args.repeat < 1:
        raise UserError("--batch and --repeat must be at least 1")
    files = instance_files(args.instances)
    episodes = Episodes.from_files(files)
    if args.limit is not None:
        seen: dict[str, int] = {}
        keep = {}
        for key, instance in episodes.items():  # ids start with the experiment's name
            experiment = key.split("/", 1)[0]
            seen[experiment] = seen.get(experiment, 0) + 1
            if seen[experiment] <= args.limit:
                keep[key] = instance
        episodes = Episodes(keep)
    print(f"sartco bench-reward: {len(episodes)} episodes of {', '.join(str(f) for f in files)}; "
          f"{os.cpu_count()} CPUs; batches of {args.batch}; best of {args.repeat}")
    start = time.perf_counter()
    drawn = [key for key, instance in episodes.items() if probed(instance)]
    for key in drawn:
        episodes.gold_draws(key)
    print(f"gold probe draws (once per episode, kept): {len(drawn)} episodes in {time.perf_counter() - start:.1f} s")
    print(f"{'answers':<22} {'pairs':>6}   rewards/s (CPU ms per reward): with probes, without")
    single = []
    for (label, kind), pairs in sorted(answer_sets(episodes).items(), key=lambda item: (item[0][1] != "single-turn", item[0])):
        runs = [best_rate(pairs, episodes, batch=args.batch, repeat=args.repeat, probes=p)
                for p in (True, False)]
        shown = ",  ".join(f"{rate:>7,.0f} ({sum(cpu):.2f})" for rate, cpu in runs)
        print(f"{label + ', ' + kind:<22} {len(pairs):>6}   {shown}")
        if kind == "single-turn":
            single.append((len(pairs), runs))
    if single:
        n = sum(count for count, _ in single)
        rates = [n / sum(count / runs[i][0] for count, runs in single) for i in (0, 1)]  # pairs over total time
        parts = [[sum(count * runs[i][1][k] for count, runs in single) / n for k in range(4)] for i in (0, 1)]
        cpus = os.cpu_count() or 1
        most = [cpus * 1e3 / sum(parts[i]) for i in (0, 1)]
        print(f"single-turn answers, all: {rates[0]:,.0f} rewards/s with probes, {rates[1]:,.0f} without "
              f"(targets {TARGETS[0]:,} and {TARGETS[1]:,} on two cores; load average {os.getloadavg()[0]:.1f} now)")
        print(f"  at the CPU these rewards took, {cpus} CPUs fully used would give at most {most[0]:,.0f} with "
              f"probes, {most[1]:,.0f} without")
        print("  that CPU, ms per reward with probes / without: " + ", ".join(
            f"{name} {parts[0][k]:.2f} / {parts[1][k]:.2f}" for k, name in enumerate(ROLES)))
    return 0
