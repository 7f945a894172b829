"""The gold code of board records run in the sandbox (sartco.program.execute_many), in batches:
what `sartco import` takes as a record's target and what `sartco generate --check` compares with it."""
from __future__ import annotations

from pathlib import Path

from sartco.dataset import BoardRecord
from sartco.program import Execution, execute_many

from .storage import load_dataset


def run_gold_code(records: list[BoardRecord]) -> list[dict[str, Execution]]:
    """Per record, the execution of each code style's total_code (in the record's style order); the
    programs run in one batch per board size. They are a dataset's gold code, never a model's, so
    the local sandbox may run a chunk of them in one confined child (its mode "gold": the same
    verdicts as a child per program, sartco.program.child.batch)."""
    jobs: dict[tuple[int, int], list[tuple[int, str, str]]] = {}
    for i, r in enumerate(records):
        for style, code in r["code"].items():
            jobs.setdefault((r["rows"], r["cols"]), []).append((i, style, code["total_code"]))
    results: list[dict[str, Execution]] = [{} for _ in records]
    for (rows, cols), group in jobs.items():
        for (i, style, _), ex in zip(group, execute_many([code for _, _, code in group], rows, cols, gold=True)):
            results[i][style] = ex
    return results


def check_records(records) -> list[str]:
    """One line per program that fails or builds another board than its record's target, in
    record and code style order."""
    records = list(records)
    problems = []
    for r, runs in zip(records, run_gold_code(records)):
        for style, ex in runs.items():
            if not ex.ok:
                problems.append(f"{r['id']} {style}: fails: {ex.error}: {ex.message}")
            elif ex.cells != r["target"]:
                problems.append(f"{r['id']} {style}: builds another board than its target")
    return problems


def check_dataset(folder: str | Path) -> list[str]:
    manifest, files = load_dataset(folder)
    problems = []
    for name in manifest["files"]:
        problems += check_records(files[name])
    return problems
