"""Work an episode's step will need, started at the episode's setup (BuildGameMaster.setup) and
done on one background thread while the model's request is out: clemcore steps no episode then,
so the step after the answer finds it done instead of doing it while the model server waits.
Today: the probes' gold draws (probes.draw_ahead) and the gold program's CodeBLEU analysis
(scoring.analyse_ahead). The work is the step's own, memoised: done ahead or not, the results
are the same; whatever it raises is left to the step, which does it again.

One daemon thread takes the work in the order of the setups. At exit (an interrupted run) the
work still queued is dropped, not done. A forked process gets its own queue and no thread (a
thread is not forked)."""
from __future__ import annotations

import atexit
import os
import queue
import threading
from collections.abc import Callable
from concurrent.futures import Future

import sartco.program.pool  # noqa: F401  its shutdown registered first, so that _stop runs before it

_lock = threading.Lock()
_queue: queue.SimpleQueue = queue.SimpleQueue()
_worker: threading.Thread | None = None
_pending: set[Future] = set()
_stopped = threading.Event()


def submit(work: Callable[[], object]) -> Future | None:
    """Queue work() for the background thread: its Future, or None once the process is exiting."""
    global _worker
    with _lock:
        if _stopped.is_set():
            return None
        if _worker is None:  # the first work of this process
            _worker = threading.Thread(target=_work_in_order, args=(_queue,), name="sartco-ahead", daemon=True)
            _worker.start()
        future: Future = Future()
        _pending.add(future)
        _queue.put((future, work))
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
    global _lock, _queue, _worker
    _lock, _queue, _worker = threading.Lock(), queue.SimpleQueue(), None
    _pending.clear()


os.register_at_fork(after_in_child=_forked)


@atexit.register  # after the sandbox pool's shutdown, so run before it: no work starts a template again
def _stop() -> None:
    _stopped.set()
    with _lock:
        for future in _pending:
            future.cancel()
