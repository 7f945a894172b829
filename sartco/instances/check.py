"""Run every program of generated records in the sandbox (sartco.program.execute_many) and compare
what it builds with the record's target."""
from __future__ import annotations

from pathlib import Path

from sartco.program import execute_many

from .generate import load_dataset


def check_records(records) -> list[str]:
    """One line per program that fails or builds another board than its record's target, in
    record and code style order; the programs run in one batch per board size."""
    records = list(records)
    jobs: dict[tuple[int, int], list[tuple[int, str, str]]] = {}
    for i, r in enumerate(records):
        for style, code in r["code"].items():
            jobs.setdefault((r["rows"], r["cols"]), []).append((i, style, code["total_code"]))
    results = {}
    for (rows, cols), group in jobs.items():
        for (i, style, _), ex in zip(group, execute_many([code for _, _, code in group], rows, cols)):
            results[(i, style)] = ex
    problems = []
    for i, r in enumerate(records):
        for style in r["code"]:
            ex = results[(i, style)]
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
