"""Where a program's CPU goes (issue 46): `sartco bench-execute --breakdown` prints it beside the floor,
and `sartco bench-reward` splits a reward's CPU by process (roles: the templates, their zygotes,
the programs' processes).

Each stage runs the corpus's programs in a fresh process pinned to one core, and counts the CPU
and the page faults of that process and of the children it reaped (os.times, getrusage), per
program:
  floor     a bare `python -S` that forks with libc's fork() and reaps; the child only _exit(0)s
  template  a template (child.template.Template: its imports, its frozen heap) that reads a
            program's line, has its zygote fork a child (child/zygote.py), waits and writes a
            line, as it does per program; the child only _exit(0)s
  walls     Template.fork of nothing: the child's descriptors, rlimits, seccomp filter and
            CONFINED, the template's pipe, pidfd and wait
  program   Template.fork of the program as the parent compiled it (runtime.answer_item): load
            the code, run it, check the board, write the answer, exit: the child as it runs now
  compiled in the child   the same, parsed, checked and compiled in the child (before issue 46)
  least     a confined child forked straight from the template: it forks with libc's fork, the
            program already in its memory (no zygote, no job sent, no clock, no pidfd); the child
            runs the same code as a template's (Template._child: descriptors, rlimits, filter,
            CONFINED, the program, its answer), the template reads the pipe to its end and reaps
            it. What a fresh confined process per program costs, less the zygote and the job
The parent's side is timed in the calling process (warm, no fork): compiled.prepare (parse,
check, instrument, compile, marshal) and verdict.decide (replay the answer's log on the parent's
board). A stage process (child/stages.py) runs as a template does (handle.ISOLATED,
PYTHONHASHSEED=0, a template's imports and no more) and reads its programs line by line, as a
template reads a chunk; stage "least" reads them all before its imports.
"""
from __future__ import annotations

import json
import os
import statistics
import subprocess
import sys
import time
from collections.abc import Iterator
from pathlib import Path

from sartco.settings import IMPORT_ROOT

from . import compiled
from .child.confine import compile_filter
from .handle import HASH_SEED, ISOLATED
from .pool import local
from .execution import Limits
from .verdict import decide

STAGES = ("floor", "template", "walls", "program", "compiled in the child", "least")
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
import os, sys
sys.path.insert(0, sys.argv[1])
os.sched_setaffinity(0, {int(sys.argv[3])})
from sartco.program.child.stages import stage
sys.exit(stage(sys.argv[2], sys.stdin.buffer, sys.stdout.buffer))
"""


def floor_command(n: int, core: int = 0) -> list[str]:
    return [sys.executable, "-S", "-c", _FLOOR, str(n), str(core)]


def floor(n: int, core: int = 0) -> tuple[float, float, int]:
    """Wall and CPU seconds and page faults of a bare `python -S` forking and reaping n children
    on one core (libc's fork(); each child only _exit(0)s)."""
    out = subprocess.run(floor_command(n, core), capture_output=True, text=True, check=True,
                         env={**os.environ, "PYTHONHASHSEED": HASH_SEED})
    wall, cpu, faults = out.stdout.split()
    return float(wall), float(cpu), int(faults)


def _walk(pids: list[int]) -> Iterator[tuple[int, list[str]]]:
    """(depth, /proc stat fields after the command) of each live process of `pids` (depth 0) and
    of their live descendants."""
    todo = [(0, pid) for pid in pids]
    while todo:
        depth, pid = todo.pop()
        try:
            fields = Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()
            yield depth, fields
            todo += [(depth + 1, int(kid)) for kid in Path(f"/proc/{pid}/task/{pid}/children").read_text().split()]
        except (OSError, IndexError, ValueError):
            pass


def usage(pids: list[int]) -> tuple[float, int]:
    """CPU seconds and page faults so far of the live processes `pids` and their live descendants
    (a template and its zygote), each with the children it reaped (from /proc: utime, stime,
    cutime, cstime; minflt, cminflt, majflt, cmajflt)."""
    cpu, faults, tick = 0.0, 0, os.sysconf("SC_CLK_TCK")
    for _, fields in _walk(pids):
        cpu += sum(map(int, fields[11:15])) / tick
        faults += sum(map(int, fields[7:11]))
    return cpu, faults


def roles(pids: list[int]) -> tuple[float, float, float]:
    """usage()'s CPU seconds of templates `pids` in three: the templates' own, their zygotes' own,
    and the programs' processes (every process below a zygote, live or reaped)."""
    parts, tick = [0.0, 0.0, 0.0], os.sysconf("SC_CLK_TCK")
    for depth, fields in _walk(pids):
        own, reaped = int(fields[11]) + int(fields[12]), int(fields[13]) + int(fields[14])
        parts[min(depth, 2)] += own / tick
        parts[min(depth + 1, 2)] += reaped / tick
    return parts[0], parts[1], parts[2]


def templates_cpu() -> float:
    """CPU seconds so far of this process's live local templates, their zygotes and the children
    they reaped: what getrusage's RUSAGE_CHILDREN never sees (a killed template's tree is not
    reaped by this process)."""
    return usage(local().pids())[0]


def templates_roles() -> tuple[float, float, float]:
    """templates_cpu() in three (roles): the templates', their zygotes' and the programs' processes'."""
    return roles(local().pids())


def stage_job(sources: list[str]) -> tuple[list[str], bytes]:
    """The programs that run (the parent compiles each; the refused ones never reach a child) and a
    stage process's input for them: the filter, then a line per program."""
    import base64

    items = [compiled.prepare(s, Limits()) for s in sources]
    kept = [(s, item) for s, item in zip(sources, items) if type(item) is bytes]
    return [s for s, _ in kept], base64.b64encode(compile_filter()) + b"\n" + b"".join(
        json.dumps([s, item.decode()]).encode() + b"\n" for s, item in kept if type(item) is bytes)


def stage_command(name: str, core: int = 0) -> list[str]:
    """The command of a stage process (its input: stage_job's; its environment: stage_env's)."""
    return [sys.executable, *ISOLATED, "-c", _STAGE, str(IMPORT_ROOT), name, str(core)]


def stage_env() -> dict[str, str]:
    return {k: v for k, v in os.environ.items() if not k.startswith("PYTHON")} | {"PYTHONHASHSEED": HASH_SEED}


def breakdown(sources: list[str], rounds: int = 3, core: int = 0) -> dict[str, float]:
    """Median CPU ms per program of each stage over `rounds` rounds (stages alternate within a
    round), and of the parent's compile and verdict."""
    import base64

    limits = Limits()
    sources, job = stage_job(sources)
    env = stage_env()
    seen: dict[str, list[float]] = {name: [] for name in (*STAGES, *(f"{s} faults" for s in STAGES),
                                                          "parent: compile", "parent: verdict")}
    for _ in range(rounds):
        _, cpu, faults = floor(len(sources), core)
        seen["floor"].append(cpu / len(sources) * 1e3)
        seen["floor faults"].append(faults / len(sources))
        answers: list[bytes] = []
        for name in STAGES[1:]:
            out = subprocess.run(stage_command(name, core), input=job, capture_output=True, check=True, env=env, cwd="/").stdout.splitlines()
            ms, faults = json.loads(out[-1])
            seen[name].append(ms)
            seen[name + " faults"].append(faults)
            if name == "program":
                answers = [base64.b64decode(a) for a in out[:-1]]
        cpu = time.process_time()
        for s in sources:
            compiled.prepare(s, limits)
        seen["parent: compile"].append((time.process_time() - cpu) / len(sources) * 1e3)
        cpu = time.process_time()
        for answer in answers:
            decide(b"exit", 0, answer, limits.wall_time)
        seen["parent: verdict"].append((time.process_time() - cpu) / len(sources) * 1e3)
    return {name: statistics.median(values) for name, values in seen.items()}
