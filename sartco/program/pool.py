"""The local sandbox: template processes on this machine, each forking one confined child per
program (child/template.py), batches split over them; and the module-level execute() / execute_many()
of the sandbox in use (sandbox.py).

`execute_many` compiles a big call in parts (feed.py: FIRST programs, then twice as many each
time) and puts each in the call's `Feed` once it is compiled; `dispatch` (on a daemon thread while
the parent compiles) runs the feed on up to `workers` templates (default: min(2, CPUs)), each
driven by one thread that reads the answers while a second one writes the chunks (a header line
+ one line per program) and takes the next programs from the feed whenever the template runs low
(handle.py): a template finds its next chunk waiting, and no template waits for another.
With `cache` (the default) equal sources run once and share their Execution, within a call
and across calls (a memo of the last MEMO verdicts per sandbox, keyed by the source, the board's
size, the limits, the semantics and the mode): the same program gives the same board everywhere.
The probes run the gold function at the same arguments for every answer to a board, and a gold
answer's probes are those very programs. Only verdicts that the program alone decides are kept:
never `timeout`, `resource_limit` (they depend on the machine's load) or `harness_error`. What the program did not cause (no template
could start or confine, a garbled answer, a failure of the pool itself) is `harness_error`.
Nothing raises out of `execute`/`execute_many`.

Templates are started lazily, survive between calls (the common case pays no start-up) and are
killed at exit or by `close()`. After a fork the child starts its own.
"""
from __future__ import annotations

import atexit
import json
import marshal
import os
import threading
from collections import OrderedDict
from functools import partial

from sartco.world import DEFAULT_COLS, DEFAULT_ROWS, Board, ErrorCode, WorldError

from . import compiled
from .feed import Background, Feed, parts
from .handle import TemplateHandle
from .execution import MODULE, SEMANTICS, Execution, Limits, not_a_str
from .verdict import failed

BATCH = 32  # a call with fewer items than this uses one template
GOLD = "gold"  # execute_many's mode for the harness's own reference programs (child/template.py)
ANSWER = "answer"  # execute_many's mode for the programs of model answers, each answer's in one child (groups)
MEMO = 50_000  # verdicts a LocalSandbox keeps for repeated programs (a few KB each)
TRANSIENT = frozenset({ErrorCode.TIMEOUT, ErrorCode.RESOURCE_LIMIT, ErrorCode.HARNESS_ERROR})
MemoKey = tuple[str, int, int, Limits, str, str]  # source, rows, cols, limits, semantics, mode


def default_workers() -> int:
    return max(1, min(2, os.cpu_count() or 1))


def pinned(n: int) -> list[int | None]:
    """The CPU of each of a call's n templates: one of its own (and of its zygote and children)
    when they are as many as this process's CPUs, else any (None: the scheduler's choice). A
    template's chain (it, its zygote, the child) runs one process at a time, and left to the
    scheduler two chains shared a core at times while the other idled (docs/sandbox.md). Other
    processes' templates are not looked at: each process's big calls spread over every CPU alike."""
    cpus = sorted(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else []
    return list(cpus) if len(cpus) == n else [None] * n


class LocalSandbox:
    """The Sandbox of this machine (sandbox.py): forked, confined children of local templates.
    `breach=True` only for the assume-breach tests (child/template.py's mode "breach")."""

    def __init__(self, workers: int | None = None, breach: bool = False):
        self.workers, self.breach = workers, breach
        self._templates: list[TemplateHandle] = []
        self._pid = os.getpid()
        self._lock = threading.Lock()
        # the kept verdicts, cells marshalled: each recall makes its own copy (a caller may change
        # it), and this copy costs a tenth of copy.deepcopy's
        self._memo: OrderedDict[MemoKey, tuple[bool, ErrorCode | None, str, bytes, int]] = OrderedDict()
        self._memo_lock = threading.Lock()

    def _recall(self, key: MemoKey) -> Execution | None:
        with self._memo_lock:
            kept = self._memo.get(key)
            if kept is not None:
                self._memo.move_to_end(key)
        if kept is None:
            return None
        ok, error, message, cells, puts = kept
        return Execution(ok, error, message, marshal.loads(cells), puts)

    def _remember(self, key: MemoKey, ex: Execution) -> None:
        if ex.error in TRANSIENT:
            return
        kept = (ex.ok, ex.error, ex.message, marshal.dumps(ex.cells), ex.puts)
        with self._memo_lock:
            self._memo[key] = kept
            while len(self._memo) > MEMO:
                self._memo.popitem(last=False)

    def templates(self, n: int) -> list[TemplateHandle]:
        """n templates, idle ones first: a batch of another thread may hold one (a game's gold
        draws made ahead, sartco.clem.core.probes). A template starts at its first program."""
        with self._lock:
            if self._pid != os.getpid():  # a forked child must not share its parent's templates
                self._templates, self._pid = [], os.getpid()
            while len(self._templates) < max(n, self.workers or default_workers()):
                self._templates.append(TemplateHandle(self.breach))
            return sorted(self._templates, key=lambda t: t.lock.locked())[:n]

    def pids(self) -> list[int]:
        """The process ids of this sandbox's running templates."""
        with self._lock:
            return [t.pid for t in self._templates if t.pid is not None]

    def close(self) -> None:
        """Kill and reap every template of this process (they restart on the next call) and forget
        the verdicts kept for repeated programs (a benchmark's next run starts cold)."""
        with self._memo_lock:
            self._memo.clear()
        with self._lock:
            if self._pid == os.getpid():
                for template in self._templates:
                    with template.lock:
                        template.kill()

    def dispatch(self, feed: Feed, items: dict[int, bytes], rows: int, cols: int, limits: Limits,
                 semantics: str = MODULE, mode: str = "code") -> dict[int, Execution]:
        """Run the programs of `feed` (items: compiled.prepare's, by index) on feed.takers
        templates, each taking its next ones from the feed as it runs low; Executions by index."""
        results: dict[int, Execution] = {}

        def drive(template: TemplateHandle, cpu: int | None):
            with template.lock:
                template.cpu = cpu
                taken: list[int] = []

                def more() -> tuple[list[bytes], frozenset[int]]:
                    batch = feed.take()
                    taken.extend(batch)
                    return [items[i] for i in batch], feed.starts(batch)

                first, starts = more()
                if first:
                    answers = template.run(first, rows, cols, limits, semantics, mode, starts=starts,
                                           more=None if feed.done() else more)  # (a small call: no writer thread)
                    results.update(zip(taken, answers))

        templates = self.templates(feed.takers)
        if len(templates) == 1:
            drive(templates[0], None)
        else:
            threads = [threading.Thread(target=drive, args=(t, cpu), daemon=True)
                       for t, cpu in zip(templates, pinned(len(templates)))]
            for t in threads:
                t.start()
            for t in threads:
                t.join()
        return results

    def execute_many(self, programs, rows: int = DEFAULT_ROWS, cols: int = DEFAULT_COLS, limits: Limits | None = None,
                     *, workers: int | None = None, cache: bool = True, semantics: str = MODULE,
                     mode: str = "code", answers: list[object] | None = None) -> list[Execution]:
        """Run many programs, each in its own confined process on its own fresh board; results in
        input order. `semantics`: MODULE (a script's namespace) or PAPER (the authors' exec, see
        namespaces.py). `mode` GOLD: the harness's own reference programs (an instance's gold
        code, never a model's), which may share a child per chunk (child/template.py, mode "gold").
        `answers` (one label per program: the model answer it belongs to, e.g. the K probes of
        one answer): the programs of one answer may share a child, never with another answer's
        (mode ANSWER, child/batch.py). The verdicts of both are those of mode "code" and are kept
        as such."""
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
            if answers is not None and mode == "code":
                mode = ANSWER
            kept = "code" if mode in (GOLD, ANSWER) else mode  # the memo's mode: theirs are code verdicts
            first: dict[str, int] = {}  # source -> the index of the item that runs it (cache)
            todo, copies = [], []
            for i, p in enumerate(programs):
                if type(p) is not str:
                    results[i] = failed(ErrorCode.TYPE_ERROR, not_a_str(p))
                elif cache and p in first:
                    copies.append((i, first[p]))
                elif cache and (known := self._recall((p, rows, cols, limits, semantics, kept))) is not None:
                    results[i] = known
                else:
                    first.setdefault(p, i)
                    todo.append(i)
            # compiled here (compiled.py), a part at a time, each fed to the templates once it is
            # (feed.py); a program that never runs has its Execution already
            labels = answers if mode == ANSWER else None
            cuts = parts(todo, labels)
            made: dict[int, bytes | Execution] = {}
            feed = Feed(len(todo), max(1, min(workers or self.workers or default_workers(), -(-len(todo) // BATCH))),
                        labels)
            job = partial(dispatch, self, feed, made, rows, cols, limits, semantics, mode)
            running: Background | None = None
            try:
                for part in cuts:
                    made.update(zip(part, [json.dumps(programs[i]).encode() for i in part] if mode == "breach" else
                                    compiled.prepare_all([programs[i] for i in part], limits)))
                    feed.put([i for i in part if type(made[i]) is bytes], len(part))
                    if running is None and len(cuts) > 1:
                        running = Background(job)
                feed.close()
                if running is not None:
                    made.update(running.result())
                elif any(type(made[i]) is bytes for i in todo):  # one part: in the caller's thread
                    made.update(job())
            finally:  # (early: Ctrl-C, or a failure; what follows would be thrown away)
                feed.stop()
            for i in todo:
                results[i] = answer = made[i]
                if cache and type(answer) is Execution:
                    self._remember((programs[i], rows, cols, limits, semantics, kept), answer)
            for i, source in copies:
                results[i] = results[source]
            return [r if type(r) is Execution else failed(ErrorCode.HARNESS_ERROR, "the sandbox returned no result")
                    for r in results]
        except Exception as exc:  # the caller must never see an exception
            n = len(programs) if isinstance(programs, list) else 1
            return [failed(ErrorCode.HARNESS_ERROR, f"sandbox failure: {type(exc).__name__}: {exc}") for _ in range(n)]

    def execute(self, code: str, rows: int = DEFAULT_ROWS, cols: int = DEFAULT_COLS, limits: Limits | None = None, *,
                semantics: str = MODULE) -> Execution:
        """Run one program on a fresh rows x cols board (docs/sandbox.md: the contract)."""
        return self.execute_many([code], rows, cols, limits, workers=1, semantics=semantics)[0]


def dispatch(sandbox: LocalSandbox, feed: Feed, items, rows, cols, limits, semantics=MODULE, mode="code") -> dict:
    """The one way execute_many reaches the templates (tests put a failing one here)."""
    return sandbox.dispatch(feed, items, rows, cols, limits, semantics, mode)


_local: LocalSandbox | None = None
_local_lock = threading.Lock()


def local() -> LocalSandbox:
    """This process's default LocalSandbox."""
    global _local
    with _local_lock:
        if _local is None:
            _local = LocalSandbox()
        return _local


def shutdown() -> None:
    """Kill and reap every template of the default local sandbox (they restart on the next call)."""
    if _local is not None:
        _local.close()


atexit.register(shutdown)
