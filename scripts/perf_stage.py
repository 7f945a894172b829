"""Where a program's process spends its CPU, in the kernel and in user space: the floor and the
stage processes of `sartco bench-execute --breakdown` (sartco/program/costs.py), each run under
Linux's profiler (`perf record -e cpu-clock -g`, every process of the stage), their samples
sorted by what the CPU was doing (the first of these met on the sample's call chain):

  page faults     the kernel's fault handler: copy-on-write copies of the template's pages, fresh
                  zeroed pages, file pages mapped in
  fork            clone(): the new process, its copy of the page tables
  exit            exit(): the address space torn down
  seccomp         the filter loaded (its BPF compiled by the kernel's JIT)
  other kernel    the other syscalls (pipes, select, wait, rlimits, prctl, ...) and scheduling
  user            the Python interpreter and the libraries' own code

    .venv/bin/python scripts/perf_stage.py [--stages floor,template,walls,program] [--limit N]

perf needs to be installed (Debian's linux-perf) and allowed (root, or kernel.perf_event_paranoid
<= 1). The sampling slows every process a little: read the shares, and the CPU per program of
`sartco bench-execute --breakdown` beside them."""
from __future__ import annotations

import argparse
import collections
import subprocess
import sys
import tempfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from sartco.program import costs  # noqa: E402
from sartco.published.gold import gold_programs  # noqa: E402
from sartco.dataset import SHARED_DATA  # noqa: E402

GROUPS = ("page faults", "fork", "exit", "seccomp", "other kernel", "user")
CHAINS = (  # a sample's group: the first group whose symbol is on its call chain
    ("page faults", ("asm_exc_page_fault",)),
    ("fork", ("kernel_clone",)),
    ("exit", ("do_exit", "do_group_exit")),
    ("seccomp", ("do_seccomp",)),
)
FREQUENCY = 10_000  # samples per CPU second


def group_of(frames: list[tuple[str, str]]) -> str:
    """frames: (symbol, dso) from the leaf up."""
    symbols = {symbol for symbol, _ in frames}
    for name, marks in CHAINS:
        if symbols.intersection(marks):
            return name
    return "other kernel" if frames and frames[0][1] == "[kernel.kallsyms]" else "user"


def samples(data: Path) -> collections.Counter:
    script = subprocess.run(["perf", "script", "-i", str(data), "-F", "ip,sym,dso"], capture_output=True,
                            text=True, check=True).stdout
    counts: collections.Counter = collections.Counter()
    frames: list[tuple[str, str]] = []
    for line in script.splitlines() + [""]:
        parts = line.split()
        if not parts:
            if frames:
                counts[group_of(frames)] += 1
            frames = []
            continue
        dso = parts[-1].strip("()")
        frames.append((parts[1] if len(parts) > 2 else "", dso))
    return counts


def profile(command: list[str], stdin: bytes | None, env: dict | None, data: Path) -> collections.Counter:
    subprocess.run(["perf", "record", "-q", "-F", str(FREQUENCY), "-e", "cpu-clock", "-g", "-o", str(data), "--",
                    *command], input=stdin, capture_output=True, check=True, env=env, cwd="/")
    return samples(data)


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--stages", default="floor,template,walls,program")
    parser.add_argument("--limit", type=int, default=0, help="only the first N distinct gold programs")
    args = parser.parse_args()
    firsts: dict[str, None] = {}
    for program in gold_programs(SHARED_DATA):
        firsts.setdefault(program.code)
    sources, job = costs.stage_job(list(firsts)[:args.limit or None])
    n = len(sources)
    print(f"{n} distinct gold programs; CPU per program by what it was doing (perf, {FREQUENCY} samples/s)")
    print(f"{'stage':<10}" + "".join(f"{g:>14}" for g in GROUPS) + f"{'all':>10}")
    with tempfile.TemporaryDirectory() as tmp:
        for stage in args.stages.split(","):
            data = Path(tmp) / f"{stage}.data"
            if stage == "floor":
                counts = profile(costs.floor_command(n), None, None, data)
            else:
                counts = profile(costs.stage_command(stage), job, costs.stage_env(), data)
            total = sum(counts.values())
            ms = {g: counts[g] / FREQUENCY / n * 1e3 for g in GROUPS}
            print(f"{stage:<10}" + "".join(f"{ms[g]:7.3f} ({100 * counts[g] / max(1, total):3.0f}%)" for g in GROUPS)
                  + f"{total / FREQUENCY / n * 1e3:8.3f} ms")
    return 0


if __name__ == "__main__":
    sys.exit(main())
