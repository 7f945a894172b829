"""The game core's one door into the sandbox: every program a build (sartco.clem.core.building)
or a function probe (sartco.clem.core.probes) runs goes through `run_many`, one batch of programs
on fresh boards of one size, in the sandbox in use (sartco.program.current(): the local one, or
whatever `sartco.program.use` put in use, e.g. sartco.program.cluster.RaySandbox), and every
verdict through `judge`.

`together` runs the programs of many answers ahead, each answer's (its build and its function
probes) in one confined child, and within its block `run_many` hands out their Executions
instead of running the same programs again: the reward API (sartco.reward.core) forks one
process per answer where it forked two.
"""
from __future__ import annotations

from collections.abc import Iterable, Iterator
from contextlib import contextmanager
from contextvars import ContextVar

from sartco.program import Execution, current, execute_many, judge
from sartco.world import ErrorCode

__all__ = ["run_many", "judge", "restart", "together"]

# the Executions `together` ran, by (program, rows, cols): this context's only (a thread of its own,
# such as the game's work ahead, never sees them)
_ran: ContextVar[dict[tuple[str, int, int], Execution] | None] = ContextVar("sartco_ran_together", default=None)


def run_many(programs: list[str], rows: int, cols: int, *, gold: bool = False,
             answers: list[object] | None = None) -> list[Execution]:
    """Each program on its own fresh rows x cols board, results in input order. `gold`: the
    programs are an instance's gold code at the probes' candidate arguments, never a model's (the
    local sandbox runs a batch of them in one confined child: sartco.program.child.template, mode "gold").
    `answers`: a label per program, the model answer it is part of (the local sandbox runs one
    answer's programs in one confined child, never with another answer's: mode "answer").
    Within `together`, a model's program that it ran is not run again (unless the sandbox failed
    it: harness_error)."""
    ran = None if gold else _ran.get()
    if ran is None:
        return execute_many(programs, rows, cols, gold=gold, answers=answers) if programs else []
    out = [ran.get((program, rows, cols)) for program in programs]
    rest = [i for i, ex in enumerate(out) if ex is None or ex.error == ErrorCode.HARNESS_ERROR]
    if rest:
        labels = None if answers is None else [answers[i] for i in rest]
        for i, ex in zip(rest, execute_many([programs[i] for i in rest], rows, cols, answers=labels)):
            out[i] = ex
    return [ex if ex is not None else Execution(False, ErrorCode.HARNESS_ERROR, "the sandbox returned no result")
            for ex in out]


@contextmanager
def together(answers: Iterable[tuple[list[str], int, int]]) -> Iterator[None]:
    """Run the programs of each answer, (programs, rows, cols), in one confined child of its own
    (one sandbox call per board size); within the block, `run_many` takes the Execution of each
    of those programs on that board size from here (a harness_error runs again there). The
    Executions are those of a child per program (sartco.program.child.batch)."""
    batches: dict[tuple[int, int], tuple[list[str], list[object]]] = {}
    for label, (programs, rows, cols) in enumerate(answers):
        batch = batches.setdefault((rows, cols), ([], []))
        batch[0].extend(programs)
        batch[1].extend([label] * len(programs))
    ran: dict[tuple[str, int, int], Execution] = {}
    for (rows, cols), (programs, labels) in batches.items():
        ran.update(((p, rows, cols), ex) for p, ex in zip(programs, run_many(programs, rows, cols, answers=labels)))
    token = _ran.set(ran)
    try:
        yield
    finally:
        _ran.reset(token)


def restart() -> None:
    """Close the sandbox in use (a local one starts fresh templates on the next call)."""
    current().close()
