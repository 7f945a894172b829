"""Where template processes are started (handle.TemplateHandle.start): from one long-lived thread,
since a template's parent-death signal fires when the thread that started it ends (prctl(2)),
and the threads that drive templates come and go. One such thread per process (a forked child
starts its own).
"""
from __future__ import annotations

import os
import subprocess
import threading
from concurrent.futures import ThreadPoolExecutor

_spawner: tuple[int, ThreadPoolExecutor] | None = None  # (pid, executor)
_spawner_lock = threading.Lock()


def spawn(argv: list[str], env: dict[str, str]) -> subprocess.Popen[bytes]:
    """Start argv in `/` with `env` as its whole environment, its stdin and stdout pipes, its stderr
    /dev/null and no other descriptor, from the spawning thread."""
    global _spawner
    with _spawner_lock:
        if _spawner is None or _spawner[0] != os.getpid():
            _spawner = (os.getpid(), ThreadPoolExecutor(1, thread_name_prefix="sartco-spawner"))
        executor = _spawner[1]
    return executor.submit(
        subprocess.Popen, argv, stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=subprocess.DEVNULL,
        close_fds=True, cwd="/", env=env,
    ).result()
