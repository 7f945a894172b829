"""`sartco bench-execute`: throughput of `sartco execute` on the gold corpus against bare compile().

All gold programs of ../shared/sartco-data/published (see gold.py: every total_code, every
dialogue editor, multi-turn dialogues cumulatively) go through `serve()`, the same JSON-lines
handler as `sartco execute` (in-process, bytes in, bytes out, with the gold board as target so
the comparison is paid for too), budgets on. In the same run the same sources go through bare
`compile(source, ...)`, the floor for anything that reads Python source. Printed: programs/s of
both and their ratio (execute / compile; the target is >= 0.5).

Two execute modes are measured:
- default: as `sartco execute` runs, workers keep a cache of checked code objects keyed by the
  exact source text (safe: the verdict and the code object depend on nothing else; budgets are
  enforced at run time). Workers are restarted before the run, so the cache starts empty and
  only repeats within the corpus hit it (the published variant files repeat sources).
- cold: the cache off, every program parsed, checked, instrumented and compiled.
Worker start-up is excluded (workers are started before the clock); compile() is timed before
and after the execute runs and averaged, to be fair to both under a drifting machine load.
"""
from __future__ import annotations

import io
import json
import os
import time
from pathlib import Path

from sartco.cli import UserError

from .cli import serve
from .gold import DEFAULT_DATA, gold_programs
from . import pool
from .pool import default_workers, execute_many, shutdown


def configure(parser) -> None:
    parser.add_argument("--data", type=Path, default=DEFAULT_DATA, help="the sartco-data folder (default: %(default)s)")
    parser.add_argument("--workers", type=int, default=None, help="worker processes (default min(2, CPUs))")
    parser.add_argument("--repeat", type=int, default=1, help="runs per mode; the best is reported")


def _compile_all(sources) -> float:
    start = time.perf_counter()
    for source in sources:
        compile(source, "<program>", "exec", dont_inherit=True)
    return time.perf_counter() - start


def _worker_cpu() -> float:
    """CPU seconds used so far by this process's live workers (from /proc)."""
    total = 0.0
    for worker in pool._workers:
        if worker.proc is not None:
            try:
                fields = Path(f"/proc/{worker.proc.pid}/stat").read_text().rsplit(")", 1)[1].split()
                total += (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")
            except (OSError, IndexError, ValueError):
                pass
    return total


def _serve(payload: bytes, workers: int, cache: bool) -> tuple[float, float, list[dict]]:
    shutdown()
    execute_many(["pass"] * workers * pool.BATCH, workers=workers)  # start the workers before the clock
    out = io.BytesIO()
    cpu = time.process_time() + _worker_cpu()
    start = time.perf_counter()
    serve(io.BytesIO(payload), out, workers=workers, cache=cache)
    elapsed = time.perf_counter() - start
    cpu = time.process_time() + _worker_cpu() - cpu
    return elapsed, cpu, [json.loads(line) for line in out.getvalue().splitlines()]


def run(args) -> int:
    if not (args.data / "published").is_dir():
        raise UserError(f"{args.data}/published: no such folder (give --data)")
    programs = list(gold_programs(args.data))
    if not programs:
        raise UserError(f"{args.data}/published: no gold programs found")
    workers = args.workers or default_workers()
    sources = [p.code for p in programs]
    payload = "".join(
        json.dumps({"id": f"{p.file}/{p.sample}/{p.kind}", "code": p.code, "target": p.target}) + "\n"
        for p in programs
    ).encode()
    n = len(programs)
    print(f"{n} gold programs ({len(set(sources))} distinct sources, {sum(map(len, sources)) / n:.0f} characters "
          f"on average), {workers} worker process(es), budgets on")
    compile_times, modes = [], {"default (code cache)": True, "cold (no cache)": False}
    best: dict[str, tuple[float, float]] = {}
    for _ in range(max(1, args.repeat)):
        compile_times.append(_compile_all(sources))
        for name, cache in modes.items():
            elapsed, cpu, rows = _serve(payload, workers, cache)
            good = sum(1 for r in rows if r.get("es") == 1)
            if len(rows) != n or good != n:
                print(f"  {name}: only {good} of {n} programs built their gold board")
            if name not in best or elapsed < best[name][0]:
                best[name] = (elapsed, cpu)
        compile_times.append(_compile_all(sources))
    floor = sum(compile_times) / len(compile_times)
    print(f"  compile()                    {n / floor:8.0f} programs/s  ({floor * 1e6 / n:6.1f} us each)")
    for name, (elapsed, cpu) in best.items():
        print(f"  execute {name:<21}{n / elapsed:8.0f} programs/s  ({elapsed * 1e6 / n:6.1f} us each, "
              f"{cpu * 1e6 / n:6.1f} us CPU)  ratio to compile() {floor / elapsed:.2f}")
    print(f"  (wall-clock ratios; the load average was {os.getloadavg()[0]:.1f} on {os.cpu_count()} CPUs)")
    shutdown()
    return 0
