"""The runtime's own failures never become a verdict they do not deserve: a MemoryError while
compiling is resource_limit, a MemoryError or an internal error while reading the board is never
`ok`, messages come out clean, a dead child is named, a crash is named as a crash, and the
checker stays linear. These run runtime.compile_program / runtime.run in this process (the
child's code, without the child), with the failures injected."""
import time

import pytest

from sartco.program import Limits, execute, verdict
from sartco.program.child import runtime
from sartco.program.check.instrument import prepare
from sartco.program.execution import clean
from sartco.world import ErrorCode

E = ErrorCode
L = Limits()


def test_memory_error_while_compiling_is_the_programs_resource_limit(monkeypatch):
    source = "put(board, 'nut', 'red', 0, 0)"
    calls = []

    def flaky(text, heads=None):
        calls.append(text)
        if len(calls) == 1:
            raise MemoryError
        return prepare(text, heads)

    monkeypatch.setattr(runtime, "prepare", flaky)
    first = runtime.compile_program(source, L)
    assert first[1] == E.RESOURCE_LIMIT
    second = runtime.compile_program(source, L)
    assert second[1] is None
    assert runtime.run(second, 8, 8, L)[:4] == [True, None, "", {"0:0": [["nut", "red"]]}]


def test_internal_compile_error_is_named(monkeypatch):
    def broken(text):
        raise AssertionError("compiler bug")

    monkeypatch.setattr(runtime, "prepare", broken)
    result = runtime.compile_program("x = 1", L)
    assert result[1] == E.HARNESS_ERROR and "internal error" in result[2]


@pytest.mark.parametrize("failure,code", [(MemoryError, E.RESOURCE_LIMIT), (RuntimeError, E.HARNESS_ERROR)])
def test_failure_while_reading_the_board_is_never_ok(monkeypatch, failure, code):
    def checked(board):
        raise failure

    monkeypatch.setattr(runtime, "checked", checked)
    ok, error, message, got, puts = runtime.run(runtime.compile_program("put(board, 'nut', 'red', 0, 0)", L), 8, 8, L)
    assert (ok, error, got) == (False, code, {})
    assert message


@pytest.mark.parametrize("program,code", [
    ("while True:\n    pass", E.TIMEOUT),
    ("x = 'a' * 10**9", E.RESOURCE_LIMIT),
    ("def f(n):\n    return f(n + 1)\nf(0)", E.RESOURCE_LIMIT),
])
def test_budget_stops_end_the_program(program, code):
    assert runtime.run(runtime.compile_program(program, L), 8, 8, Limits(steps=10_000))[1] == code


@pytest.mark.parametrize("program", [
    "put(**{'\\ud800': 1})",
    "raise ValueError('a\\x00b\\x1b[31mc\\u202ed\\ndone')",
    "d = {}\nx = d['\\udc80\\x07']",
])
def test_messages_are_clean(program):
    message = runtime.run(runtime.compile_program(program, L), 8, 8, L)[2]
    assert message and message.isprintable()
    message.encode("utf-8")


def test_clean():
    assert clean("plain text: (1, 2)") == "plain text: (1, 2)"
    # escaped, not dropped: each unsafe character is shown as its Python escape
    assert clean("a\ud800b\tc\r\nd\x00e\u202ef é ✓") == "a\\ud800b c  d\\x00e\\u202ef é ✓"
    assert clean(clean("a\ud800\x1b")) == clean("a\ud800\x1b")


@pytest.mark.parametrize("status,code,word", [
    (-11, E.RUNTIME_ERROR, "SIGSEGV"), (-6, E.RUNTIME_ERROR, "SIGABRT"), (-9, E.RESOURCE_LIMIT, "SIGKILL"),
    (3, E.RESOURCE_LIMIT, "memory"),
    # a program's process is the program's: however it ends, never the harness's fault (issue 32)
    (1, E.RUNTIME_ERROR, "status 1"), (0, E.RUNTIME_ERROR, "status 0"),
])
def test_a_dead_child_is_named(status, code, word):
    ex = verdict.died(status)
    assert (ex.ok, ex.error) == (False, code) and word in ex.message


def test_a_crash_is_reported_as_a_crash():
    ex = execute("x = [1]\nfor i in range(300000):\n    x = map(abs, x)\ny = list(x)")
    assert (ex.ok, ex.error) == (False, E.RUNTIME_ERROR) and "crashed" in ex.message and "SIGSEGV" in ex.message


def test_checker_is_linear_in_the_program_size():
    """A 100 KB list display (the case that was quadratic): checked and compiled like any program.
    The times are printed, not asserted (the machine is shared)."""
    for n in (5_000, 20_000):
        source = "cells = [" + "(1, 2), " * n + "]\nput(board, 'nut', 'red', len(cells) % 8, 0)"
        start = time.perf_counter()
        compile(source, "<p>", "exec")
        bare = time.perf_counter() - start
        start = time.perf_counter()
        code = prepare(source)
        checked = time.perf_counter() - start
        print(f"{len(source)} characters: compile() {bare * 1e3:.0f} ms, check + compile {checked * 1e3:.0f} ms "
              f"(ratio {checked / bare:.1f})")
        ex = execute(source, limits=Limits(source=200_000))
        assert ex.ok and ex.cells == {f"{n % 8}:0": [["nut", "red"]]}, ex.message
        assert code is not None
