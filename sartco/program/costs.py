"""Where a program's CPU goes (issue 46): `sartco bench-execute --breakdown` prints it beside the floor.

Each stage forks one child per program of the corpus in a fresh process pinned to one core, and
counts the CPU of that process and of the children it reaped (os.times), per program:
  floor     a bare `python -S` that forks with libc's fork() and reaps; the child only _exit(0)s
  template  the same loop in a template (worker.Template: its imports, its frozen heap)
  walls     Template.fork of nothing: the child's descriptors, rlimits, seccomp filter and CONFINED,
            the template's pipe, pidfd and wait
  program   Template.fork of the program as the parent compiled it (runtime.answer_item): load the
            code, run it, replay the board, write the answer, exit: the child as it runs today
  compiled in the child (before issue 46): the same, parsed, checked and compiled in the child
The parent's side is timed in the calling process (warm, no fork): compiled.prepare (parse,
check, instrument, compile, marshal) and verdict.decide (replay the answer's log on the parent's
board). A template's stage process runs as a template does (driver.ISOLATED, PYTHONHASHSEED=0).
"""
from __future__ import annotations

import json
import os
import resource
import statistics
import subprocess
import sys
import time

from sartco.settings import IMPORT_ROOT

from . import compiled
from .child.confine import compile_filter
from .handle import HASH_SEED, ISOLATED
from .execution import MODULE, Limits
from .verdict import decide

STAGES = ("floor", "template", "walls", "program", "compiled in the child")
_FLOOR = """
import ctypes, os, resource, sys
os.sched_setaffinity(0, {int(sys.argv[2])})
fork, n = ctypes.PyDLL(None, use_errno=True).fork, int(sys.argv[1])
faults = lambda: sum(r.ru_minflt + r.ru_majflt for r in map(resource.getrusage, (resource.RUSAGE_SELF,
                                                                                 resource.RUSAGE_CHILDREN)))
start, before = os.times(), faults()
for _ in range(n):
    pid = fork()
    if pid == 0:
        os._exit(0)
    os.waitpid(pid, 0)
t = os.times()
print(t[4] - start[4], sum(t[:4]) - sum(start[:4]), faults() - before)
"""
_STAGE = """
import base64, json, os, sys
sys.path.insert(0, sys.argv[1])
os.sched_setaffinity(0, {int(sys.argv[3])})
from sartco.program.costs import stage
print(json.dumps(stage(sys.argv[2], json.loads(sys.stdin.read()))))
"""


def floor(n: int, core: int = 0) -> tuple[float, float, int]:
    """Wall and CPU seconds and page faults of a bare `python -S` forking and reaping n children
    on one core (libc's fork(); each child only _exit(0)s)."""
    out = subprocess.run([sys.executable, "-S", "-c", _FLOOR, str(n), str(core)], capture_output=True, text=True,
                         check=True, env={**os.environ, "PYTHONHASHSEED": HASH_SEED})
    wall, cpu, faults = out.stdout.split()
    return float(wall), float(cpu), int(faults)


def stage(name: str, job: dict) -> tuple[float, float, list[str]]:
    """In a stage process: CPU ms and page faults per program of one stage over job's programs,
    and the answers of stage "program" (base64)."""
    import base64

    from .child.template import Template

    template = Template(base64.b64decode(job["bpf"]))
    runtime, limits = template.runtime, Limits()
    sources, items = job["sources"], [item.encode() for item in job["items"]]
    fork = template._fork

    def bare(_):
        pid = fork()
        if pid == 0:
            os._exit(0)
        os.waitpid(pid, 0)

    answers: list[str] = []

    def program(k):
        how, status, answer = template.fork(lambda: runtime.answer_item(items[k], 8, 8, limits, MODULE), limits)
        answers.append(base64.b64encode(answer).decode())

    run = {
        "template": bare,
        "walls": lambda k: template.fork(lambda: b"", limits),
        "program": program,
        "compiled in the child": lambda k: template.fork(
            lambda: runtime.answer(runtime.compile_program(sources[k], limits), 8, 8, limits, MODULE), limits),
    }[name]
    start, faults = os.times(), _faults()
    for k in range(len(sources)):
        run(k)
    end, faults = os.times(), _faults() - faults
    return (sum(end[:4]) - sum(start[:4])) / len(sources) * 1e3, faults / len(sources), answers


def _faults() -> int:
    """Page faults (minor and major) of this process and of the children it reaped."""
    return sum(r.ru_minflt + r.ru_majflt for r in map(resource.getrusage, (resource.RUSAGE_SELF,
                                                                            resource.RUSAGE_CHILDREN)))


def breakdown(sources: list[str], rounds: int = 3, core: int = 0) -> dict[str, float]:
    """Median CPU ms per program of each stage over `rounds` rounds (stages alternate within a
    round), and of the parent's compile and verdict."""
    import base64

    limits = Limits()
    items = [compiled.prepare(s, 8, 8, limits) for s in sources]
    keep = [k for k, item in enumerate(items) if type(item) is bytes]  # the programs that run
    sources = [sources[k] for k in keep]
    job = json.dumps({"bpf": base64.b64encode(compile_filter()).decode(), "sources": sources,
                      "items": [items[k].decode() for k in keep]})
    env = {k: v for k, v in os.environ.items() if not k.startswith("PYTHON")} | {"PYTHONHASHSEED": HASH_SEED}
    seen: dict[str, list[float]] = {name: [] for name in (*STAGES, *(f"{s} faults" for s in STAGES),
                                                          "parent: compile", "parent: verdict")}
    for _ in range(rounds):
        _, cpu, faults = floor(len(sources), core)
        seen["floor"].append(cpu / len(sources) * 1e3)
        seen["floor faults"].append(faults / len(sources))
        answers: list[bytes] = []
        for name in STAGES[1:]:
            out = subprocess.run([sys.executable, *ISOLATED, "-c", _STAGE, str(IMPORT_ROOT), name, str(core)],
                                 input=job, capture_output=True, text=True, check=True, env=env, cwd="/")
            ms, faults, made = json.loads(out.stdout)
            seen[name].append(ms)
            seen[name + " faults"].append(faults)
            answers += [base64.b64decode(a) for a in made]
        cpu = time.process_time()
        for s in sources:
            compiled.prepare(s, 8, 8, limits)
        seen["parent: compile"].append((time.process_time() - cpu) / len(sources) * 1e3)
        cpu = time.process_time()
        for answer in answers:
            decide(b"exit", 0, answer, limits.wall_time)
        seen["parent: verdict"].append((time.process_time() - cpu) / len(sources) * 1e3)
    return {name: statistics.median(values) for name, values in seen.items()}
