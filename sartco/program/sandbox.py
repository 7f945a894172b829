"""The sandbox as an interface: what the games, the paper protocol, the probes, the scorers and
`sartco execute` / `bench-execute` run programs through.

    class Sandbox(Protocol):
        execute(code, rows, cols, limits, *, semantics) -> Execution
        execute_many(programs, rows, cols, limits, *, semantics) -> list[Execution]   # input order
        close() -> None

Every implementation keeps the contract of docs/sandbox.md: one fresh confined process
per program, the board decided by the caller's side from a put log, `harness_error` only for the
sandbox's own failures, no exception out of execute / execute_many. `LocalSandbox` (pool.py) is
this machine's; a remote or cluster sandbox implements the same three methods and is put in use
with `use(sandbox)`, without touching its callers. `current()` is the sandbox in use (the local
one unless `use` said otherwise); the module-level execute / execute_many of sartco.program run
through it.
"""
from __future__ import annotations

import threading
from typing import Iterable, Protocol, runtime_checkable

from sartco.world import DEFAULT_COLS, DEFAULT_ROWS

from .execution import MODULE, Execution, Limits
from .pool import GOLD, LocalSandbox, local


@runtime_checkable
class Sandbox(Protocol):
    def execute(self, code: str, rows: int = DEFAULT_ROWS, cols: int = DEFAULT_COLS, limits: Limits | None = None, *,
                semantics: str = MODULE) -> Execution: ...

    def execute_many(self, programs: Iterable[str], rows: int = DEFAULT_ROWS, cols: int = DEFAULT_COLS,
                     limits: Limits | None = None, *, semantics: str = MODULE) -> list[Execution]: ...

    def close(self) -> None: ...


_in_use: Sandbox | None = None
_lock = threading.Lock()


def current() -> Sandbox:
    """The sandbox in use."""
    return _in_use if _in_use is not None else local()


def use(sandbox: Sandbox | None) -> Sandbox | None:
    """Put `sandbox` in use (None: the local one again); returns the one in use before."""
    global _in_use
    if sandbox is not None and not isinstance(sandbox, Sandbox):
        raise TypeError(f"{type(sandbox).__name__} is not a Sandbox (execute, execute_many, close)")
    with _lock:
        before, _in_use = _in_use, sandbox
    return before


def execute(code: str, rows: int = DEFAULT_ROWS, cols: int = DEFAULT_COLS, limits: Limits | None = None, *,
            semantics: str = MODULE) -> Execution:
    """Run one program on a fresh rows x cols board in the sandbox in use."""
    return current().execute(code, rows, cols, limits, semantics=semantics)


def execute_many(programs: Iterable[str], rows: int = DEFAULT_ROWS, cols: int = DEFAULT_COLS, limits: Limits | None = None, *,
                 workers: int | None = None, cache: bool = True, semantics: str = MODULE,
                 gold: bool = False, answers: list[object] | None = None) -> list[Execution]:
    """Run many programs in the sandbox in use, results in input order. `workers`, `cache`,
    `gold` (the programs are the harness's own reference code, never a model's: pool.GOLD) and
    `answers` (a label per program: the model answer it is part of; one answer's programs may
    share a child: pool.ANSWER) are the local sandbox's (pool.LocalSandbox.execute_many);
    another sandbox ignores them."""
    box = current()
    if isinstance(box, LocalSandbox):
        return box.execute_many(programs, rows, cols, limits, workers=workers, cache=cache, semantics=semantics,
                                mode=GOLD if gold else "code", answers=None if gold else answers)
    return box.execute_many(programs, rows, cols, limits, semantics=semantics)
