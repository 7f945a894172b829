"""The template process: it imports what programs need, builds the kernel's walls, runs no
program itself, and has one confined child per program, forked by its zygote (zygote.py: every
child starts from the same memory, so one program's objects lie at the same addresses). The child runs that one program and
exits, so nothing a program does outlives it: no process runs programs of two answers (only
one answer's probes, mode "answer", or the harness's gold programs of a batch, "gold", share one).

Protocol with the parent (driver.py), lines of bytes:
  parent -> template, once at start: the seccomp filter, a BPF program in base64 (confine.py)
  template -> parent, once at start: '"ready" {"pid": its pid outside, "walls": [[namespace, up, why]]}',
      or "unconfined: <why>" (then it exits: the walls cannot be built here; no program runs unconfined)
  parent -> template, per chunk: a header {"limits": [...Limits fields...], "rows": R, "cols": C,
      "semantics": "module" | "paper", "items": K, "mode": "code" | "gold" | "answer" | "breach",
      "cpu": the one CPU it, its zygote and their children run on from now on, or null: any}, then K
      lines, each a program as the parent compiled it (runtime.answer_item; "breach": a JSON string)
  template -> parent, one line per item, in order: b"<how> <status> <answer as base64>", where
      <how> is how the child ended: "exit" (status: its exit status), "signal" (status: the signal
      that killed it), "timeout" (killed at Limits.wall_time), "overflow" (killed: it wrote more
      than ANSWER_BYTES), "unconfined" (it ended before its walls were up: no program ran).
The template decides nothing about the program: the parent reads the child's answer (a put log
of plain values and an outcome, see runtime.answer) and decides the board (verdict.py).

Modes "gold" and "answer" (batch.py): the chunk's programs in one child.

The child, between fork and the program's first line (`_child`): its descriptors become /dev/null
(0, 1, 2) and its answer pipe (3), every other one closed; then the rlimits, death with the
template, and the seccomp filter (confine.py); then it writes CONFINED to the pipe, so the
template knows that the walls were up before anything of the program ran. A child's failure
after that is the program's: its exit status and signals are reported as they are.

Mode "breach" runs a source with Python's real builtins and none of the sandbox's checks (as if
every one had fallen), inside the same walls; only a template started with `--breach` (the
tests' assume-breach harness, tests/program/test_walls.py) accepts it.

The template never outlives the parent (PR_SET_PDEATHSIG; its stdin closing ends it) and its
zygote and children never outlive it (the same, set in each; the children are the template's own).
"""
from __future__ import annotations

import base64
import errno
import gc
import json
import os
import select
import signal
import sys
import time
from collections.abc import Callable, Iterable
from functools import partial
from types import ModuleType
from typing import TYPE_CHECKING

from . import batch
from .zygote import WARM, Zygote

if TYPE_CHECKING:
    from ..execution import Limits

OUT_OF_MEMORY = 3  # a child's exit status after a MemoryError outside the program's own run
FAILED = 4  # a child's exit status when its own code failed after the walls were up
CONFINED = b"C"  # the first byte of every answer: written by the child once its walls are up
ANSWER_BYTES = 4 << 20  # the most a child may write (a 64 x 64 board's full log is under 1 MiB)
MAX_FD = 1 << 16
# modules that Python imports lazily while it compiles or runs a program (a confined child can
# open no file, so none can be imported there): the parser's NFKC of non-ASCII names (PEP 3131)
PRELOAD = ("unicodedata",)


def _vm_bytes() -> int:
    with open("/proc/self/statm") as f:
        return int(f.read().split()[0]) * os.sysconf("SC_PAGE_SIZE")


def _one(work: Callable[[], bytes]) -> tuple[bytes]:
    return (work(),)


def _open_a_file() -> bytes:
    """The self-test's work: the errno of opening a file, or b"opened"."""
    try:
        os.open("/proc/self/statm", os.O_RDONLY)
    except OSError as exc:
        return b"%d" % exc.errno
    return b"opened"


class Template:
    """What the children are forked from: the filter, the template's size, /dev/null."""

    runtime: ModuleType  # sartco.program.child.runtime, imported in the template only

    def __init__(self, bpf: bytes, breach: bool = False):
        from ..standins.modules import forget_typing
        from . import confine, runtime
        from .breach import breached

        self.runtime, self.breached = runtime, breached
        for name in PRELOAD:
            __import__(name)
        self.filter = confine.Walls(bpf)  # raises confine.Unconfinable
        self.breach = breach
        self.null = os.open(os.devnull, os.O_RDWR)
        if breach:  # the assume-breach tests attack the kernel's walls with these already imported
            import socket  # noqa: F401
            import subprocess  # noqa: F401
            import threading  # noqa: F401
        # the zygote clones children with the GIL held, not os.fork(): Python's at-fork work doubled a
        # fork's cost, and with one thread only (checked here) the child's interpreter is consistent as it is
        if len(sys._current_frames()) != 1:
            raise RuntimeError("the sandbox template must have one thread")
        forget_typing()  # after every import: each program of a child finds typing's caches empty (runtime.RAN)
        gc.collect()
        gc.freeze()  # the template's objects are never collected: a child's collections touch none of them
        self.base = _vm_bytes()
        self.cpus = os.sched_getaffinity(0)  # the CPUs it may use
        self.cpu: int | None = None  # the one it runs on (place)

    def start(self) -> None:
        """Once the template is set up (its namespaces finished): the zygote that every child is
        forked from (zygote.py), then the self-test: a child that tries to open a file must get
        EPERM from the filter (not EMFILE from the rlimits, not a descriptor), or no program runs here."""
        from .confine import Unconfinable
        from ..execution import Limits

        self.zygote = Zygote(lambda job, write: self._child(job[0], job[1], write))
        for _ in range(WARM):  # the zygote's loop settles meanwhile (zygote.WARM)
            how, status, answer = self.fork(_open_a_file, Limits(wall_time=10.0))
            if how == b"unconfined":
                raise Unconfinable(f"the kernel refused the seccomp filter or the rlimits (status {status})")
            if (how, status, answer) != (b"exit", 0, b"%d" % errno.EPERM):
                raise Unconfinable(f"a confined process could open a file ({how.decode()} {status} {answer[:40]!r})")

    def place(self, cpu: int | None) -> None:
        """Run on `cpu` from now on, and so do the zygote and its children (None: any; pool.pinned)."""
        try:
            for pid in (0, self.zygote.pid) if cpu != self.cpu else ():
                os.sched_setaffinity(pid, self.cpus if cpu is None else {cpu})
            self.cpu = cpu
        except (OSError, ValueError):  # scheduling only: where the kernel refuses, as before
            pass

    def fork(self, work: Callable[[], bytes], limits: Limits) -> tuple[bytes, int, bytes]:
        """Run work() (-> the answer's bytes) in a fresh confined child; how it ended, its status
        and what it wrote after CONFINED. work is pickled to the child: a module-level function
        or a partial of one, never a lambda or closure."""
        return self.spawn(partial(_one, work), limits, limits, 0)

    def spawn(self, work: Callable[[], Iterable[bytes]], limits: Limits, walls: Limits,
               frames: int) -> tuple[bytes, int, bytes]:
        """Fork a confined child (rlimits of `walls`) that writes every chunk of work(); with
        `frames`, what it writes is that many framed answers, and each has limits.wall_time. The
        child comes from the zygote (work and walls pickled)."""
        read, write = os.pipe()
        try:
            pidfd = self.zygote.fork((work, walls), write)
        except BaseException:
            os.close(read)
            raise
        finally:
            os.close(write)
        try:
            return self._collect(pidfd, read, limits.wall_time, frames)
        finally:
            os.close(read)

    def _child(self, work: Callable[[], Iterable[bytes]], limits: Limits, write: int) -> None:
        status = FAILED
        try:
            for fd in (0, 1, 2):
                os.dup2(self.null, fd)
            os.dup2(write, 3)
            os.closerange(4, MAX_FD)
            self.filter.apply(limits, self.base)
            os.write(3, CONFINED)
            for answer in work():
                view = memoryview(answer)
                while view:
                    view = view[os.write(3, view):]
            status = 0
        except MemoryError:
            status = OUT_OF_MEMORY
        except BaseException:
            status = FAILED
        finally:
            os._exit(status)

    def _collect(self, pidfd: int, read: int, wall_time: float, frames: int = 0) -> tuple[bytes, int, bytes]:
        chunks: list[bytes] = []
        size, cap = 0, ANSWER_BYTES * max(1, frames)
        stream, at = bytearray(), len(CONFINED)  # with frames: the output so far, the next frame's offset
        deadline = time.monotonic() + wall_time
        watch = [read, pidfd]
        how = None
        try:
            while watch:
                remaining = deadline - time.monotonic()
                ready = select.select(watch, [], [], remaining)[0] if remaining > 0 else []
                if not ready:
                    how = b"timeout"
                    break
                if read in ready:
                    chunk = os.read(read, 1 << 16)
                    if not chunk:
                        watch.remove(read)
                    else:
                        chunks.append(chunk)
                        size += len(chunk)
                        if size > cap + 1:
                            how = b"overflow"
                            break
                        if frames:
                            stream += chunk
                            ended, at = batch.advance(stream, at)
                            if ended:  # the next answer's time starts
                                deadline = time.monotonic() + wall_time
                if pidfd in ready:
                    watch.remove(pidfd)
                    if read in watch:  # the child ended: read what it left in the pipe
                        while chunk := os.read(read, 1 << 16):
                            chunks.append(chunk)
                            size += len(chunk)
                            if size > cap + 1:
                                how = b"overflow"
                                break
                        watch.remove(read)
                    if how:
                        break
            if how is not None:
                try:
                    signal.pidfd_send_signal(pidfd, signal.SIGKILL)
                except ProcessLookupError:
                    pass
            status = self.zygote.status()  # the zygote waits for it
        finally:
            os.close(pidfd)
        data = b"".join(chunks)
        if how is None:
            if not data.startswith(CONFINED):
                how, status = b"unconfined", os.waitstatus_to_exitcode(status)
            elif os.WIFSIGNALED(status):
                how, status = b"signal", os.WTERMSIG(status)
            else:
                how, status = b"exit", os.WEXITSTATUS(status)
        elif how == b"timeout" and not data.startswith(CONFINED):
            how = b"unconfined"
        return how, status, data[len(CONFINED):] if data.startswith(CONFINED) else b""

    def serve(self, inp, out) -> int:
        from ..execution import Limits

        runtime = self.runtime
        while True:
            header = inp.readline()
            if not header:
                return 0
            request = json.loads(header)
            limits = Limits(*request["limits"])
            rows, cols, semantics = request["rows"], request["cols"], request["semantics"]
            mode = request.get("mode")
            self.place(request.get("cpu"))
            breach = mode == "breach"
            items = [inp.readline() for _ in range(request["items"])]
            if mode in ("gold", "answer"):  # one chunk in one child (batch.py)
                for how, status, answer in batch.run(self, items, rows, cols, limits, semantics):
                    out.write(b"%s %d %s\n" % (how, status, base64.b64encode(answer)))
                out.flush()
                continue
            for item in items:
                if breach and not self.breach:
                    how, status, answer = b"unconfined", 0, b""  # never runs: this template is not the tests'
                elif breach:
                    how, status, answer = self.fork(partial(self.breached, json.loads(item), rows, cols), limits)
                else:
                    how, status, answer = self.fork(partial(runtime.answer_item, item, rows, cols, limits, semantics),
                                                    limits)
                out.write(b"%s %d %s\n" % (how, status, base64.b64encode(answer)))
                out.flush()


def main(parent: int = 0, breach: bool = False, namespaces: bool = True) -> int:
    """The template's life: its namespaces (isolation.py), the seccomp filter (stdin's first line,
    BPF in base64), chunks of programs (the module docstring); "ready" names the namespaces up."""
    from . import confine, isolation

    isolation.fixed_layout()
    isolation.die_with_parent(parent)
    refused = isolation.enter_namespaces() if namespaces else "not asked for (a template without namespaces)"
    inp, out = sys.stdin.buffer, sys.stdout.buffer
    try:
        template = Template(base64.b64decode(inp.readline()), breach)
        template.start()  # its zygote, before the capabilities go (zygote.py)
        pid, walls = isolation.finish(refused)
    except (confine.Unconfinable, OSError) as exc:
        out.write(b"unconfined: " + str(exc).encode("ascii", "backslashreplace") + b"\n")
        out.flush()
        return 0
    out.write(b'"ready" ' + json.dumps({"pid": pid, "walls": walls}).encode() + b"\n")
    out.flush()
    return template.serve(inp, out)
