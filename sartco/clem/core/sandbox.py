"""The game core's one door into the sandbox: every program a build (sartco.clem.core.building)
or a function probe (sartco.clem.core.probes) runs goes through `run_many`, one batch of programs
on fresh boards of one size, and every verdict through `judge`.

sartco.program's calls are named here once: when the sandbox becomes an object with
execute / execute_many / close, `run_many` (execute_many) and `restart` (close) are the lines to change.
"""
from __future__ import annotations

from sartco.program import Execution, execute_many, judge, shutdown

__all__ = ["run_many", "judge", "restart"]


def run_many(programs: list[str], rows: int, cols: int) -> list[Execution]:
    """Each program on its own fresh rows x cols board, results in input order."""
    return execute_many(programs, rows, cols) if programs else []


def restart() -> None:
    """End the sandbox's worker processes (their caches with them); the next call starts fresh ones."""
    shutdown()
