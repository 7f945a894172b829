"""The worker process: reads batches of programs, runs them one by one, answers line by line.

Protocol (JSON lines, ASCII only):
  worker -> parent, once at start:  "ready"
  parent -> worker, one line per batch: {"limits": [...Limits fields...], "rows": R, "cols": C,
                                          "cache": bool, "programs": [source, ...]}
  worker -> parent, one line per program, flushed at once: [ok, code, message, cells, puts]
The parent times each answer and kills the worker when one is late (a loop in C code cannot be
stopped any other way); the worker exits when its stdin closes, so it never outlives the parent.

Hardening at start: RLIMIT_AS (raised to base + Limits.memory per batch), no core files, no
file may grow (RLIMIT_FSIZE 0), no new processes (RLIMIT_NPROC 0; ignored for root).
"""
from __future__ import annotations

import gc
import json
import os
import resource
import sys


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


def main() -> int:
    from .records import Limits
    from .runtime import run

    for kind in (resource.RLIMIT_CORE, resource.RLIMIT_FSIZE, resource.RLIMIT_NPROC):
        _limit(kind, 0)
    gc.freeze()  # startup objects are never collected: cheaper collections later
    base = _vm_bytes()
    memory = None
    inp, out = sys.stdin.buffer, sys.stdout.buffer
    out.write(b'"ready"\n')
    out.flush()
    dumps = json.dumps
    for line in inp:
        request = json.loads(line)
        limits = Limits(*request["limits"])
        if limits.memory != memory:
            memory = limits.memory
            _limit(resource.RLIMIT_AS, base + memory)
        rows, cols, cache = request["rows"], request["cols"], request["cache"]
        for source in request["programs"]:
            try:
                answer = dumps(run(source, rows, cols, limits, cache))
            except MemoryError:
                answer = dumps([False, "resource_limit", "out of memory", {}, 0])
            out.write(answer.encode("ascii") + b"\n")
            out.flush()
    return 0


if __name__ == "__main__":
    sys.exit(main())
