"""A process forked while another thread of the parent holds a lock: the hazard of a background
thread at fork (sartco.clem.core.ahead, probes), which the tests of both fork into."""
from __future__ import annotations

import os
import threading
import time
from collections.abc import Callable


def forked_while_held(lock, in_child: Callable[[], bool], seconds: float = 120) -> int:
    """Fork while a thread of this process holds `lock`; the child runs in_child() and exits 0
    when it gives True, 1 when not, 2 when it raised. The child's exit code; AssertionError
    (the child killed) when it has not ended within `seconds` (a deadlock on the lock)."""
    held, release = threading.Event(), threading.Event()

    def holder() -> None:
        with lock:
            held.set()
            release.wait(60)

    thread = threading.Thread(target=holder)
    thread.start()
    held.wait(60)
    pid = os.fork()
    if pid == 0:   # the child: the lock is held by a thread it does not have
        try:
            os._exit(0 if in_child() else 1)
        finally:
            os._exit(2)
    release.set()
    thread.join()
    deadline = time.monotonic() + seconds
    while time.monotonic() < deadline:
        done, status = os.waitpid(pid, os.WNOHANG)
        if done:
            return os.waitstatus_to_exitcode(status)
        time.sleep(0.1)
    os.kill(pid, 9)
    os.waitpid(pid, 0)
    raise AssertionError("the forked process hung")
