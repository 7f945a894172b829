"""Persistent worker processes, batching, restarts; execute() and execute_many().

`dispatch` sends items in chunks (a header line + one line per item) to up to `workers` worker
processes (default: min(2, CPUs)), each driven by one thread that reads the answers while a
second one writes the chunks (so a worker finds its next chunk waiting). Items with the same key
(the source) go to the same worker, so its code cache sees all repeats; without keys the shares
are balanced by size. `execute_many` sends programs (mode "code"), `sartco execute` sends its raw
input lines (mode "line": the worker parses, runs, compares and writes the finished output line,
so the parent only routes bytes); `execute` is a batch of one. What the model did not cause (no
worker could start, a garbled or missing answer, a failure of the pool itself) is `harness_error`. Each worker is driven through
driver.Worker (hard wall time, kills, restarts, the verdicts of dead workers). Nothing raises
out of `execute`/`execute_many`.

Workers are started lazily, survive between calls (the common case pays no start-up) and are
killed at exit or by `shutdown()`. After a fork the child starts its own.
"""
from __future__ import annotations

import atexit
import json
import os
import threading

from sartco.world import DEFAULT_COLS, DEFAULT_ROWS, Board, ErrorCode, WorldError

from .driver import Worker, failed
from .execution import MODULE, SEMANTICS, Execution, Limits, not_a_str

E = ErrorCode
BATCH = 32  # a call with fewer items than this uses one worker


def _decode(line: bytes) -> Execution:
    try:
        ok, code, message, cells, puts = json.loads(line)
        if type(ok) is not bool or type(message) is not str or type(cells) is not dict or type(puts) is not int:
            raise ValueError("unexpected field types")
        return Execution(ok, None if code is None else ErrorCode(code), message, cells, puts)
    except (ValueError, TypeError) as exc:
        return failed(E.HARNESS_ERROR, f"garbled answer from the sandbox worker: {exc}")


_workers: list[Worker] = []
_pool_pid = None
_pool_lock = threading.Lock()


def _get_workers(n: int) -> list[Worker]:
    global _pool_pid, _workers
    with _pool_lock:
        if _pool_pid != os.getpid():  # a forked child must not share its parent's workers
            _workers, _pool_pid = [], os.getpid()
        while len(_workers) < n:
            _workers.append(Worker())
        return _workers[:n]


def shutdown() -> None:
    """Kill and reap every worker of this process (they restart on the next call)."""
    with _pool_lock:
        if _pool_pid == os.getpid():
            for worker in _workers:
                with worker.lock:
                    worker.kill()


atexit.register(shutdown)


def default_workers() -> int:
    return max(1, min(2, os.cpu_count() or 1))


def dispatch(mode: str, items: list[bytes], keys: list | None, rows: int, cols: int, limits: Limits,
             workers: int | None = None, cache: bool = True, semantics: str = MODULE) -> list:
    """Run items on the workers; answers in input order (see driver.Worker.run). Items with equal
    keys go to the same worker, so its code cache sees every repeat of a source; without keys
    (no cache to serve) the shares are balanced by size, since a program's cost grows with its
    text (parsing and compiling are most of it), so that no worker waits idle for the other."""
    results: list = [None] * len(items)
    n = max(1, min(workers or default_workers(), -(-len(items) // BATCH)))
    shares: list[list[int]] = [[] for _ in range(n)]
    if keys is None:
        load = [0] * n
        for i, item in enumerate(items):
            w = load.index(min(load))
            shares[w].append(i)
            load[w] += len(item)
    else:
        for i, key in enumerate(keys):
            shares[hash(key) % n].append(i)

    def drive(worker: Worker, share: list[int]):
        with worker.lock:
            for i, answer in zip(share, worker.run(mode, [items[i] for i in share], rows, cols, limits, cache,
                                                          semantics)):
                results[i] = answer

    pool = _get_workers(n)
    if n == 1:
        drive(pool[0], shares[0])
    else:
        threads = [threading.Thread(target=drive, args=(w, sh), daemon=True) for w, sh in zip(pool, shares)]
        for t in threads:
            t.start()
        for t in threads:
            t.join()
    return results


def execute_many(programs, rows: int = DEFAULT_ROWS, cols: int = DEFAULT_COLS, limits: Limits | None = None, *,
                 workers: int | None = None, cache: bool = True, semantics: str = MODULE) -> list[Execution]:
    """Run many programs, each on its own fresh board; results in input order. `semantics`:
    MODULE (a script's namespace) or PAPER (the authors' exec, see namespaces.py)."""
    if semantics not in SEMANTICS:
        raise ValueError(f"unknown semantics {semantics!r}; expected one of {', '.join(SEMANTICS)}")
    try:
        programs = list(programs)
        limits = limits or Limits()
        try:
            Board(rows, cols)
        except WorldError as exc:
            return [failed(exc.code, exc.message) for _ in programs]
        results: list = [None] * len(programs)
        todo = []
        for i, p in enumerate(programs):
            if type(p) is str:
                todo.append(i)
            else:
                results[i] = failed(E.TYPE_ERROR, not_a_str(p))
        items = [json.dumps(programs[i]).encode() for i in todo]
        keys = [programs[i] for i in todo] if cache else None
        answers = dispatch("code", items, keys, rows, cols, limits, workers, cache, semantics)
        for i, answer in zip(todo, answers):
            results[i] = _decode(answer) if type(answer) is bytes else answer
        return [r if r is not None else failed(E.HARNESS_ERROR, "the sandbox returned no result") for r in results]
    except Exception as exc:  # the caller must never see an exception
        n = len(programs) if isinstance(programs, list) else 1
        return [failed(E.HARNESS_ERROR, f"sandbox failure: {type(exc).__name__}: {exc}") for _ in range(n)]


def execute(code: str, rows: int = DEFAULT_ROWS, cols: int = DEFAULT_COLS, limits: Limits | None = None, *,
            semantics: str = MODULE) -> Execution:
    """Run one program on a fresh rows x cols board (see the package docstring)."""
    return execute_many([code], rows, cols, limits, workers=1, semantics=semantics)[0]
