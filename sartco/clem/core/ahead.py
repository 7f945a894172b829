"""Work an episode's step will need, started before the step and done on background threads: at
the episode's setup (BuildGameMaster.setup), while the model's request is out (clemcore steps no
episode then), and when an answer comes in, while clemcore steps the round's other episodes. The
step then finds it done instead of doing it while the model server waits.
Today: the probes' gold draws (probes.draw_ahead) and the gold program's CodeBLEU analysis
(metrics.analyse_gold) at the setup, and an answer's build when the answer comes in
(answer_builds.start_build: clemcore's batchwise runner hands a round's answers to their players
before it steps the first episode). The work is the step's own, memoised: done ahead or not, the results
are the same; whatever it raises is left to the step, which does it again.

A daemon thread per lane takes its work in order (`submit`); `Started` keeps what was started by
what decides it, for the step that takes it. At exit (an interrupted run) the work still queued
is dropped, not done. A forked process gets its own queues, no thread (a thread is not forked),
nothing started and locks that no thread holds."""
from __future__ import annotations

import atexit
import os
import queue
import threading
from collections import OrderedDict
from collections.abc import Callable, Hashable
from concurrent.futures import Future

import sartco.program.pool  # noqa: F401  its shutdown registered first, so that _stop runs before it

_lock = threading.Lock()
_lanes: dict[str, queue.SimpleQueue] = {}  # a queue and a thread per lane
_pending: set[Future] = set()
_stopped = threading.Event()


def submit(work: Callable[[], object], lane: str = "setup") -> Future | None:
    """Queue work() for the lane's background thread: its Future, or None once the process is
    exiting. Lanes do not wait for each other: "setup" (an episode's setup), "answers" (an answer
    that came in: its build, started while clemcore steps the round's other episodes)."""
    with _lock:
        if _stopped.is_set():
            return None
        jobs = _lanes.get(lane)
        if jobs is None:  # the lane's first work in this process
            jobs = _lanes[lane] = queue.SimpleQueue()
            threading.Thread(target=_work_in_order, args=(jobs,), name=f"sartco-ahead-{lane}", daemon=True).start()
        future: Future = Future()
        _pending.add(future)
        jobs.put((future, work))
    return future


def _work_in_order(jobs: queue.SimpleQueue) -> None:
    while not _stopped.is_set():
        future, work = jobs.get()
        if future.set_running_or_notify_cancel():
            try:
                future.set_result(work())
            except BaseException as exc:
                future.set_exception(exc)
        with _lock:
            _pending.discard(future)


def _forked() -> None:
    """In a forked child: no thread, nothing queued, a lock that no thread holds."""
    global _lock
    _lock = threading.Lock()
    _lanes.clear()
    _pending.clear()


os.register_at_fork(after_in_child=_forked)


@atexit.register  # after the sandbox pool's shutdown, so run before it: no work starts a template again
def _stop() -> None:
    _stopped.set()
    with _lock:
        for future in _pending:
            future.cancel()


class Started:
    """Work started ahead on a lane, by what decides it (its key), for the step that needs it.
    `start(key, work)` queues work() once per key; `take(key, wait_queued)` forgets the key and
    gives the step work()'s result once it has ended, waiting for it if it has begun (or, with
    wait_queued, while it is still queued; else the queued work is dropped). None: nothing was
    started, the work was dropped, or it raised (the step then does the work itself, and meets
    what it raises). The `most` newest keys are kept (an older one's queued work is dropped)."""

    def __init__(self, lane: str, most: int):
        self.lane, self.most = lane, most
        self._lock = threading.Lock()
        self._futures: OrderedDict[Hashable, Future] = OrderedDict()
        os.register_at_fork(after_in_child=self._forked)

    def __len__(self) -> int:
        with self._lock:
            return len(self._futures)

    def start(self, key: Hashable, work: Callable[[], object]) -> None:
        with self._lock:
            if key in self._futures:
                return
            future = submit(work, self.lane)
            if future is None:
                return
            self._futures[key] = future
            while len(self._futures) > self.most:
                self._futures.popitem(last=False)[1].cancel()

    def take(self, key: Hashable, wait_queued: bool) -> object | None:
        with self._lock:
            future = self._futures.pop(key, None)
        if future is None or (not wait_queued and future.cancel()):
            return None
        try:
            return future.result()
        except BaseException:  # raised there, or dropped at exit: the step does the work itself
            return None

    def _forked(self) -> None:
        self._lock = threading.Lock()
        self._futures.clear()
