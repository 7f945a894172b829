"""Run every program of generated records and compare what it builds with the record's target.

Uses sartco.program.execute (the sandbox) when it is installed; otherwise a plain exec with the
world's init_board/put (the same rules), and says so in `executor()`.
"""
from __future__ import annotations

import json
from pathlib import Path
from typing import Callable

from sartco.world import Board, WorldError, put


def _plain_execute(code: str, rows: int = 8, cols: int = 8):
    """Stand-in until sartco.program lands: (ok, message, cells)."""
    namespace = {"init_board": lambda r=rows, c=cols: Board(r, c), "put": put}
    try:
        exec(compile(code, "<generated>", "exec"), namespace)
    except WorldError as exc:
        return False, f"{exc.code}: {exc.message}", {}
    board = namespace.get("board")
    return True, "", board.cells() if isinstance(board, Board) else {}


def executor() -> tuple[str, Callable[[str, int, int], tuple[bool, str, dict]]]:
    try:
        from sartco.program import execute  # the sandbox, when it exists
    except ImportError:
        return "plain exec (sartco.program.execute not available)", _plain_execute

    def run(code: str, rows: int = 8, cols: int = 8):
        ex = execute(code, rows=rows, cols=cols)
        return ex.ok, f"{ex.error}: {ex.message}", ex.cells

    return "sartco.program.execute", run


def programs(record: dict) -> dict[str, str]:
    return {style: code["total_code"] for style, code in record["code"].items()}


def check_records(records, run=None) -> list[str]:
    run = run or executor()[1]
    problems = []
    for r in records:
        for style, code in programs(r).items():
            ok, message, cells = run(code, r["rows"], r["cols"])
            if not ok:
                problems.append(f"{r['id']} {style}: fails: {message}")
            elif cells != r["target"]:
                problems.append(f"{r['id']} {style}: builds another board than its target")
    return problems


def check_dataset(folder: str | Path) -> list[str]:
    folder = Path(folder)
    manifest = json.loads((folder / "manifest.json").read_text(encoding="utf-8"))
    run = executor()[1]
    problems = []
    for name in manifest["files"]:
        problems += check_records(json.loads((folder / name).read_text(encoding="utf-8")), run)
    return problems
