"""harness.md / harness.csv of `sartco report`: the episodes in which the harness failed, not the
model (Error Category harness_error: the sandbox could not run the program or gave no usable
answer, or the game master or the scorer raised; sartco.clem.core.harness), per model and game.

Such an episode is left out of every other table's scores (it is no measurement of the model)
and counted here; `sartco report` then exits with HARNESS_STATUS, so that `make main` fails, and
names the `sartco resume` that plays them again.
"""
from __future__ import annotations

import sys
from collections import defaultdict
from collections.abc import Mapping
from pathlib import Path
from typing import Any

from sartco.clem.core.outcomes import NO_ANSWER
from sartco.world import ErrorCode

from .files import markdown_table, write_csv

HARNESS_STATUS = 3  # exit status of `sartco report` when any episode is a harness error
HEADER = ["model", "game", "episodes", "harness_errors", "first_reason"]


def is_harness(episode: Mapping[str, Any]) -> bool:
    return episode["category"] == ErrorCode.HARNESS_ERROR


def rows(episodes: list[dict]) -> list[dict]:
    """One row per model and game: its episodes, how many were harness errors, the first reason."""
    groups: dict[tuple, list] = defaultdict(list)
    for e in episodes:
        groups[(e["model"], e["game"])].append(e)
    out = []
    for (model, game), group in sorted(groups.items()):
        faults = [e for e in group if is_harness(e)]
        out.append({"model": model, "game": game, "episodes": len(group), "harness_errors": len(faults),
                    "first_reason": faults[0]["harness_reason"] if faults else ""})
    return out


def fixes(results: Path, episodes: list[dict]) -> str:
    """What to do about the harness errors: the `sartco resume` of each model and game whose model
    server gave no answer (it plays those episodes again), else the reasons to read."""
    faults = [e for e in episodes if is_harness(e)]
    unanswered = sorted({(e["model"], e["game"]) for e in faults if str(e["harness_reason"]).startswith(NO_ANSWER)})
    todo = [f"`sartco resume -r {results} -g {game} -m {model}` plays the episodes the model server did not "
            f"answer again" for model, game in unanswered]
    if any(not str(e["harness_reason"]).startswith(NO_ANSWER) for e in faults):
        todo.append("for the others fix the cause their reason names, remove their episode folders and run "
                    "`sartco resume` the same way")
    return "; ".join(todo)


def write(episodes: list[dict], out: Path, results: Path) -> tuple[list[str], int]:
    """Write harness.md and harness.csv; return the files and the number of harness errors (a line
    on stderr names them, and the `sartco resume` that plays them again, when there are any).
    results: the results folder the episodes are from."""
    table = rows(episodes)
    total = sum(r["harness_errors"] for r in table)
    write_csv(out / "harness.csv", HEADER, table)
    md = ("# Harness errors (episodes the harness failed, not the model; left out of every score)\n\n"
          + markdown_table(["model", "game", "episodes", "harness errors", "first reason"],
                           [[r[h] for h in HEADER] for r in table]))
    if total:
        md += f"\nTo do: {fixes(results, episodes)}.\n"
    (out / "harness.md").write_text(md, encoding="utf-8")
    if total:
        print(f"sartco report: {total} harness error(s) (the harness failed, not the model; left out of the scores, "
              f"see {out / 'harness.md'}); {fixes(results, episodes)} "
              f"(exit status {HARNESS_STATUS})", file=sys.stderr)
    return ["harness.md", "harness.csv"], total
