"""The kernel's walls, tested as if every Python-level check had fallen (issue 32).

`breached(source)` runs a source with Python's real builtins and none of the sandbox's checks
(child/template.py's mode "breach", only in a template started for these tests), inside the same walls
as every program: a fresh forked child, rlimits, the seccomp filter. The template imported
ctypes, socket, subprocess and threading beforehand, so a program attacks the kernel, not the
absence of a module. A program reports what it saw by raising (the message comes back) or by
putting pieces; the test also looks at the host (files, processes) afterwards.
"""
import json
import os

import pytest

from sartco.program import LocalSandbox, Limits, execute
from sartco.program.child.result import FORGED
from sartco.world import ErrorCode

E = ErrorCode


@pytest.fixture(scope="module")
def box():
    sandbox = LocalSandbox(workers=1, breach=True)
    yield sandbox
    sandbox.close()


def breached(box, source: str, limits: Limits | None = None):
    return box.execute_many([source], limits=limits or Limits(wall_time=10.0), mode="breach", cache=False)[0]


def _report(attempts: str) -> str:
    """A program that runs each attempt (a Python expression) and raises one line naming how each ended."""
    return ("seen = []\n"
            f"for name, attempt in {attempts}:\n"
            "    try:\n"
            "        attempt()\n"
            "        seen.append(name + ':done')\n"
            "    except BaseException as exc:\n"
            "        seen.append(name + ':' + type(exc).__name__ + ':' + str(getattr(exc, 'errno', '')))\n"
            "raise RuntimeError(' '.join(seen))\n")


def _seen(ex) -> dict:
    assert ex.error == E.RUNTIME_ERROR, ex
    text = ex.message.split("RuntimeError: ", 1)[1]
    return dict(item.split(":", 1) for item in text.split())


def test_no_file_is_opened_read_written_or_created(box, tmp_path):
    secret = tmp_path / "secret.txt"
    secret.write_text("the answer")
    made = tmp_path / "made.txt"
    attempts = [
        ("read", f"lambda: open({str(secret)!r}).read()"),
        ("osopen", f"lambda: os.open({str(secret)!r}, os.O_RDONLY)"),
        ("write", f"lambda: open({str(made)!r}, 'w').write('x')"),
        ("create", f"lambda: os.open({str(made)!r}, os.O_CREAT | os.O_WRONLY)"),
        ("mkdir", f"lambda: os.mkdir({str(tmp_path / 'dir')!r})"),
        ("remove", f"lambda: os.remove({str(secret)!r})"),
        ("rename", f"lambda: os.rename({str(secret)!r}, {str(made)!r})"),
        ("listdir", f"lambda: os.listdir({str(tmp_path)!r})"),
        ("stat", f"lambda: os.stat({str(secret)!r})"),
        ("libc", f"lambda: ctypes.CDLL(None).open({str(secret).encode()!r}, 0) >= 0 or 1 / 0"),
    ]
    pairs = "[" + ", ".join(f"({n!r}, {a})" for n, a in attempts) + "]"
    seen = _seen(breached(box, "import os, ctypes\n" + _report(pairs)))
    for name, _ in attempts:
        assert seen[name] in ("PermissionError:1", "ZeroDivisionError:"), (name, seen[name])
    assert secret.read_text() == "the answer" and not made.exists() and not (tmp_path / "dir").exists()


def test_no_socket_exec_process_thread_or_signal(box):
    parent = os.getpid()
    attempts = [
        ("socket", "lambda: socket.socket()"),
        ("unix", "lambda: socket.socket(socket.AF_UNIX)"),
        ("pair", "lambda: socket.socketpair()"),
        ("exec", "lambda: os.execv('/bin/true', ['true'])"),
        ("popen", "lambda: subprocess.run(['true'])"),
        ("fork", "lambda: os.fork()"),
        ("thread", "lambda: threading.Thread(target=print).start()"),
        ("killparent", f"lambda: os.kill({parent}, signal.SIGTERM)"),
        ("killtemplate", "lambda: os.kill(os.getppid(), signal.SIGKILL)"),
        ("killall", "lambda: os.kill(-1, signal.SIGKILL)"),
        ("pipe", "lambda: os.pipe()"),
        ("setrlimit", "lambda: resource.setrlimit(resource.RLIMIT_AS, (-1, -1))"),
    ]
    pairs = "[" + ", ".join(f"({n!r}, {a})" for n, a in attempts) + "]"
    seen = _seen(breached(box, "import os, signal, socket, subprocess, threading, resource\n" + _report(pairs)))
    for name, _ in attempts:
        assert not seen[name].startswith("done"), (name, seen[name])
    for name in ("socket", "unix", "pair", "exec", "fork", "killparent", "killtemplate", "killall", "pipe"):
        assert seen[name] == "PermissionError:1", (name, seen[name])
    assert seen["thread"].startswith("RuntimeError")  # can't start new thread
    # the template is alive: the next program runs in it
    after = breached(box, "put(board, 'nut', 'red', 0, 0)")
    assert after.ok and after.cells == {"0:0": [["nut", "red"]]}, after


def test_memory_is_capped_by_the_kernel(box):
    for source in ("x = bytearray(8 * 1024 ** 3)", "x = [0] * (2 * 1024 ** 3)", "import ctypes\nx = ctypes.create_string_buffer(4 * 1024 ** 3)"):
        ex = breached(box, source, Limits(memory=256 * 1024 ** 2, wall_time=20.0))
        assert (ex.ok, ex.error) == (False, E.RESOURCE_LIMIT), (source, ex)


def test_a_crash_and_an_exit_are_the_programs_never_the_harness(box):
    cases = {
        "import os\nos._exit(0)": E.RUNTIME_ERROR,
        "import os\nos._exit(3)": E.RESOURCE_LIMIT,  # the child's out-of-memory status: still the program's
        "import os\nos._exit(70)": E.RUNTIME_ERROR,
        "import ctypes\nctypes.string_at(0)": E.RUNTIME_ERROR,  # SIGSEGV
        "import os, signal\nos.kill(os.getpid(), signal.SIGKILL)": E.RUNTIME_ERROR,  # refused: a PermissionError
        "import os\nos.close(3)\nwhile True: pass": E.TIMEOUT,
        "import os\nos.write(3, b'x' * (8 << 20))": E.RESOURCE_LIMIT,
        "class Bad(Exception):\n    def __str__(self):\n        raise SystemExit(1)\nraise Bad()": E.RUNTIME_ERROR,
    }
    for source, code in cases.items():
        ex = breached(box, source, Limits(wall_time=2.0))
        assert (ex.ok, ex.error) == (False, code), (source, ex)


@pytest.mark.parametrize("answer,why", [
    ([True, None, "", 8, 8, ["screw", "purple", 0, 0]], "a colour put refuses"),
    ([True, None, "", 8, 8, ["screw", "red", 0, 0, "screw", "red", 0, 0]], "a screw on a screw"),
    ([True, None, "", 8, 8, ["nut", "red", 9, 0]], "a cell off the board"),
    ([True, None, "", 8, 8, ["nut", "red", True, 0]], "a coordinate that is not an int"),
    ([True, None, "", 100, 100, ["nut", "red", 0, 0]], "a board over the world's limits"),
    ([True, None, "", 8, 8, ["nut", "red"] + ["washer", "red", 1, 1] * 5], "a log that is not of fours"),
])
def test_a_forged_put_log_is_refused_by_the_parent(box, answer, why):
    source = f"import os\nos.write(3, {json.dumps(answer).encode()!r})\nos._exit(0)"
    ex = breached(box, source)
    assert not ex.ok and ex.error in (E.FORBIDDEN, E.RUNTIME_ERROR), (why, ex)
    if ex.error == E.FORBIDDEN:
        assert ex.message.startswith(FORGED), ex
    assert all(stack in ([["nut", "red"]], [["screw", "red"]]) for stack in ex.cells.values()), ex


@pytest.mark.parametrize("answer", [
    b"not json", b'[true, null, "", 8, 8, []] trailing', b'[true, "harness_error", "", 8, 8, []]',
    b'[false, "harness_error", "x", 8, 8, []]', b'[true, "no_such_code", "", 8, 8, []]', b'{"ok": true}',
    b'[1, null, "", 8, 8, []]', b"\xff\xfe",
])
def test_no_answer_makes_a_harness_error(box, answer):
    ex = breached(box, f"import os\nos.write(3, {answer!r})\nos._exit(0)")
    assert (ex.ok, ex.error) == (False, E.RUNTIME_ERROR), ex


def test_what_a_program_changes_is_absent_in_the_next(box):
    """World rules, put, typing, random, functools, the hash seed's table: all changed in one
    child; the next program, run normally, sees none of it."""
    attack = (
        "import sys, random, functools, typing\n"
        "import sartco.world.rules as rules, sartco.world.board as boards, sartco.program.child.runtime as runtime\n"
        "rules.check = lambda *a, **k: None\n"
        "boards.MAX_SIDE = 10 ** 6\n"
        "runtime.put = lambda *a: None\n"
        "random.seed(99)\nfunctools.reduce = None\ntyping.List = int\n"
        "for _ in range(6):\n    rules.put(board, 'screw', 'purple', 0, 0)\n"
    )
    first = breached(box, attack)
    assert first.error == E.FORBIDDEN and first.message.startswith(FORGED), first  # the parent refused the board
    honest = ("import random, functools\nfrom typing import List\n"
              "xs: List[int] = [random.randrange(8) for _ in range(3)]\n"
              "put(board, 'screw', 'red', functools.reduce(lambda a, b: a + b, xs) % 8, 0)\n"
              "put(board, 'screw', 'red', functools.reduce(lambda a, b: a + b, xs) % 8, 0)\n")
    expected = execute(honest)  # in the default sandbox, which never saw the attack
    again = box.execute_many([honest], cache=False)[0]
    assert (again.ok, again.error, again.cells) == (expected.ok, expected.error, expected.cells)
    assert expected.error == E.NOT_ON_TOP_OF_SCREW, expected  # the rules hold


def test_a_template_refuses_breach_mode_unless_started_for_it():
    sandbox = LocalSandbox(workers=1)
    try:
        ex = sandbox.execute_many(["x = 1"], mode="breach", cache=False)[0]
    finally:
        sandbox.close()
    assert ex.error == E.HARNESS_ERROR and "no program ran" in ex.message


def test_no_process_outlives_its_program(box):
    ex = breached(box, "import os\nraise RuntimeError(str(os.getpid()))")
    pid = int(ex.message.rsplit(" ", 1)[1])
    with pytest.raises(ProcessLookupError):
        os.kill(pid, 0)


def test_without_seccomp_nothing_runs(monkeypatch):
    from sartco.program import handle
    from sartco.program.child import confine

    def unusable():
        raise confine.Unconfinable("libseccomp is not usable (test)")

    monkeypatch.setattr(handle, "_bpf", None)
    monkeypatch.setattr(handle, "compile_filter", unusable)
    ex = _one_put_in_a_new_sandbox()
    assert (ex.ok, ex.error, ex.cells) == (False, E.HARNESS_ERROR, {})
    assert "cannot confine programs here" in ex.message and "libseccomp" in ex.message


def test_a_filter_that_does_not_hold_is_refused(monkeypatch):
    """A filter that allows everything: the template's self-test finds a file opened."""
    from sartco.program import handle

    allow_all = bytes([0x06, 0, 0, 0, 0, 0, 0xFF, 0x7F])  # BPF_RET | BPF_K, SECCOMP_RET_ALLOW
    monkeypatch.setattr(handle, "_bpf", allow_all)
    ex = _one_put_in_a_new_sandbox()
    assert (ex.ok, ex.error) == (False, E.HARNESS_ERROR) and "could open a file" in ex.message, ex


def _one_put_in_a_new_sandbox():
    sandbox = LocalSandbox(workers=1)
    try:
        return sandbox.execute("put(board, 'nut', 'red', 0, 0)")
    finally:
        sandbox.close()


@pytest.mark.parametrize("raised", ["SystemExit", "KeyboardInterrupt", "GeneratorExit", "BaseException"])
def test_a_message_that_raises_is_the_programs_failure(raised):
    """An exception whose __str__ raises a BaseException while its message is written ends the
    program's own process: the program's runtime_error, never harness_error."""
    source = (f"class Bad(Exception):\n    def __str__(self):\n        raise {raised}()\n"
              "put(board, 'nut', 'red', 0, 0)\nraise Bad()\n")
    ex = execute(source)
    assert not ex.ok and ex.error not in (E.HARNESS_ERROR, None), ex
