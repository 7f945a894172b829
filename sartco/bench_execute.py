"""`sartco bench-execute`: throughput of `sartco execute` on the gold corpus, and against bare compile().

All gold programs of ../shared/sartco-data/published (see sartco.published.gold: every total_code, every
dialogue editor, multi-turn dialogues cumulatively) go through `serve()`, the same JSON-lines
handler as `sartco execute` (in-process, bytes in, bytes out, with the gold board as target so
the comparison is paid for too), budgets on. In the same run the same sources go through bare
`compile(source, ...)`, the floor for anything that reads Python source. Printed: programs/s of
each and the ratio execute / compile (the target is >= 0.5).

The gold corpus repeats sources (the published variant files share code), so a figure with the
cache on (equal sources of a batch run once) mostly measures repeats. Hence the modes:
- cold (the headline): the cache off, every program run in its own forked, confined process:
  parsed, checked, instrumented, compiled, run there, its put log replayed and compared here;
  with the default templates and, for the record, with one (compile() uses one core; the
  templates' children use up to two, the parent reads, replays and compares meanwhile);
- distinct: `sartco execute` as it runs (cache on) on each distinct source once, against
  compile() of the same distinct sources: a cache that never hits;
- cached: `sartco execute` as it runs on the whole corpus, repeats run once.
Templates are restarted before each run and started before the clock. Each side
is timed --repeat times (compile() before and after each round of execute runs) and the best
time of each side is compared, as timeit does: the least disturbed run of each.
Wall-clock ratios are the headline; CPU per program (parent + templates + their children) is printed
beside them, because other processes on the machine slow the wall clock of the children more than
that of a single-threaded compile() loop.
"""
from __future__ import annotations

import io
import json
import os
import time
from pathlib import Path

from sartco.dataset import SHARED_DATA as DEFAULT_DATA
from sartco.errors import UserError
from sartco.program import pool
from sartco.program import execute_many, shutdown
from sartco.program.pool import default_workers
from sartco.program.serve import serve
from sartco.program.walls import summary, walls
from sartco.published.files import require_data
from sartco.published.gold import gold_programs


TARGET_PER_CORE = 1000  # programs/s per core, cold (issue 32)


def configure(parser) -> None:
    parser.add_argument("--data", type=Path, default=DEFAULT_DATA, help="the sartco-data folder (default: %(default)s)")
    parser.add_argument("--workers", type=int, default=None, help="worker processes (default min(2, CPUs))")
    parser.add_argument("--repeat", type=int, default=5,
                        help="runs per mode (default %(default)s); the best run of each side is compared")


def _compile_all(sources) -> tuple[float, float]:
    """Wall and CPU seconds of bare compile() over the sources."""
    start, cpu = time.perf_counter(), time.process_time()
    for source in sources:
        compile(source, "<program>", "exec", dont_inherit=True)
    return time.perf_counter() - start, time.process_time() - cpu


def _worker_cpu() -> float:
    """CPU seconds used so far by this process's live templates and the children they reaped
    (from /proc: utime, stime, cutime, cstime)."""
    total = 0.0
    for pid in pool.local().pids():
        try:
            fields = Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()
            total += sum(map(int, fields[11:15])) / os.sysconf("SC_CLK_TCK")
        except (OSError, IndexError, ValueError):
            pass
    return total


def _serve(payload: bytes, workers: int, cache: bool) -> tuple[float, float, list[dict]]:
    shutdown()
    # start the workers before the clock (distinct sources: equal ones all go to one worker)
    execute_many([f"x = {i}" for i in range(workers * pool.BATCH)], workers=workers)
    out = io.BytesIO()
    cpu = time.process_time() + _worker_cpu()
    start = time.perf_counter()
    serve(io.BytesIO(payload), out, workers=workers, cache=cache)
    elapsed = time.perf_counter() - start
    cpu = time.process_time() + _worker_cpu() - cpu
    return elapsed, cpu, [json.loads(line) for line in out.getvalue().splitlines()]


def _payload(programs) -> bytes:
    return "".join(
        json.dumps({"id": f"{p.file}/{p.sample}/{p.kind}", "code": p.code, "target": p.target}) + "\n"
        for p in programs
    ).encode()


def run(args) -> int:
    require_data(args.data / "published")
    if not (args.data / "published").is_dir():
        raise UserError(f"{args.data}/published: no such folder (give --data)")
    programs = list(gold_programs(args.data))
    if not programs:
        raise UserError(f"{args.data}/published: no gold programs found")
    workers = args.workers or default_workers()
    firsts = {}
    for p in programs:
        firsts.setdefault(p.code, p)
    corpora = {"all": programs, "distinct": list(firsts.values())}
    sources = {name: [p.code for p in progs] for name, progs in corpora.items()}
    payloads = {name: _payload(progs) for name, progs in corpora.items()}
    n = len(programs)
    print(f"{n} gold programs ({len(firsts)} distinct sources, {sum(map(len, sources['all'])) / n:.0f} characters "
          f"on average), budgets on, {workers} worker process(es) unless said otherwise")
    print(f"walls: {summary(walls())}")
    runs = [  # label, corpus, workers, cache
        (f"cold, {workers} worker(s), no cache", "all", workers, False),
        ("cold, 1 worker, no cache", "all", 1, False),
        (f"distinct sources, {workers} worker(s)", "distinct", workers, True),
        (f"cached (repeats hit), {workers} w.", "all", workers, True),
    ]
    if workers == 1:
        del runs[1]
    floors: dict[str, list[float]] = {name: [] for name in corpora}
    floor_cpu: dict[str, list[float]] = {name: [] for name in corpora}
    best: dict[str, tuple[float, float]] = {}

    def time_compile():
        for name, srcs in sources.items():
            wall, cpu = _compile_all(srcs)
            floors[name].append(wall)
            floor_cpu[name].append(cpu)

    for _ in range(max(1, args.repeat)):
        time_compile()
        for label, corpus, w, cache in runs:
            elapsed, cpu, rows = _serve(payloads[corpus], w, cache)
            m = len(corpora[corpus])
            good = sum(1 for r in rows if r.get("es") == 1)
            if len(rows) != m or good != m:
                print(f"  {label}: only {good} of {m} programs built their gold board")
            if label not in best or elapsed < best[label][0]:
                best[label] = (elapsed, cpu)
        time_compile()
    for name in corpora:
        m = len(corpora[name])
        floor, cpu = min(floors[name]), min(floor_cpu[name])
        print(f"    compile(), {name + ' sources':<31}{m / floor:8.0f} programs/s  ({floor * 1e6 / m:6.1f} us each, "
              f"{cpu * 1e6 / m:6.1f} us CPU)")
    for i, (label, corpus, w, cache) in enumerate(runs):
        m = len(corpora[corpus])
        floor, floor_c = min(floors[corpus]), min(floor_cpu[corpus])
        elapsed, cpu = best[label]
        print(f"  {'*' if i == 0 else ' '} execute {label:<33}{m / elapsed:8.0f} programs/s  "
              f"({elapsed * 1e6 / m:6.1f} us each, {cpu * 1e6 / m:6.1f} us CPU)  ratio to compile() {floor / elapsed:.2f}"
              f"  (CPU ratio {floor_c / cpu:.2f}, x{min(w, os.cpu_count() or 1)} cores {min(w, os.cpu_count() or 1) * floor_c / cpu:.2f})")
    elapsed = best[runs[0][0]][0]
    ratio = min(floors["all"]) / elapsed
    cores = min(workers, os.cpu_count() or 1)
    per_core = n / elapsed / cores
    print(f"  * headline: cold, {workers} template process(es), a fresh confined process per program, budgets on: "
          f"{n / elapsed:.0f} programs/s, {per_core:.0f} per core (target >= {TARGET_PER_CORE}: "
          f"{'met' if per_core >= TARGET_PER_CORE else 'NOT met'}); ratio to compile() {ratio:.2f}")
    print(f"  (ratio = compile() time / execute time, wall clock, of the same sources in the same run; CPU ratio = "
          f"compile() CPU / execute CPU of parent + workers, 'x2 cores' what that gives if the workers had the "
          f"cores to themselves; the load average was {os.getloadavg()[0]:.1f} on {os.cpu_count()} CPUs)")
    shutdown()
    return 0
