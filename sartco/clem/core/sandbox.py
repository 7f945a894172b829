"""The game core's one door into the sandbox: every program a build (sartco.clem.core.building)
or a function probe (sartco.clem.core.probes) runs goes through `run_many`, one batch of programs
on fresh boards of one size, in the sandbox in use (sartco.program.current(): the local one, or
whatever `sartco.program.use` put in use, e.g. sartco.program.cluster.RaySandbox), and every
verdict through `judge`.
"""
from __future__ import annotations

from sartco.program import Execution, current, execute_many, judge

__all__ = ["run_many", "judge", "restart"]


def run_many(programs: list[str], rows: int, cols: int, *, gold: bool = False,
             answers: list[object] | None = None) -> list[Execution]:
    """Each program on its own fresh rows x cols board, results in input order. `gold`: the
    programs are an instance's gold code at the probes' candidate arguments, never a model's (the
    local sandbox runs a batch of them in one confined child: sartco.program.child.template, mode "gold").
    `answers`: a label per program, the model answer it is part of (the local sandbox runs one
    answer's programs in one confined child, never with another answer's: mode "answer")."""
    return execute_many(programs, rows, cols, gold=gold, answers=answers) if programs else []


def restart() -> None:
    """Close the sandbox in use (a local one starts fresh templates on the next call)."""
    current().close()
