"""Nothing a program does makes its episode a harness fault (issue 42): a template that dies or
falls silent while it runs a program is judged by evidence (handle.TemplateHandle._judged). The program
runs again alone in a fresh template, whose answer is its verdict; failing there too, an empty
program runs in another: answered, the program brought its templates down (its own failure);
not answered, templates fail whatever runs (the harness's)."""
import pytest

from harness_helpers import answering_worker

from sartco.program import LocalSandbox, Limits
from sartco.program import feed, handle
from sartco.program.child import confine
from sartco.world import ErrorCode

E = ErrorCode
PUT = "put(board, 'nut', 'red', 0, 0)"


def _fake(monkeypatch, misbehave: str) -> LocalSandbox:
    """Stand-in templates that answer every program "ok, no board" unless `misbehave` ends them."""
    answering_worker(monkeypatch, misbehave)
    monkeypatch.setattr(handle, "SLACK", 0.5)
    return LocalSandbox(workers=1)


def _run(sandbox, programs, wall_time=1.0):
    try:
        return sandbox.execute_many(programs, limits=Limits(wall_time=wall_time), cache=False)
    finally:
        sandbox.close()


def test_a_program_that_brings_its_template_down_fails_itself(monkeypatch):
    sandbox = _fake(monkeypatch, "if 'BRING DOWN' in source: sys.exit(1)")
    before, down, after = _run(sandbox, ["x = 1", "x = 'BRING DOWN'", "x = 2"])
    assert before.ok and after.ok, (before, after)
    assert (down.ok, down.error) == (False, E.RUNTIME_ERROR), down
    assert down.message == "the program brought down the sandbox template that ran it, twice (an empty program did not)"


@pytest.mark.parametrize("workers", [1, 2])
def test_a_template_brought_down_in_the_middle_of_a_fed_call_takes_the_rest_on_a_fresh_one(monkeypatch, workers):
    """A call in parts (pool.py's feed): the template dies while programs taken from the feed are
    still queued behind the culprit; they run on its fresh successor, and more are taken after."""
    monkeypatch.setattr(feed, "FIRST", 8)
    sandbox = _fake(monkeypatch, "if 'BRING DOWN' in source: sys.exit(1)")
    sandbox.workers = workers
    programs = [f"x = {k}" for k in range(100)]
    programs[37] = "x = 'BRING DOWN'"
    results = _run(sandbox, programs)
    assert [k for k, ex in enumerate(results) if not ex.ok] == [37]
    assert results[37].error == E.RUNTIME_ERROR, results[37]


def test_a_program_whose_template_falls_silent_is_its_timeout(monkeypatch):
    sandbox = _fake(monkeypatch, "if 'FALL SILENT' in source: time.sleep(60)")
    silent, after = _run(sandbox, ["x = 'FALL SILENT'", "x = 2"], wall_time=0.5)
    assert (silent.ok, silent.error) == (False, E.TIMEOUT) and "stopped answering" in silent.message, silent
    assert after.ok, after


def test_a_template_that_dies_once_gives_the_programs_own_verdict(monkeypatch, tmp_path):
    flag = tmp_path / "died"
    sandbox = _fake(monkeypatch, f"if not os.path.exists({str(flag)!r}): open({str(flag)!r}, 'w').close(); sys.exit(1)")
    first, second = _run(sandbox, ["x = 1", "x = 2"])
    assert flag.exists()
    assert first.ok and second.ok, (first, second)


def test_templates_that_die_whatever_runs_are_the_harness(monkeypatch):
    sandbox = _fake(monkeypatch, "sys.exit(1)")
    for ex in _run(sandbox, ["x = 1", "x = 2"]):
        assert (ex.ok, ex.error, ex.message) == (False, E.HARNESS_ERROR, "the sandbox worker ended unexpectedly (status 1)")


def test_a_program_that_kills_its_real_template_is_its_own_failure(monkeypatch):
    """Both walls down against signals (no namespaces, a filter that wrongly allows kill): the
    breached program SIGKILLs its parent. That is the template's zygote (child/zygote.py); where
    the kernel lets the zygote have a pid namespace of its own, it is pid 1 there and the signal
    is ignored, else the zygote dies and the template with it. Either way the verdict is the
    program's own (runtime_error when the template fell), never the harness's, and the programs
    around it build their boards."""
    wrong = confine.RULES + tuple(confine.Rule(name, "a wrong rule", "any") for name in ("kill", "getppid"))
    monkeypatch.setattr(handle, "NAMESPACES", False)
    monkeypatch.setattr(handle, "_bpf", confine.compile_filter(wrong))
    sandbox = LocalSandbox(workers=1, breach=True)
    try:
        results = sandbox.execute_many([PUT, "import os, signal\nos.kill(os.getppid(), signal.SIGKILL)", PUT],
                                       limits=Limits(wall_time=5.0), cache=False, mode="breach")
    finally:
        sandbox.close()
    assert [(ex.ok, ex.error) for ex in results] in (
        [(True, None), (False, E.RUNTIME_ERROR), (True, None)], [(True, None), (True, None), (True, None)]), results
    assert results[2].cells == {"0:0": [["nut", "red"]]}
    assert results[1].ok or "brought down the sandbox template" in results[1].message


@pytest.mark.parametrize("mode", ["code", "breach"])
def test_with_the_walls_up_no_program_reaches_its_template(mode):
    """The same attack with the walls up: refused (EPERM), the template keeps serving."""
    sandbox = LocalSandbox(workers=1, breach=mode == "breach")
    try:
        sandbox.execute("x = 1")
        template = sandbox.pids()
        attack, after = sandbox.execute_many(["import os, signal\nos.kill(os.getppid(), signal.SIGKILL)", PUT],
                                             cache=False, mode=mode)
        assert sandbox.pids() == template
    finally:
        sandbox.close()
    assert attack.error in (E.RUNTIME_ERROR, E.FORBIDDEN) and after.ok, (attack, after)
