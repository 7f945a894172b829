"""costs.templates_cpu: the CPU of every program's process is counted where benchmarks read it
(`sartco bench-execute`, `sartco bench-reward`), and costs.templates_roles puts it where it was
spent (`sartco bench-reward`'s last line). getrusage(RUSAGE_CHILDREN) never sees it: a
program's process is reaped by its zygote, and a template's tree is killed, not reaped, by this
process. And the breakdown's stages "program" and "least" run the programs they are timed on."""
import base64
import json
import subprocess
import time

from sartco.clock import cpu_seconds
from sartco.program import execute_many, shutdown
from sartco.program import costs
from sartco.program.costs import templates_cpu, templates_roles

WORK = "sum(range(400000))"


def test_templates_cpu_counts_the_programs_processes():
    execute_many(["x = 1"] * 4, workers=2, cache=False)   # the templates up
    try:
        own = time.process_time()
        for _ in range(100):
            eval(WORK)
        own = time.process_time() - own   # the same work in this process
        templates, roles, here = templates_cpu(), templates_roles(), cpu_seconds()
        results = execute_many([f"x = {WORK} + {i}" for i in range(100)], workers=2, cache=False)
        assert all(r.ok for r in results)
        assert templates_cpu() - templates >= 0.5 * own   # at least half: the programs' own loops
        assert cpu_seconds() - here < 0.5 * own   # and not in this process or its reaped children
        # in its parts: the loops ran in the programs' processes, not in a template or its zygote
        template, zygote, programs = (b - a for a, b in zip(roles, templates_roles()))
        assert programs >= 0.5 * own and template + zygote < 0.5 * own, (template, zygote, programs, own)
        assert abs(sum(templates_roles()) - templates_cpu()) < 0.015   # the parts of one whole
    finally:
        shutdown()


def test_the_least_stage_answers_as_the_program_stage():
    sources = ["put(board, 'screw', 'red', 0, 0)", "for x in range(3):\n    put(board, 'nut', 'blue', x, 1)",
               "put(board, 'screw', 'pink', 0, 0)", "x = 1 / 0"]
    kept, job = costs.stage_job(sources)
    assert kept == sources
    answers = {}
    for name in ("program", "least"):
        done = subprocess.run(costs.stage_command(name), input=job, capture_output=True, env=costs.stage_env(),
                              cwd="/", timeout=120)
        assert done.returncode == 0, done.stderr
        lines = done.stdout.splitlines()
        ms, faults = json.loads(lines[-1])
        assert ms > 0 and faults > 0
        answers[name] = [json.loads(base64.b64decode(line)) for line in lines[:-1]]
    assert answers["least"] == answers["program"]
    assert [a[0] for a in answers["least"]] == [True, True, False, False]   # each ran: two built, two failed
    assert answers["least"][1][-1] == ["nut", "blue", 0, 1, "nut", "blue", 1, 1, "nut", "blue", 2, 1]
