"""The worker process: reads batches of programs, runs them one by one, answers line by line.

Protocol (lines of bytes):
  worker -> parent, once at start:  "ready"
  parent -> worker, per batch: a header {"limits": [...Limits fields...], "rows": R, "cols": C,
      "cache": bool, "mode": "code" | "line", "items": K, "ahead": bool}, then K item lines:
      mode "code": the source as a JSON string;
      mode "line": "<input line number> <raw input line of sartco execute>".
  worker -> parent, one line per item, flushed at once:
      mode "code": [ok, code, message, cells, puts]
      mode "line": the finished output line of `sartco execute` (see lines.py).
The parent times each answer and kills the worker when one is late (a loop in C code cannot be
stopped any other way). The worker never outlives the parent: it exits when its stdin closes,
and the kernel kills it when the parent dies (PR_SET_PDEATHSIG), even inside a long C loop.

A worker that must not run another program (runtime.SPOILED after a budget stop, a MemoryError
or an internal error, or resident memory more than RETIRE_BYTES above its start after a program,
e.g. a reference cycle the program left behind) writes that
program's answer with a leading "!" and exits: the parent passes the answer on and sends the
rest of the batch to a fresh worker. So no program starts in a worker that a previous one
filled, and nothing a failure left behind (caches, cycles) is seen again.
With "ahead" (and K > 1) the worker first parses and compiles the batch's programs, for at most
AHEAD_SHARE of a wall time, then runs them one by one: the parser and compiler stay warm in the
CPU caches, about 5 % less work per program than alternating compiling with running. Each
program is still compiled on its own (no code is shared between items unless "cache" says so).

Hardening at start: RLIMIT_AS (raised to base + Limits.memory per batch), no core files, no
file may grow (RLIMIT_FSIZE 0), no new processes (RLIMIT_NPROC 0; ignored for root).
"""
from __future__ import annotations

import gc
import json
import os
import resource
import sys
import time


OUT_OF_MEMORY = 3  # exit status: the parent reports resource_limit for the current item
RETIRED = b"!"  # the first byte of the last answer of a worker that retires (the parent then replaces it)
RETIRE_BYTES = 64 * 1024 * 1024  # resident memory growth after which a worker retires
PR_SET_PDEATHSIG = 1
AHEAD_SHARE = 0.1  # of Limits.wall_time: the longest a worker compiles a batch ahead


def _vm_bytes() -> int:
    with open("/proc/self/statm") as f:
        return int(f.read().split()[0]) * os.sysconf("SC_PAGE_SIZE")


def _limit(kind, soft):
    try:
        _, hard = resource.getrlimit(kind)
        if hard != resource.RLIM_INFINITY and soft > hard:
            soft = hard
        resource.setrlimit(kind, (soft, hard))
    except (ValueError, OSError):
        pass


def _die_with_parent(parent: int) -> None:
    """SIGKILL when the thread that started this worker (driver.py's spawner) ends."""
    import ctypes
    import signal

    try:
        ctypes.CDLL(None, use_errno=True).prctl(PR_SET_PDEATHSIG, signal.SIGKILL, 0, 0, 0)
    except (OSError, AttributeError):  # not Linux: the stdin pipe still ends the worker
        pass
    if parent and os.getppid() != parent:  # the parent died before prctl
        os._exit(0)


def _resident_meter():
    """A function giving this process's resident memory in bytes now: one pread() of
    /proc/self/statm (a few microseconds). Not getrusage's peak: after exec that includes the
    parent's peak, which may be far above anything this worker holds."""
    page = os.sysconf("SC_PAGE_SIZE")
    try:
        fd = os.open("/proc/self/statm", os.O_RDONLY | os.O_CLOEXEC)
    except OSError:  # not Linux: only runtime.SPOILED retires a worker
        return lambda: 0
    return lambda: int(os.pread(fd, 128, 0).split()[1]) * page


def main(parent: int = 0) -> int:
    from . import runtime
    from .lines import encode, finish, parse_line
    from .execution import Limits
    from .runtime import compile_program, run

    _die_with_parent(parent)

    for kind in (resource.RLIMIT_CORE, resource.RLIMIT_FSIZE, resource.RLIMIT_NPROC):
        _limit(kind, 0)
    gc.freeze()  # startup objects are never collected: cheaper collections later
    base = _vm_bytes()
    resident = _resident_meter()
    retire_at = resident() + RETIRE_BYTES
    memory = None
    inp, out = sys.stdin.buffer, sys.stdout.buffer
    out.write(b'"ready"\n')
    out.flush()
    while True:
        header = inp.readline()
        if not header:
            return 0
        request = json.loads(header)
        limits = Limits(*request["limits"])
        if limits.memory != memory:
            memory = limits.memory
            _limit(resource.RLIMIT_AS, base + memory)
        rows, cols, cache, mode = request["rows"], request["cols"], request["cache"], request["mode"]
        semantics = request["semantics"]

        def prepare(item: bytes) -> tuple:
            """(the item's input, its compile_program result or None): everything before running."""
            if mode == "code":
                source = json.loads(item)
                return source, compile_program(source, limits, cache)
            number, _, raw = item.partition(b" ")
            number = int(number)
            parsed = parse_line(number, raw, check_target=False)
            return (number, parsed), None if parsed[1] is None else compile_program(parsed[1], limits, cache)

        def answer(job: tuple) -> str:
            given, compiled = job
            if mode == "code":
                return encode(run(compiled, rows, cols, limits, semantics, given))
            return finish(*given, lambda: run(compiled, rows, cols, limits)[:4])

        # read the whole batch before answering: its programs are compiled ahead, and the parent
        # may still be writing the next one
        items = [inp.readline().rstrip(b"\n") for _ in range(request["items"])]
        jobs: list = []
        try:
            if request["ahead"] and len(items) > 1:
                # compile ahead while the parser and compiler are warm in the CPU caches (about 5 %
                # less work than alternating with running), for at most AHEAD_SHARE of a wall time
                stop = time.monotonic() + AHEAD_SHARE * limits.wall_time
                for item in items:
                    jobs.append(prepare(item))
                    if time.monotonic() > stop:
                        break
            for k, item in enumerate(items):
                if k < len(jobs):
                    job, jobs[k] = jobs[k], None
                else:
                    job = prepare(item)
                text = answer(job).encode("ascii")
                if runtime.SPOILED or resident() > retire_at:
                    out.write(RETIRED + text + b"\n")
                    out.flush()
                    os._exit(0)
                out.write(text + b"\n")
                out.flush()
        except MemoryError:  # outside the program's own run: give up, the parent reports it
            os._exit(OUT_OF_MEMORY)
    return 0


if __name__ == "__main__":
    sys.exit(main(int(sys.argv[1]) if len(sys.argv) > 1 else 0))
