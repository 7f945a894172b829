"""The parent's side of one worker process: start it, send it chunks, read its answers, kill it
when an answer is late, and the verdict of a program whose worker died.

A worker answers each program on its own line, so the parent knows which program is running and
gives each one `Limits.wall_time` seconds from the moment the previous answer was read. A late
answer kills the worker (SIGKILL, then reaped) and the program gets `timeout`; a worker that
dies gets its program `resource_limit` (out of memory: its own exit status, or SIGKILL from the
kernel) or `runtime_error` (a crash, named by its signal); a worker that could not start or ended
by another exit (the worker's own code failed, not the program) gives `harness_error`. A worker that
retires after an answer (a leading "!", see worker.py) is replaced before the next program.
The rest of the batch goes to a fresh worker. A worker compiles each chunk ahead (worker.py), for
at most a tenth of a wall time, which the chunk's first program shares: so a kill before the first
answer of a chunk of several blames nobody yet, and the rest runs again, each program compiled
at its own turn.

Workers are started from one long-lived thread (`spawn`), so that they die with the parent
process (worker.py), isolated as `python -I -S` would be (`-s -S -P`: no user site, no site, no
script or working folder on sys.path; an environment without PYTHON* variables) except for one
variable that -I would ignore: PYTHONHASHSEED=0, so that str hashes, and with them the order of
sets and everything built from it, are the same in every worker, run and machine.
"""
from __future__ import annotations

import fcntl
import json
import os
import select
import signal
import subprocess
import sys
import threading
import time
from collections import deque
from concurrent.futures import ThreadPoolExecutor

from sartco.settings import IMPORT_ROOT
from sartco.world import ErrorCode

from .execution import MODULE, Execution, Limits
from .worker import OUT_OF_MEMORY, RETIRED

E = ErrorCode
CHUNK = 64  # items per worker round trip
PATIENCE = 0.01  # most seconds to wait before reading more answers of a running batch: while a
# worker works, the parent wakes up seldom and reads many answers at once; as the end of the batch
# nears, the waits shrink to half the estimated rest, so the last answers are read as they come
START_TIMEOUT = 30.0
PIPE_SIZE = 1 << 20  # bytes of answers a worker can write ahead of the parent
READ_SIZE = 1 << 16  # bytes per read (a read allocates its whole size first)
_ROOT = str(IMPORT_ROOT)
ISOLATED = ("-s", "-S", "-P")  # -I without -E (see the module docstring)
HASH_SEED = "0"
_BOOT = (
    "import sys; sys.path.insert(0, sys.argv[1]); "
    "from sartco.program.worker import main; sys.exit(main(int(sys.argv[2])))"
)


class _Dead(Exception):
    """The worker process is gone or unusable."""


class Worker:
    def __init__(self):
        self.proc: subprocess.Popen | None = None
        self.lines: deque[bytes] = deque()
        self.tail = b""
        self.lock = threading.Lock()
        self.room = 4096  # bytes the worker's stdin pipe holds

    # -- process ---------------------------------------------------------------------------
    def start(self):
        self.proc = spawn([sys.executable, *ISOLATED, "-c", _BOOT, _ROOT, str(os.getpid())])
        for pipe in (self.proc.stdin, self.proc.stdout):  # room for items sent ahead and answers that
            try:  # pile up while the parent waits (Linux; elsewhere the default size)
                fcntl.fcntl(pipe.fileno(), fcntl.F_SETPIPE_SZ, PIPE_SIZE)
            except (AttributeError, OSError):
                pass
        try:
            self.room = fcntl.fcntl(self.proc.stdin.fileno(), fcntl.F_GETPIPE_SZ)
        except (AttributeError, OSError):
            self.room = 4096  # POSIX guarantees at least PIPE_BUF
        self.lines.clear()
        self.tail = b""
        if self._readline(time.monotonic() + START_TIMEOUT) != b'"ready"':
            self.kill()
            raise _Dead("the sandbox worker did not start")

    def kill(self) -> int | None:
        proc, self.proc = self.proc, None
        if proc is None:
            return None
        try:
            proc.kill()
        except OSError:
            pass
        for stream in (proc.stdin, proc.stdout):
            try:
                stream.close()
            except OSError:
                pass
        return proc.wait()

    # -- i/o --------------------------------------------------------------------------------
    def _readline(self, deadline: float) -> bytes | None:
        """The next answer line; None when the deadline passed; raise _Dead on EOF."""
        fd = self.proc.stdout.fileno()
        while not self.lines:
            remaining = deadline - time.monotonic()
            if remaining <= 0 or not select.select([fd], [], [], remaining)[0]:
                return None
            chunk = os.read(fd, READ_SIZE)
            if not chunk:
                raise _Dead("the sandbox worker ended")
            parts = (self.tail + chunk).split(b"\n")
            self.tail = parts.pop()
            self.lines.extend(parts)
        return self.lines.popleft()

    def _send(self, stdin, mode: str, items: list[bytes], rows: int, cols: int, limits: Limits, cache: bool,
              ahead: bool, semantics: str):
        """Write the items in chunks. For more than fits in the pipe at once this runs in a thread
        of its own: the worker finds its next chunk waiting when it finishes one, and a full pipe
        never blocks the reading of answers."""
        try:
            for k in range(0, len(items), CHUNK):
                chunk = items[k:k + CHUNK]
                header = json.dumps({"limits": limits.as_list(), "rows": rows, "cols": cols, "cache": cache,
                                     "mode": mode, "items": len(chunk), "ahead": ahead,
                                     "semantics": semantics}).encode()
                stdin.write(b"\n".join([header, *chunk]) + b"\n")
                stdin.flush()
        except (OSError, ValueError):
            pass  # the worker died or was killed: the reader finds out and reports it

    def run(self, mode: str, items: list[bytes], rows: int, cols: int, limits: Limits, cache: bool,
            semantics: str = MODULE) -> list:
        """One answer per item: the worker's answer line (bytes), or an Execution for an item
        whose worker timed out or died (the rest then goes to a fresh worker)."""
        results: list = []
        ahead = True  # the worker compiles each chunk ahead (see worker.py)
        while len(results) < len(items):
            todo = items[len(results):]
            try:
                if self.proc is None:
                    self.start()
            except (_Dead, OSError, ValueError) as exc:
                self.kill()
                results.extend(failed(E.HARNESS_ERROR, f"sandbox unavailable: {exc}") for _ in todo)
                break
            send = (self.proc.stdin, mode, todo, rows, cols, limits, cache, ahead, semantics)
            writer = None
            if len(todo) <= CHUNK and sum(map(len, todo)) + 4096 < self.room:
                self._send(*send)  # one chunk that fits in the empty pipe: the write cannot block
            else:
                writer = threading.Thread(target=self._send, args=send, daemon=True)
                writer.start()
            started = time.monotonic()
            for k in range(len(todo)):
                if k and not self.lines and not select.select([self.proc.stdout], [], [], 0)[0]:
                    # nothing to read: let answers pile up, so that one wake-up reads many
                    rest = (len(todo) - k) * (time.monotonic() - started) / k
                    if rest > 0.002:
                        time.sleep(min(PATIENCE, rest / 2))
                try:
                    line = self._readline(time.monotonic() + limits.wall_time)
                    failure = None if line is not None else failed(
                        E.TIMEOUT, f"the program ran longer than {limits.wall_time:g} s")
                except (_Dead, OSError):
                    line, failure = None, _died(self.kill())
                if line is not None and line[:1] == RETIRED:  # the worker retired after answering
                    results.append(line[1:])
                    self.kill()
                    break
                if line is not None:
                    results.append(line)
                    continue
                self.kill()
                if ahead and k % CHUNK == 0 and len(todo) - k > 1:
                    # no answer yet of a chunk the worker compiled ahead: any of its programs may
                    # be at fault, so the rest runs again, each compiled at its own turn
                    ahead = False
                else:
                    results.append(failure)
                break
            if writer is not None:
                writer.join()  # done, or unblocked by the kill (a closed pipe)
        return results


def _died(status: int | None) -> Execution:
    """The verdict of a program whose worker ended without answering it."""
    if status == OUT_OF_MEMORY:
        return failed(E.RESOURCE_LIMIT, "the sandbox worker ran out of memory")
    if status in (-signal.SIGKILL, -signal.SIGXCPU):  # the kernel's OOM killer or a CPU limit
        return failed(E.RESOURCE_LIMIT, f"the sandbox worker was killed ({signal.Signals(-status).name}): "
                                         f"out of memory or CPU time")
    if status is not None and status < 0:
        try:
            name = signal.Signals(-status).name
        except ValueError:
            name = f"signal {-status}"
        return failed(E.RUNTIME_ERROR, f"the program crashed the sandbox worker ({name})")
    # an exit status of the worker's own (its code failed, or it was ended from outside): not the program's
    return failed(E.HARNESS_ERROR, f"the sandbox worker ended unexpectedly (status {status})")


def failed(code: ErrorCode, message: str) -> Execution:
    return Execution(False, code, message, {}, 0)


_spawner: tuple[int, ThreadPoolExecutor] | None = None  # (pid, executor)
_spawner_lock = threading.Lock()


def spawn(argv: list[str]) -> subprocess.Popen:
    """Start a worker from one long-lived thread: a worker's parent-death signal fires when the
    thread that started it ends (prctl(2)), and the threads that drive workers come and go."""
    global _spawner
    with _spawner_lock:
        if _spawner is None or _spawner[0] != os.getpid():
            _spawner = (os.getpid(), ThreadPoolExecutor(1, thread_name_prefix="sartco-spawner"))
        executor = _spawner[1]
    return executor.submit(
        subprocess.Popen, argv, stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=subprocess.DEVNULL,
        close_fds=True, cwd="/", env=_environment(),
    ).result()


def _environment() -> dict[str, str]:
    """The parent's environment without PYTHON* variables, and the fixed hash seed."""
    env = {k: v for k, v in os.environ.items() if not k.startswith("PYTHON")}
    env["PYTHONHASHSEED"] = HASH_SEED
    return env
