"""The worker pool under batches: programs compiled ahead, runaways killed, shares balanced.

A worker compiles each chunk of a batch ahead before running it (child/template.py); a worker killed
before it answered the first program of a chunk may have been compiling any of them, so the
parent runs the rest again, each compiled at its own turn. These tests pin down that every
program still gets its own exact result, in input order.
"""
import os

import pytest

from sartco.program import Limits, execute_many, handle, pool
from sartco.world import ErrorCode

RUNAWAY = "x = sum(sum(range(10**6)) for i in range(10**6))"  # a loop in C code: only a kill stops it


def _benign(i: int) -> str:
    return f"put(board, 'nut', 'red', {i % 8}, {i // 8 % 8})\nx = {i}"


@pytest.fixture
def small_chunks(monkeypatch):
    monkeypatch.setattr(handle, "CHUNK", 4)
    pool.shutdown()
    yield
    pool.shutdown()


def test_runaways_at_and_inside_chunks_are_blamed_exactly(small_chunks):
    # chunk starts with CHUNK 4: items 0, 4, 8; runaways at 0 (a chunk compiled ahead), 4 (after the
    # first kill: compiled at its own turn) and 6 (inside a chunk)
    programs = [RUNAWAY if i in (0, 4, 6) else _benign(i) for i in range(10)]
    results = execute_many(programs, limits=Limits(wall_time=0.5), workers=1, cache=False)
    assert len(results) == 10
    for i, ex in enumerate(results):
        if i in (0, 4, 6):
            assert (ex.ok, ex.error) == (False, ErrorCode.TIMEOUT), (i, ex.message)
        else:
            assert ex.ok, (i, ex.message)
            assert ex.cells == {f"{i % 8}:{i // 8 % 8}": [["nut", "red"]]}


def test_a_compile_that_overruns_blames_its_own_program(small_chunks):
    """Compiling 100,000 lines takes about a second: far beyond the wall time, while the worker
    compiles the chunk ahead. The kill comes before any answer of the chunk, so the chunk runs
    again program by program: the benign program first is not blamed, the slow one is."""
    slow = "x = 1\n" * 100_000
    results = execute_many([_benign(0), slow, _benign(2)], limits=Limits(wall_time=0.25, source=10**6),
                           workers=1, cache=False)
    assert results[0].ok and results[0].cells == {"0:0": [["nut", "red"]]}, results[0].message
    assert (results[1].ok, results[1].error) == (False, ErrorCode.TIMEOUT)
    assert results[2].ok, results[2].message


def test_failures_compiled_ahead_stay_with_their_program(small_chunks):
    programs = ["put(board, 'nut', 'red', 0, 0", "import os", "x" * 200, _benign(3),
                "put(board, 'screw', 'red', 1, 1)\nput(board, 'nut', 'red', 1, 1)", _benign(5)]
    results = execute_many(programs, limits=Limits(source=100), workers=1, cache=False)
    assert [r.error for r in results] == [
        ErrorCode.SYNTAX_ERROR, ErrorCode.FORBIDDEN, ErrorCode.RESOURCE_LIMIT, None,
        ErrorCode.NOT_ON_TOP_OF_SCREW, None]
    assert results[4].cells == {"1:1": [["screw", "red"]]}  # the board so far, of its own program


def test_two_workers_without_cache_answer_in_order():
    pool.shutdown()
    # sizes vary a lot, so the balanced shares are far from alternating
    programs = [_benign(i) + "\n" + "y = 1\n" * (i % 17) * 20 for i in range(300)]
    results = execute_many(programs, workers=2, cache=False)
    assert all(r.ok for r in results)
    assert [r.cells for r in results] == [{f"{i % 8}:{i // 8 % 8}": [["nut", "red"]]} for i in range(300)]
    pool.shutdown()


@pytest.fixture
def counted(monkeypatch):
    """A fresh LocalSandbox and the number of programs each of its calls sent to the templates."""
    box = pool.LocalSandbox()
    sent: list[int] = []
    real = pool.dispatch

    def counting(*args):
        ran = real(*args)  # an Execution for each program the templates ran
        sent.append(len(ran))
        return ran

    monkeypatch.setattr(pool, "dispatch", counting)
    yield box, sent
    box.close()


def test_a_repeated_program_runs_once_until_the_sandbox_is_closed(counted):
    """The memo of verdicts: a program seen before (same board size, limits, semantics) is not
    run again, and gets an equal Execution of its own; close() forgets it."""
    box, sent = counted
    first = box.execute_many([_benign(1), _benign(2)])
    again = box.execute_many([_benign(2), _benign(1), _benign(3)])
    assert sent == [2, 1]
    assert (again[0], again[1]) == (first[1], first[0]) and again[0].cells is not first[1].cells
    again[0].cells.clear()  # a caller's change reaches no other caller
    assert box.execute_many([_benign(2)])[0] == first[1]
    box.execute_many([_benign(1)], 8, 9)  # another board size: run
    box.execute_many([_benign(1)], cache=False)  # no cache: run
    assert sent == [2, 1, 1, 1]
    box.close()
    box.execute_many([_benign(1)])
    assert sent == [2, 1, 1, 1, 1]


def test_verdicts_that_depend_on_the_machine_are_not_kept(counted):
    box, sent = counted
    limits = Limits(wall_time=0.3)
    for _ in range(2):
        [ex] = box.execute_many([RUNAWAY], limits=limits)
        assert ex.error in (ErrorCode.TIMEOUT, ErrorCode.RESOURCE_LIMIT)
    assert sent == [1, 1]


def _tree(root: int) -> list[int]:
    """root and every process under it."""
    children: dict[int, list[int]] = {}
    for entry in os.listdir("/proc"):
        try:
            with open(f"/proc/{entry}/stat") as f:
                children.setdefault(int(f.read().rsplit(")", 1)[1].split()[1]), []).append(int(entry))
        except (OSError, ValueError):
            pass
    found, todo = [], [root]
    while todo:
        found.append(todo.pop())
        todo += children.get(found[-1], [])
    return found


def _cpus_of(pid: int) -> str:
    with open(f"/proc/{pid}/status") as f:
        return next(line.split()[1] for line in f if line.startswith("Cpus_allowed_list:"))


@pytest.mark.skipif(not 2 <= len(os.sched_getaffinity(0)) <= 4, reason="needs 2 to 4 CPUs")
def test_a_call_on_as_many_templates_as_cpus_runs_each_on_a_cpu_of_its_own():
    """pool.pinned: while a call runs on as many templates as this process's CPUs, each template,
    its zygote and so every child of theirs run on one CPU, another for each template; a call on
    fewer templates leaves them on any CPU again."""
    cpus = sorted(os.sched_getaffinity(0))
    every = f"{cpus[0]}-{cpus[-1]}" if cpus == list(range(cpus[0], cpus[-1] + 1)) else ",".join(map(str, cpus))
    assert pool.pinned(len(cpus) + 1) == [None] * (len(cpus) + 1) and pool.pinned(len(cpus)) == cpus
    box = pool.LocalSandbox(workers=len(cpus))
    try:
        results = box.execute_many([_benign(i) for i in range(64 * len(cpus))], cache=False)
        assert all(ex.ok for ex in results)
        # under the process started (it only waits): the template (pid 1 of its namespace), its zygote
        held = sorted([_cpus_of(pid) for pid in _tree(t.proc.pid)[1:]] for t in box._templates)
        assert min(map(len, held)) >= 2
        assert [set(tree) for tree in held] == [{str(cpu)} for cpu in cpus]
        assert box.execute_many([_benign(1) + "\nz = 0"], cache=False)[0].ok  # one template
        again = [{_cpus_of(pid) for pid in _tree(t.proc.pid)[1:]} for t in box._templates]
    finally:
        box.close()
    assert {every} in again  # the template that ran it, and its zygote: any CPU again
