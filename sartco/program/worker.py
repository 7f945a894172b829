"""The worker process: reads batches of programs, runs them one by one, answers line by line.

Protocol (lines of bytes):
  worker -> parent, once at start:  "ready"
  parent -> worker, per batch: a header {"limits": [...Limits fields...], "rows": R, "cols": C,
      "cache": bool, "mode": "code" | "line", "items": K}, then K item lines:
      mode "code": the source as a JSON string;
      mode "line": "<input line number> <raw input line of sartco execute>".
  worker -> parent, one line per item, flushed at once:
      mode "code": [ok, code, message, cells, puts]
      mode "line": the finished output line of `sartco execute` (see lines.py).
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


OUT_OF_MEMORY = 3  # exit status: the parent reports resource_limit for the current item


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
    from .lines import encode, handle
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
    while True:
        header = inp.readline()
        if not header:
            return 0
        request = json.loads(header)
        limits = Limits(*request["limits"])
        if limits.memory != memory:
            memory = limits.memory
            _limit(resource.RLIMIT_AS, base + memory)
        rows, cols, cache = request["rows"], request["cols"], request["cache"]

        def run_code(source):
            return run(source, rows, cols, limits, cache)[:4]

        # read the whole batch before answering: the parent writes it in one go, and answering
        # while it still writes could fill both pipes (deadlock)
        items = [inp.readline().rstrip(b"\n") for _ in range(request["items"])]
        for item in items:
            try:
                if request["mode"] == "code":
                    answer = encode(run(json.loads(item), rows, cols, limits, cache))
                else:
                    number, _, raw = item.partition(b" ")
                    answer = handle(int(number), raw, run_code)
            except MemoryError:  # outside the program's own run: give up, the parent reports it
                os._exit(OUT_OF_MEMORY)
            out.write(answer.encode("ascii") + b"\n")
            out.flush()
    return 0


if __name__ == "__main__":
    sys.exit(main())
