"""`sartco bench-execute`: throughput of `sartco execute` against a bare process's fork, in one run.

All gold programs of ../shared/sartco-data/published (see sartco.published.gold: every total_code, every
dialogue editor, multi-turn dialogues cumulatively) go through `serve()`, the same JSON-lines
handler as `sartco execute` (in-process, bytes in, bytes out, with the gold board as target so
the comparison is paid for too), budgets on.

The floor (issue 46): a bare `python -S` that forks and reaps as many children as there are
programs (libc's fork(), each child only _exit(0)s), on one core, measured in the same run right
before each execute run. The ratio is execute's programs/s over the floor's children/s: 1.0 means
a fresh confined process per program (on the default two templates) at the price of one core's
bare forks. The modes:
- distinct (the headline): `sartco execute` as it runs (cache on) on each distinct source once:
  a cache that never hits, every program parsed, checked and compiled in the parent and run in
  its own forked, confined process, its put log replayed and compared here;
- cold: every program of the corpus with the cache off (the corpus repeats sources), with the
  default templates and with one;
- cached: `sartco execute` as it runs on the whole corpus, repeats run once.
Templates are restarted before each run and started before the clock. Each mode runs --repeat
times; the median ratio is printed (the machine may be shared: each ratio is taken against the
floor measured just before it), with the median programs/s and CPU per program (parent + templates
+ their children) beside it. bare compile() of the same sources is printed for the record.
`--breakdown` adds where a program's CPU goes (sartco.program.costs), stage by stage, beside
the floor, also medians of --repeat rounds on one core.
"""
from __future__ import annotations

import io
import json
import os
import statistics
import time
from pathlib import Path

from sartco.dataset import SHARED_DATA as DEFAULT_DATA
from sartco.errors import UserError
from sartco.program import costs, pool
from sartco.program import execute_many, shutdown
from sartco.program.pool import default_workers
from sartco.program.serve import serve
from sartco.program.walls import summary, walls
from sartco.published.files import require_data
from sartco.published.gold import gold_programs


TARGET_RATIO = 0.5  # execute (distinct programs, default templates) over the floor (issue 46)


def configure(parser) -> None:
    parser.add_argument("--data", type=Path, default=DEFAULT_DATA, help="the sartco-data folder (default: %(default)s)")
    parser.add_argument("--workers", type=int, default=None, help="worker processes (default min(2, CPUs))")
    parser.add_argument("--repeat", type=int, default=5,
                        help="runs per mode (default %(default)s); medians are printed")
    parser.add_argument("--modes", default="distinct,cold,cold1,cached",
                        help="which runs, comma-separated (default %(default)s)")
    parser.add_argument("--breakdown", action="store_true",
                        help="also where a program's CPU goes, stage by stage, beside the floor (on one core)")


def _compile_all(sources) -> tuple[float, float]:
    """Wall and CPU seconds of bare compile() over the sources."""
    start, cpu = time.perf_counter(), time.process_time()
    for source in sources:
        compile(source, "<program>", "exec", dont_inherit=True)
    return time.perf_counter() - start, time.process_time() - cpu


def _serve(payload: bytes, workers: int, cache: bool) -> tuple[float, float, list[dict]]:
    shutdown()
    # start the workers before the clock (distinct sources: equal ones all go to one worker)
    execute_many([f"x = {i}" for i in range(workers * pool.BATCH)], workers=workers)
    out = io.BytesIO()
    cpu = time.process_time() + costs.templates_cpu()
    start = time.perf_counter()
    serve(io.BytesIO(payload), out, workers=workers, cache=cache)
    elapsed = time.perf_counter() - start
    cpu = time.process_time() + costs.templates_cpu() - cpu
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
    payloads = {name: _payload(progs) for name, progs in corpora.items()}
    n = len(programs)
    print(f"{n} gold programs ({len(firsts)} distinct sources, {sum(len(p.code) for p in programs) / n:.0f} characters "
          f"on average), budgets on, {workers} template process(es) unless said otherwise; "
          f"load average {os.getloadavg()[0]:.1f} on {os.cpu_count()} CPUs")
    print(f"walls: {summary(walls())}")
    runs = {  # mode -> label, corpus, workers, cache
        "distinct": (f"distinct sources, {workers} template(s)", "distinct", workers, True),
        "cold": (f"cold, {workers} template(s), no cache", "all", workers, False),
        "cold1": ("cold, 1 template, no cache", "all", 1, False),
        "cached": (f"cached (repeats hit), {workers} t.", "all", workers, True),
    }
    chosen = [mode for mode in args.modes.split(",") if mode in runs and not (mode == "cold1" and workers == 1)]
    seen: dict[str, list[tuple[float, float, float]]] = {mode: [] for mode in chosen}  # ratio, programs/s, CPU us
    for _ in range(max(1, args.repeat)):
        for mode in chosen:
            label, corpus, w, cache = runs[mode]
            m = len(corpora[corpus])
            floor_wall, _, _ = costs.floor(m)
            elapsed, cpu, rows = _serve(payloads[corpus], w, cache)
            good = sum(1 for r in rows if r.get("es") == 1)
            if len(rows) != m or good != m:
                print(f"  {label}: only {good} of {m} programs built their gold board")
            seen[mode].append((floor_wall / elapsed, m / elapsed, cpu * 1e6 / m))
    floor_wall, floor_cpu, _ = costs.floor(len(firsts))
    print(f"    floor: a bare python -S forking {len(firsts)} children on one core: {len(firsts) / floor_wall:8.0f} "
          f"children/s ({floor_cpu * 1e6 / len(firsts):5.0f} us CPU each)")
    for mode in chosen:
        label, corpus, w, _ = runs[mode]
        ratio, rate, cpu = (statistics.median(v[k] for v in seen[mode]) for k in range(3))
        wall, _ = _compile_all([p.code for p in corpora[corpus]])
        print(f"  {'*' if mode == 'distinct' else ' '} execute {label:<36}{rate:8.0f} programs/s ({cpu:6.0f} us CPU each)"
              f"  ratio to the floor {ratio:.2f}   (compile() alone: {len(corpora[corpus]) / wall:6.0f}/s)")
    if "distinct" in seen:
        ratio = statistics.median(v[0] for v in seen["distinct"])
        print(f"  * headline: distinct programs, a fresh confined process each, {workers} template(s): ratio to the "
              f"floor {ratio:.2f} (target >= {TARGET_RATIO}: {'met' if ratio >= TARGET_RATIO else 'NOT met'}; "
              f"median of {len(seen['distinct'])}, each against the floor measured just before it)")
    if args.breakdown:
        parts = costs.breakdown([p.code for p in firsts.values()], rounds=max(1, args.repeat))
        print(f"  where a program's CPU goes (median of {max(1, args.repeat)} rounds, {len(firsts)} distinct programs, "
              f"one core; sartco.program.costs):")
        before = 0.0
        for name in costs.STAGES[:4]:
            print(f"    {name:<24}{parts[name]:6.2f} ms  (+{parts[name] - before:5.2f})  {parts[name + ' faults']:6.0f} page faults")
            before = parts[name]
        for name, said in (("compiled in the child", "before issue 46"),
                           ("least", "a confined child forked straight from a template, no zygote, no job sent")):
            print(f"    {name:<24}{parts[name]:6.2f} ms           {parts[name + ' faults']:6.0f} page faults  ({said})")
        for name in ("parent: compile", "parent: verdict"):
            print(f"    {name:<24}{parts[name]:6.2f} ms")
        most = 2 * parts["floor"] / (parts["least"] + parts["parent: compile"] + parts["parent: verdict"])
        print(f"  the most a fresh confined process per program allows on two cores: ratio to the floor {most:.2f} "
              f"(2 x floor / (least + the parent's compile and verdict))")
    print(f"  (load average {os.getloadavg()[0]:.1f} now)")
    shutdown()
    return 0
