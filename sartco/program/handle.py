"""The parent's side of one template process (child/template.py): start it, send it chunks of programs,
read one line per program, and turn each into an Execution (verdict.py decides the board).

The template enforces each program's wall time itself (it kills the child at Limits.wall_time)
and always answers; the parent still gives each answer Limits.wall_time + SLACK seconds, and a
template that is late, dies, answers garbage, could not start or cannot confine programs is the
harness's failure (`harness_error`, with the reason), never a program's: no program runs in the
template. The rest of a batch then goes to a fresh template.

Templates are started from one long-lived thread (`spawn`), so that they die with the parent
process (child/template.py), isolated as `python -I -S` would be (`-s -S -P`: no user site, no site, no
script or working folder on sys.path; an environment without PYTHON* variables) except for one
variable that -I would ignore: PYTHONHASHSEED=0, so that str hashes, and with them the order of
sets and everything built from it, are the same in every child, run and machine. BLAS libraries
are told to use one thread (a forked child has no other thread, and may start none).
"""
from __future__ import annotations

import base64
import binascii
import fcntl
import json
import os
import select
import subprocess
import sys
import threading
import time
from collections import deque
from concurrent.futures import ThreadPoolExecutor

from sartco.settings import IMPORT_ROOT
from sartco.world import ErrorCode

from .child.confine import Unconfinable, compile_filter
from .execution import MODULE, Execution, Limits
from .verdict import decide, failed

CHUNK = 64  # items per template round trip
SLACK = 10.0  # seconds beyond a program's wall time before the parent gives up on its template
START_TIMEOUT = 60.0
PIPE_SIZE = 1 << 20  # bytes of answers a template can write ahead of the parent
READ_SIZE = 1 << 16  # bytes per read (a read allocates its whole size first)
_ROOT = str(IMPORT_ROOT)
ISOLATED = ("-s", "-S", "-P")  # -I without -E (see the module docstring)
HASH_SEED = "0"
ONE_THREAD = ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS")
_BOOT = (
    "import sys; sys.path.insert(0, sys.argv[1]); "
    "from sartco.program.child.template import main; sys.exit(main(int(sys.argv[2]), '--breach' in sys.argv[3:]))"
)
HOWS = (b"exit", b"signal", b"timeout", b"overflow", b"unconfined")


class _Dead(Exception):
    """The template process is gone or unusable."""


class TemplateHandle:
    """One template process and the thread-safe state of reading its answers."""

    def __init__(self, breach: bool = False):
        self.proc: subprocess.Popen | None = None
        self.lines: deque[bytes] = deque()
        self.tail = b""
        self.lock = threading.Lock()
        self.room = 4096  # bytes the template's stdin pipe holds
        self.breach = breach

    # -- process ---------------------------------------------------------------------------
    def start(self):
        try:
            bpf = _filter()
        except Unconfinable as exc:
            raise _Dead(f"the sandbox cannot confine programs here: {exc}") from None
        argv = [sys.executable, *ISOLATED, "-c", _BOOT, _ROOT, str(os.getpid())] + (["--breach"] if self.breach else [])
        self.proc = spawn(argv)
        self.proc.stdin.write(base64.b64encode(bpf) + b"\n")
        self.proc.stdin.flush()
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
        first = self._readline(time.monotonic() + START_TIMEOUT)
        if first != b'"ready"':
            self.kill()
            if first is not None and first.startswith(b"unconfined: "):
                raise _Dead("the sandbox cannot confine programs here: " + first[12:].decode("ascii", "replace"))
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

    def _send(self, stdin, items: list[bytes], rows: int, cols: int, limits: Limits, semantics: str, mode: str):
        """Write the items in chunks. For more than fits in the pipe at once this runs in a thread
        of its own: the template finds its next chunk waiting when it finishes one, and a full pipe
        never blocks the reading of answers."""
        try:
            for k in range(0, len(items), CHUNK):
                chunk = items[k:k + CHUNK]
                header = json.dumps({"limits": limits.as_list(), "rows": rows, "cols": cols, "semantics": semantics,
                                     "items": len(chunk), "mode": mode}).encode()
                stdin.write(b"\n".join([header, *chunk]) + b"\n")
                stdin.flush()
        except (OSError, ValueError):
            pass  # the template died or was killed: the reader finds out and reports it

    def run(self, items: list[bytes], rows: int, cols: int, limits: Limits, semantics: str = MODULE,
            mode: str = "code") -> list[Execution]:
        """One Execution per item (a program's source as a JSON string), in order."""
        results: list[Execution] = []
        while len(results) < len(items):
            todo = items[len(results):]
            try:
                if self.proc is None:
                    self.start()
            except (_Dead, OSError, ValueError) as exc:
                self.kill()
                results.extend(failed(ErrorCode.HARNESS_ERROR, f"sandbox unavailable: {exc}") for _ in todo)
                break
            send = (self.proc.stdin, todo, rows, cols, limits, semantics, mode)
            writer = None
            if len(todo) <= CHUNK and sum(map(len, todo)) + 4096 < self.room:
                self._send(*send)  # one chunk that fits in the empty pipe: the write cannot block
            else:
                writer = threading.Thread(target=self._send, args=send, daemon=True)
                writer.start()
            for _ in todo:
                try:
                    line = self._readline(time.monotonic() + limits.wall_time + SLACK)
                    fault = None if line is not None else "the sandbox worker did not answer in time"
                except (_Dead, OSError):
                    line, fault = None, f"the sandbox worker ended unexpectedly (status {self.kill()})"
                if line is not None:
                    result = _answer(line, limits)
                    results.append(result)
                    if result is not None:
                        continue
                    results[-1] = failed(ErrorCode.HARNESS_ERROR, f"garbled answer from the sandbox worker: {line[:60]!r}")
                else:
                    results.append(failed(ErrorCode.HARNESS_ERROR, fault))
                self.kill()  # the template failed: the rest goes to a fresh one
                break
            if writer is not None:
                writer.join()  # done, or unblocked by the kill (a closed pipe)
        return results


def _answer(line: bytes, limits: Limits) -> Execution | None:
    """The Execution of one answer line of the template, None when the line is garbled."""
    parts = line.split(b" ")
    if len(parts) != 3 or parts[0] not in HOWS or not parts[1].lstrip(b"-").isdigit():
        return None
    try:
        answer = base64.b64decode(parts[2], validate=True)
    except (binascii.Error, ValueError):
        return None
    return decide(parts[0], int(parts[1]), answer, limits.wall_time)


_bpf: bytes | None = None


def _filter() -> bytes:
    """The seccomp filter, compiled once per process (confine.compile_filter)."""
    global _bpf
    if _bpf is None:
        _bpf = compile_filter()
    return _bpf


_spawner: tuple[int, ThreadPoolExecutor] | None = None  # (pid, executor)
_spawner_lock = threading.Lock()


def spawn(argv: list[str]) -> subprocess.Popen:
    """Start a template from one long-lived thread: its parent-death signal fires when the
    thread that started it ends (prctl(2)), and the threads that drive templates come and go."""
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
    """The parent's environment without PYTHON* variables, the fixed hash seed, one BLAS thread."""
    env = {k: v for k, v in os.environ.items() if not k.startswith("PYTHON")}
    env["PYTHONHASHSEED"] = HASH_SEED
    env.update(dict.fromkeys(ONE_THREAD, "1"))
    return env
