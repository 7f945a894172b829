"""Before/after of the sandbox in one run: another checkout's sartco.program and this one's, alternately.

    git worktree add /tmp/base 188cc2a; .venv/bin/python scripts/bench_pair.py /tmp/base [ROUNDS]

Each round runs, for each side in turn and in a fresh process that imports that side's sartco
(PYTHONPATH): the floor (a bare `python -S` forking and reaping as many children as there are
programs, on one core; sartco.program.costs's loop, inlined so that any side can run it), then
execute_many on the distinct gold programs (each source once, cache off, the default two
templates, started before the clock). Printed per round and side: programs/s, the ratio to the
floor measured just before it, CPU ms per program (parent + templates + their children) and the
page faults per program of the templates, their zygotes and their children; then the medians per side. Only
public interfaces are used (execute_many, pool.local().pids()), so a checkout from before issue
46 runs it too.
"""
from __future__ import annotations

import json
import os
import statistics
import subprocess
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent.parent
MEASURE = r"""
import ctypes, json, os, resource, sys, time
from pathlib import Path
from sartco.dataset import SHARED_DATA
from sartco.published.gold import gold_programs
from sartco.program import execute_many, pool, shutdown

firsts = {}
for p in gold_programs(SHARED_DATA):
    firsts.setdefault(p.code, p)
sources = list(firsts)
n = len(sources)
import subprocess
FLOOR = '''
import ctypes, os, sys
os.sched_setaffinity(0, {0})
fork = ctypes.PyDLL(None, use_errno=True).fork
start = os.times()
for _ in range(int(sys.argv[1])):
    pid = fork()
    if pid == 0:
        os._exit(0)
    os.waitpid(pid, 0)
print(os.times()[4] - start[4])
'''
floor = float(subprocess.run([sys.executable, "-S", "-c", FLOOR, str(n)], capture_output=True, text=True,
                             check=True).stdout)

def stats():  # the templates, their zygotes (issue 43) and what each reaped
    cpu, faults, todo = 0.0, 0, list(pool.local().pids())
    while todo:
        pid = todo.pop()
        fields = Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()
        cpu += sum(map(int, fields[11:15])) / os.sysconf("SC_CLK_TCK")
        faults += sum(map(int, fields[7:11]))
        todo += map(int, Path(f"/proc/{pid}/task/{pid}/children").read_text().split())
    return cpu + time.process_time(), faults

shutdown()
execute_many([f"x = {i}" for i in range(64)], workers=2, cache=False)
cpu, faults = stats()
start = time.perf_counter()
results = execute_many(sources, workers=2, cache=False)
elapsed = time.perf_counter() - start
cpu2, faults2 = stats()
assert all(r.ok for r in results), [r for r in results if not r.ok][:1]
print(json.dumps([n / elapsed, floor / elapsed, (cpu2 - cpu) / n * 1e3, (faults2 - faults) / n]))
shutdown()
"""


def main() -> int:
    base = Path(sys.argv[1]).resolve()
    rounds = int(sys.argv[2]) if len(sys.argv) > 2 else 3
    python = os.environ.get("PYTHON", str(HERE / ".venv/bin/python"))
    data = os.environ.get("SARTCO_DATA", str(HERE.parent / "shared/sartco-data"))
    seen: dict[str, list] = {"base": [], "this": []}
    for r in range(rounds):
        for name, side in (("base", base), ("this", HERE)):
            env = {**os.environ, "PYTHONPATH": str(side), "SARTCO_DATA": data}
            out = subprocess.run([python, "-c", MEASURE], capture_output=True, text=True, env=env, cwd=side)
            if out.returncode:
                print(out.stderr[-2000:])
                return 1
            rate, ratio, cpu, faults = json.loads(out.stdout.splitlines()[-1])
            seen[name].append((rate, ratio, cpu, faults))
            print(f"round {r + 1} {name} ({side}): {rate:6.0f} programs/s, ratio to the floor {ratio:.2f}, "
                  f"{cpu:.2f} ms CPU and {faults:.0f} page faults (templates and children) per program; "
                  f"load {os.getloadavg()[0]:.1f}")
    for name, values in seen.items():
        rate, ratio, cpu, faults = (statistics.median(v[k] for v in values) for k in range(4))
        print(f"median {name}: {rate:6.0f} programs/s, ratio to the floor {ratio:.2f}, {cpu:.2f} ms CPU, "
              f"{faults:.0f} page faults per program")
    return 0


if __name__ == "__main__":
    sys.exit(main())
