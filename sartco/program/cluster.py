"""The sandbox on a Ray cluster: `RaySandbox(address)` implements the Sandbox interface
(sandbox.py) by sending chunks of programs to Ray tasks, each of which runs them in the local
sandbox of the node it lands on (pool.LocalSandbox: a fresh confined process per program, the
board replayed by that node's parent side). So the walls stay the rule on every Ray worker; the
driver receives plain Executions, in input order.

    from sartco.program import cluster, use
    use(cluster.RaySandbox("ray://head:10001"))   # or "auto", or None for a local Ray instance

Ray is an optional dependency (the `ray` extra); a missing Ray is one clear error. A task that
fails (a node lost, Ray's own error) is the harness's: its programs get `harness_error` with
Ray's reason, never the program's error. Results equal the local sandbox's
(tests/program/test_conformance.py).
"""
from __future__ import annotations

import os
from collections.abc import Iterable
from dataclasses import astuple
from typing import Any

from sartco.errors import UserError
from sartco.world import DEFAULT_COLS, DEFAULT_ROWS, ErrorCode

from .execution import MODULE, SEMANTICS, Execution, Limits
from .verdict import failed

CHUNK = 256  # programs per Ray task: a task's overhead (~ms) spread over many forks


def _run_chunk(programs: list[str], rows: int, cols: int, limits: list[Any], semantics: str) -> list[tuple[Any, ...]]:
    """On a Ray worker: the chunk in that node's local sandbox, on one template process (a task
    holds one CPU: Ray runs as many tasks side by side as a node has CPUs), as plain tuples."""
    from sartco.program import pool

    return [astuple(ex) for ex in pool.local().execute_many(programs, rows, cols, Limits(*limits), workers=1,
                                                            semantics=semantics)]


class RaySandbox:
    """A Sandbox whose programs run on a Ray cluster (see the module docstring)."""

    def __init__(self, address: str | None = None, chunk: int = CHUNK, **init: Any):
        try:
            import ray
        except ImportError:
            raise UserError("the Ray sandbox needs Ray: pip install 'sartco-bench[ray]'") from None
        self.ray = ray
        self.chunk = max(1, chunk)
        if not ray.is_initialized():
            init.setdefault("runtime_env", {"env_vars": {"SARTCO_DATA": os.environ.get("SARTCO_DATA", "")}}
                            if os.environ.get("SARTCO_DATA") else None)
            ray.init(address=address, ignore_reinit_error=True, log_to_driver=False, **init)
        self._remote = ray.remote(num_cpus=1, max_retries=0)(_run_chunk)

    def execute_many(self, programs: Iterable[str], rows: int = DEFAULT_ROWS, cols: int = DEFAULT_COLS, limits: Limits | None = None,
                     *, semantics: str = MODULE) -> list[Execution]:
        if semantics not in SEMANTICS:
            raise ValueError(f"unknown semantics {semantics!r}; expected one of {', '.join(SEMANTICS)}")
        programs = list(programs)
        limits = limits or Limits()
        chunks = [programs[k:k + self.chunk] for k in range(0, len(programs), self.chunk)]
        refs = [self._remote.remote(chunk, rows, cols, limits.as_list(), semantics) for chunk in chunks]
        results: list[Execution] = []
        for chunk, ref in zip(chunks, refs):
            try:
                rows_: list[tuple[Any, ...]] = self.ray.get(ref)
                results.extend(Execution(ok, None if code is None else ErrorCode(code), message, cells, puts)
                               for ok, code, message, cells, puts in rows_)
            except Exception as exc:  # Ray's failure, never the program's
                reason = f"sandbox failure on the Ray cluster: {type(exc).__name__}: {str(exc)[:200]}"
                results.extend(failed(ErrorCode.HARNESS_ERROR, reason) for _ in chunk)
        return results

    def execute(self, code: str, rows: int = DEFAULT_ROWS, cols: int = DEFAULT_COLS, limits: Limits | None = None, *,
                semantics: str = MODULE) -> Execution:
        return self.execute_many([code], rows, cols, limits, semantics=semantics)[0]

    def close(self) -> None:
        """Leaves the cluster running; shuts down a Ray instance this process started."""
        if self.ray.is_initialized():
            self.ray.shutdown()
