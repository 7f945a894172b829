"""costs.templates_cpu: the CPU of every program's process is counted where benchmarks read it
(`sartco bench-execute`, `sartco bench-reward`). getrusage(RUSAGE_CHILDREN) never sees it: a
program's process is reaped by its zygote, and a template's tree is killed, not reaped, by this
process."""
import time

from sartco.clock import cpu_seconds
from sartco.program import execute_many, shutdown
from sartco.program.costs import templates_cpu

WORK = "sum(range(400000))"


def test_templates_cpu_counts_the_programs_processes():
    execute_many(["x = 1"] * 4, workers=2, cache=False)   # the templates up
    try:
        own = time.process_time()
        for _ in range(100):
            eval(WORK)
        own = time.process_time() - own   # the same work in this process
        templates, here = templates_cpu(), cpu_seconds()
        results = execute_many([f"x = {WORK} + {i}" for i in range(100)], workers=2, cache=False)
        assert all(r.ok for r in results)
        assert templates_cpu() - templates >= 0.5 * own   # at least half: the programs' own loops
        assert cpu_seconds() - here < 0.5 * own   # and not in this process or its reaped children
    finally:
        shutdown()
