"""The parent's side of one template process (child/template.py): start it, send it chunks of programs,
read one line per program, and turn each into an Execution (verdict.py decides the board).

The template enforces each program's wall time itself (it kills the child at Limits.wall_time)
and always answers; the parent still gives each answer Limits.wall_time + SLACK seconds, and a
template that is late, dies, answers garbage, could not start or cannot confine programs is the
harness's failure (`harness_error`, with the reason), never a program's: no program runs in the
template. The rest of a batch then goes to a fresh template.

Templates are started from one long-lived thread (spawn.py), so that they die with the parent
process (child/template.py), isolated as `python -I -S` would be (`-s -S -P`: no user site, no site, no
script or working folder on sys.path), in `/`, with ENVIRONMENT as their whole environment:
nothing of the user's (no API key, token or path) is inherited. PYTHONHASHSEED=0 (which -I
would ignore) makes str hashes, and with them the order of sets and everything built from it,
the same in every child, run and machine; PYTHONUTF8=1 and LC_CTYPE=C.UTF-8 fix the encoding
(else Python would pick one from the locale). The template's argv holds the interpreter, the
import root (sys.path), the parent's pid and the mode; then it enters its namespaces
(confine.py; NAMESPACES) and reports them on its ready line (walls.py shows them).
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
from functools import partial
from typing import Any

from sartco.settings import IMPORT_ROOT
from sartco.world import ErrorCode

from . import compiled
from .child.confine import Unconfinable, compile_filter
from .execution import MODULE, Execution, Limits
from .feed import More, Stream
from .spawn import spawn
from .verdict import decide, failed

CHUNK = 64  # items per template round trip
SLACK = 10.0  # seconds beyond a program's wall time before the parent gives up on its template
START_TIMEOUT = 60.0
PIPE_SIZE = 1 << 20  # bytes of answers a template can write ahead of the parent
READ_SIZE = 1 << 16  # bytes per read (a read allocates its whole size first)
_ROOT = str(IMPORT_ROOT)
ISOLATED = ("-s", "-S", "-P")  # -I without -E (see the module docstring)
HASH_SEED = "0"
# the template's whole environment: nothing of the user's (no key, token or path) is inherited
ENVIRONMENT = {"PYTHONHASHSEED": HASH_SEED, "PYTHONUTF8": "1", "LC_CTYPE": "C.UTF-8"}
NAMESPACES = True  # templates enter their namespaces (the tests turn it off to test seccomp alone)
_BOOT = (
    "import sys; sys.path.insert(0, sys.argv[1]); "
    "from sartco.program.child.template import main; "
    "sys.exit(main(int(sys.argv[2]), '--breach' in sys.argv[3:], '--no-namespaces' not in sys.argv[3:]))"
)
HOWS = (b"exit", b"signal", b"timeout", b"overflow", b"unconfined")
SHARED = ("gold", "answer")  # modes whose chunk runs in one child (child/batch.py)


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
        self.cpu: int | None = None  # the one CPU its processes run on from its next chunk (None: any; pool.pinned)
        self.pid: int | None = None  # the template's pid (pid 1 of its namespace, whose parent is proc)
        self.walls: list[Any] = []  # [name, up, why] of each namespace, as the template reported them

    # -- process ---------------------------------------------------------------------------
    def start(self) -> None:
        try:
            bpf = _filter()
        except Unconfinable as exc:
            raise _Dead(f"the sandbox cannot confine programs here: {exc}") from None
        argv = [sys.executable, *ISOLATED, "-c", _BOOT, _ROOT, str(os.getpid())] + (["--breach"] if self.breach else []) \
            + ([] if NAMESPACES else ["--no-namespaces"])
        self.proc = spawn(argv, dict(ENVIRONMENT))  # ENVIRONMENT, and nothing of the parent's
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
        ready, _, report = (first or b"").partition(b" ")
        if ready != b'"ready"':
            self.kill()
            if first is not None and first.startswith(b"unconfined: "):
                raise _Dead("the sandbox cannot confine programs here: " + first[12:].decode("ascii", "replace"))
            raise _Dead("the sandbox worker did not start")
        report = json.loads(report) if report else {}
        self.pid, self.walls = report.get("pid", self.proc.pid), report.get("walls", [])
        _say_once(self.walls)

    def kill(self) -> int | None:
        proc, self.proc, self.pid = self.proc, None, None
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

    def _send(self, stdin, items: list[bytes], rows: int, cols: int, limits: Limits, semantics: str, mode: str,
              starts: frozenset[int] = frozenset()):
        """Write the items in chunks (of CHUNK at most; a new one at each index of `starts`). For
        more than fits in the pipe at once this runs in a thread of its own: the template finds its
        next chunk waiting when it finishes one, and a full pipe never blocks the reading of answers."""
        try:
            for chunk in _chunks(items, starts):
                header = json.dumps({"limits": limits.as_list(), "rows": rows, "cols": cols, "semantics": semantics,
                                     "items": len(chunk), "mode": mode, "cpu": self.cpu}).encode()
                stdin.write(b"\n".join([header, *chunk]) + b"\n")
                stdin.flush()
        except (OSError, ValueError):
            pass  # the template died or was killed: the reader finds out and reports it

    def run(self, items: list[bytes], rows: int, cols: int, limits: Limits, semantics: str = MODULE,
            mode: str = "code", judge: bool = True, starts: frozenset[int] = frozenset(),
            more: More | None = None) -> list[Execution]:
        """One Execution per item (a program as compiled.prepare made it), in order, and per item
        that `more` hands out: it is asked for more (items, and where chunks start among them) each
        time the template has fewer than AHEAD left, until it hands out none (pool.py's feed).
        With `judge`, a template that dies or falls silent while it runs an item is judged
        (`_judged`). In the modes whose chunk shares a child (SHARED), a chunk starts at each index
        of `starts` too (one answer's programs), and its first answer may take the whole chunk's
        wall time, twice."""
        stream = Stream(list(items), set(starts), more, _longest)
        results: list[Execution] = []
        while len(results) < len(stream.items) or not stream.ended:
            suspect, late = None, False
            try:
                if self.proc is None:
                    self.start()
            except (_Dead, OSError, ValueError) as exc:
                self.kill()
                stream.drain()
                results.extend(failed(ErrorCode.HARNESS_ERROR, f"sandbox unavailable: {exc}")
                               for _ in stream.items[len(results):])
                break
            stream.dead = False
            send = partial(self._send, self.proc.stdin, rows=rows, cols=cols, limits=limits, semantics=semantics,
                           mode=mode)
            todo, rest = stream.items[len(results):], frozenset(k - len(results) for k in stream.starts if k >= len(results))
            writer = None
            if stream.ended and len(todo) <= CHUNK and sum(map(len, todo)) + 4096 < self.room:
                send(todo, starts=rest)  # one chunk that fits in the empty pipe: the write cannot block
            else:
                writer = threading.Thread(target=stream.write, args=(send, todo, rest), daemon=True)
                writer.start()
            while stream.next(len(results)):
                patience = limits.wall_time * (2 * stream.longest if mode in SHARED else 1) + SLACK
                try:
                    line = self._readline(time.monotonic() + patience)
                    fault, late = (None, False) if line is not None else ("the sandbox worker did not answer in time", True)
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
                    suspect = len(results) - 1
                self.kill()  # the template failed: the rest goes to a fresh one
                stream.stop()
                break
            if writer is not None:
                writer.join()  # done, or unblocked by the kill (a closed pipe)
            if stream.error is not None:
                raise stream.error
            if suspect is not None and judge:
                results[suspect] = self._judged(stream.items[suspect], results[suspect], late, rows, cols, limits,
                                                semantics, mode)
        return results

    def _judged(self, item: bytes, fault: Execution, late: bool, rows: int, cols: int, limits: Limits, semantics: str,
                mode: str) -> Execution:
        """The template died (or fell silent: `late`) while it ran `item`, whose verdict so far is
        the harness_error `fault`. Whose failure was it? The evidence: the item runs again alone in
        a fresh template, and that answer is its verdict. If that template fails too, a program that
        does nothing runs in another: answered, the program brought its templates down itself (its
        `runtime_error`, or `timeout` when they fell silent); not answered, templates fail whatever
        runs here, and the fault is the harness's."""
        again = self.run([item], rows, cols, limits, semantics, mode, judge=False)[0]
        if again.error is not ErrorCode.HARNESS_ERROR:
            return again
        empty = compiled.prepare("", limits)  # what fails whatever runs fails on too
        control = self.run([empty], rows, cols, limits, semantics, "code", judge=False)[0] if type(empty) is bytes else fault
        if control.error is ErrorCode.HARNESS_ERROR:
            return fault
        if late:
            return failed(ErrorCode.TIMEOUT, f"the program's sandbox template stopped answering while it ran, twice "
                                             f"(an empty program's did not): it ran longer than {limits.wall_time:g} s")
        return failed(ErrorCode.RUNTIME_ERROR, "the program brought down the sandbox template that ran it, twice "
                                               "(an empty program did not)")


def _chunks(items: list[bytes], starts: frozenset[int]) -> list[list[bytes]]:
    """The items in chunks of CHUNK at most, a new one at each index of `starts`."""
    chunks: list[list[bytes]] = []
    for k, item in enumerate(items):
        if not chunks or k in starts or len(chunks[-1]) == CHUNK:
            chunks.append([])
        chunks[-1].append(item)
    return chunks


def _longest(items: list[bytes], starts: frozenset[int]) -> int:
    """The most items of one chunk (_chunks)."""
    return max(map(len, _chunks(items, starts)), default=1)


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


_said = False


def _say_once(walls: list[Any]) -> None:
    """Once per process: the namespaces the kernel refused (programs still run, behind layer 1)."""
    global _said
    down = [(name, why) for name, up, why in walls if not up]
    if NAMESPACES and down and not _said:
        _said = True
        print(f"sartco: {', '.join(name for name, _ in down)} namespace(s) down ({down[0][1]}); programs run "
              f"behind seccomp and rlimits", file=sys.stderr)


_bpf: bytes | None = None


def _filter() -> bytes:
    """The seccomp filter, compiled once per process (confine.compile_filter)."""
    global _bpf
    if _bpf is None:
        _bpf = compile_filter()
    return _bpf
