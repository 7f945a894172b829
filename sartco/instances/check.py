"""Run every program of generated records in the sandbox (sartco.program.execute) and compare
what it builds with the record's target."""
from __future__ import annotations

import json
from pathlib import Path

from sartco.program import execute


def check_records(records) -> list[str]:
    problems = []
    for r in records:
        for style, code in r["code"].items():
            ex = execute(code["total_code"], rows=r["rows"], cols=r["cols"])
            if not ex.ok:
                problems.append(f"{r['id']} {style}: fails: {ex.error}: {ex.message}")
            elif ex.cells != r["target"]:
                problems.append(f"{r['id']} {style}: builds another board than its target")
    return problems


def check_dataset(folder: str | Path) -> list[str]:
    folder = Path(folder)
    manifest = json.loads((folder / "manifest.json").read_text(encoding="utf-8"))
    problems = []
    for name in manifest["files"]:
        problems += check_records(json.loads((folder / name).read_text(encoding="utf-8")))
    return problems
