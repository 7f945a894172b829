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
import signal
import socket
import subprocess
import time

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
    assert ex.error == E.RUNTIME_ERROR, ex
    template = box.pids()[0]
    with open(f"/proc/{template}/task/{template}/children") as f:
        zygotes = f.read().split()  # the template's one child is its zygote (child/zygote.py), which forks programs'
    assert len(zygotes) == 1
    with open(f"/proc/{zygotes[0]}/task/{zygotes[0]}/children") as f:
        assert f.read().split() == []


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


# -- issue 42: signals out, secrets in, the namespaces; each probe in three sandboxes --------------
# "both": the walls as they are; "seccomp": layer 1 alone (no namespaces); "namespaces": layer 2
# alone, behind a filter that wrongly allows the calls of every route (signals, fcntl, sockets).
WRONGLY_ALLOWED = ("kill", "tkill", "tgkill", "rt_sigqueueinfo", "pidfd_open", "pidfd_send_signal", "fcntl",
                   "getppid", "socket", "connect", "bind", "sendto")
F_SETOWN, F_SETSIG, F_GETFL, F_SETFL, F_SETOWN_EX, O_ASYNC = 8, 10, 3, 4, 15, 0x2000
PROBE = """import ctypes, json, os, signal, socket
libc = ctypes.CDLL(None, use_errno=True)
libc.syscall.restype = ctypes.c_long
class Owner(ctypes.Structure):
    _fields_ = [("type", ctypes.c_int), ("pid", ctypes.c_int)]
def c(result):
    return "ok" if result >= 0 else "errno" + str(ctypes.get_errno())
VICTIM, GROUP, TEMPLATE = {victim}, {group}, {template}
seen = {{}}
"""


def _walls_up(box) -> bool:
    template = box.templates(1)[0]
    return bool(template.walls) and all(up for _, up, _ in template.walls)


@pytest.fixture(scope="module", params=["both", "seccomp", "namespaces"])
def walled(request):
    from sartco.program import handle
    from sartco.program.child import confine

    with pytest.MonkeyPatch.context() as patch:
        if request.param == "seccomp":
            patch.setattr(handle, "NAMESPACES", False)
        if request.param == "namespaces":
            wrong = confine.RULES + tuple(confine.Rule(name, "a wrong rule", "any") for name in WRONGLY_ALLOWED)
            patch.setattr(handle, "_bpf", confine.compile_filter(wrong))
        sandbox = LocalSandbox(workers=1, breach=True)
        sandbox.execute_many(["x = 1"], cache=False)  # the template starts with the patches in place
        if request.param != "seccomp" and not _walls_up(sandbox):
            sandbox.close()
            pytest.skip("the kernel refuses namespaces here (the seccomp-only sandbox is tested)")
        yield request.param, sandbox
        sandbox.close()


@pytest.fixture
def victim():
    """A sacrificial process of the user, leader of its own process group."""
    proc = subprocess.Popen(["sleep", "600"], start_new_session=True)
    yield proc
    proc.kill()
    proc.wait()


def _probe(walled, victim, body: str):
    """Run a breached program (PROBE + body, which fills `seen`); afterwards the victim lives, the
    same template serves, and an honest program builds its board. Returns `seen`."""
    kind, box = walled
    template = box.pids()[0]
    source = PROBE.format(victim=victim.pid, group=victim.pid, template=template) + body + \
        "raise RuntimeError(json.dumps(seen))\n"
    ex = breached(box, source)
    time.sleep(0.2)  # a signal the template's read of the answer raised has arrived
    assert victim.poll() is None, (kind, ex)
    assert box.pids() == [template], (kind, ex)
    after = box.execute_many(["put(board, 'nut', 'red', 0, 0)"], cache=False)[0]
    assert after.ok and after.cells == {"0:0": [["nut", "red"]]}, (kind, after)
    assert ex.error == E.RUNTIME_ERROR and "RuntimeError: " in ex.message, (kind, ex)
    return json.loads(ex.message.split("RuntimeError: ", 1)[1])


ROUTES = {  # how the answer pipe (3) gets its owner: the kernel signals the owner when the template reads
    "F_SETOWN pid": "libc.fcntl(3, {F_SETOWN}, VICTIM)",
    "F_SETOWN group": "libc.fcntl(3, {F_SETOWN}, -GROUP)",
    "F_SETOWN template": "libc.fcntl(3, {F_SETOWN}, TEMPLATE)",
    "F_SETOWN pid 1": "libc.fcntl(3, {F_SETOWN}, 1)",
    "F_SETOWN parent": "libc.fcntl(3, {F_SETOWN}, os.getppid())",
    "F_SETOWN_EX pid": "libc.fcntl(3, {F_SETOWN_EX}, ctypes.byref(Owner(1, VICTIM)))",
    "F_SETOWN_EX group": "libc.fcntl(3, {F_SETOWN_EX}, ctypes.byref(Owner(2, GROUP)))",
    "F_SETOWN_EX tid": "libc.fcntl(3, {F_SETOWN_EX}, ctypes.byref(Owner(0, VICTIM)))",
}


@pytest.mark.parametrize("route", list(ROUTES))
@pytest.mark.parametrize("signal_number", [signal.SIGKILL, 0])  # 0: the default, SIGIO, which ends a process
def test_no_signal_out_through_fcntl(walled, victim, route, signal_number):
    own = ROUTES[route].format(F_SETOWN=F_SETOWN, F_SETOWN_EX=F_SETOWN_EX)
    seen = _probe(walled, victim, (
        f"seen['own'] = c({own})\n"
        f"seen['sig'] = c(libc.fcntl(3, {F_SETSIG}, {int(signal_number)}))\n"
        f"seen['async'] = c(libc.fcntl(3, {F_SETFL}, libc.fcntl(3, {F_GETFL}) | {O_ASYNC}))\n"))
    if walled[0] != "namespaces":
        assert seen == {"own": "errno1", "sig": "errno1", "async": "errno1"}, seen


KILLS = {
    "kill pid": "c(libc.kill(VICTIM, signal.SIGKILL))",
    "kill group": "c(libc.kill(-GROUP, signal.SIGKILL))",
    "kill template": "c(libc.kill(TEMPLATE, signal.SIGKILL))",
    "kill parent": "c(libc.kill(os.getppid(), signal.SIGKILL))",
    "kill 1": "c(libc.kill(1, signal.SIGKILL))",
    "term 1": "c(libc.kill(1, signal.SIGTERM))",
    "int 1": "c(libc.kill(1, signal.SIGINT))",
    "tgkill": "c(libc.syscall(234, VICTIM, VICTIM, signal.SIGKILL))",
    "sigqueue": "c(libc.syscall(129, VICTIM, signal.SIGKILL, (ctypes.c_int * 32)(signal.SIGKILL, 0, -1)))",
    "pidfd": "c(libc.syscall(424, libc.syscall(434, VICTIM, 0), signal.SIGKILL, None, 0))",
}


def test_no_signal_out_by_pid_or_group(walled, victim):
    seen = _probe(walled, victim, "".join(f"seen[{name!r}] = {call}\n" for name, call in KILLS.items()))
    if walled[0] != "namespaces":
        assert set(seen.values()) == {"errno1"}, seen


def test_kill_everything_reaches_nothing_in_the_namespaces(walled, victim):
    """kill(-1) signals every process the caller may signal but itself and pid 1: in the pid namespace, none (ESRCH)
    (guarded: it runs only where the child's parent is pid 1, i.e. inside a pid namespace)."""
    if walled[0] != "namespaces":
        pytest.skip("kill is refused by the filter (test_no_socket_exec_process_thread_or_signal)")
    seen = _probe(walled, victim, "seen['parent'] = os.getppid()\n"
                                  "if seen['parent'] == 1:\n    seen['all'] = c(libc.kill(-1, signal.SIGKILL))\n")
    assert seen == {"parent": 1, "all": "errno3"}, seen  # ESRCH: no process it could signal


def test_no_network_and_no_host_socket(walled, victim):
    """A listener on the host's loopback and an abstract unix socket: unreachable."""
    listener = socket.socket()
    listener.bind(("127.0.0.1", 0))
    listener.listen(1)
    abstract = socket.socket(socket.AF_UNIX)
    name = f"\0sartco-test-{os.getpid()}"
    abstract.bind(name)
    abstract.listen(1)
    try:
        seen = _probe(walled, victim, (
            "os.close(0)  # room for one descriptor (the rlimit allows 4)\n"
            "def attempt(family, address):\n"
            "    try:\n        s = socket.socket(family)\n    except OSError as exc:\n        return 'socket' + str(exc.errno)\n"
            "    try:\n        s.connect(address)\n        return 'connected'\n"
            "    except OSError as exc:\n        return 'connect' + str(exc.errno)\n"
            "    finally:\n        s.close()\n"
            f"seen['tcp'] = attempt(socket.AF_INET, ('127.0.0.1', {listener.getsockname()[1]}))\n"
            f"seen['unix'] = attempt(socket.AF_UNIX, {name!r})\n"))
    finally:
        listener.close()
        abstract.close()
    assert "connected" not in seen.values(), seen
    if walled[0] != "namespaces":
        assert set(seen.values()) == {"socket1"}, seen
    else:  # the socket is made, but the namespace's loopback is down and it has none of the host's sockets
        assert seen == {"tcp": "connect101", "unix": "connect111"}, seen


def test_no_executable_memory_and_no_other_abi(walled, victim):
    """mmap/mprotect refuse PROT_EXEC (no code of the program's own); the x32 ABI kills the process."""
    seen = _probe(walled, victim, (
        "libc.mmap.restype = ctypes.c_void_p\n"
        "libc.mmap.argtypes = (ctypes.c_void_p, ctypes.c_size_t, ctypes.c_int, ctypes.c_int, ctypes.c_int, ctypes.c_long)\n"
        "page = libc.mmap(None, 4096, 7, 0x22, -1, 0)\n"
        "seen['mmap exec'] = 'errno' + str(ctypes.get_errno()) if page in (None, 2 ** 64 - 1) else 'ok'\n"
        "page = libc.mmap(None, 4096, 3, 0x22, -1, 0)\n"
        "seen['mmap'] = 'ok' if page not in (None, 2 ** 64 - 1) else 'failed'\n"
        "seen['mprotect exec'] = c(libc.mprotect(ctypes.c_void_p(page), 4096, 7))\n"))
    assert seen["mmap"] == "ok", seen
    if walled[0] != "namespaces":
        assert (seen["mmap exec"], seen["mprotect exec"]) == ("errno1", "errno1"), seen
    kind, box = walled
    template = box.pids()[0]
    x32 = breached(box, "import ctypes\nctypes.CDLL(None).syscall(0x40000000 | 257, -100, b'/etc/passwd', 0)\n"
                        "raise RuntimeError('the x32 call returned')")
    assert (x32.error, x32.message) == (E.RUNTIME_ERROR, "the program crashed its process (SIGSYS)"), x32
    assert box.pids() == [template] and victim.poll() is None


SECRETS = {"OPENAI_API_KEY": "sk-planted-7f3a9c41e2", "HF_TOKEN": "hf_planted_5b8d20c6aa", "SARTCO_SECRET": "planted-0d9e4f"}


def _memory(pid: int) -> bytes:
    """Every readable byte of a process's memory (what a program's child, its fork, could read)."""
    chunks = []
    with open(f"/proc/{pid}/maps") as maps, open(f"/proc/{pid}/mem", "rb", 0) as mem:
        for line in maps:
            span, perms = line.split()[:2]
            start, end = (int(x, 16) for x in span.split("-"))
            if perms[0] == "r" and not line.rstrip().endswith("[vvar]"):
                try:
                    mem.seek(start)
                    chunks.append(mem.read(end - start))
                except OSError:
                    pass
    return b"\0".join(chunks)


def test_no_secret_of_the_user_in_a_programs_process(monkeypatch):
    """Secrets planted in the parent's environment are nowhere in the template (its environ,
    argv, memory) nor in what a breached child reads of its own environment."""
    for name, value in SECRETS.items():
        monkeypatch.setenv(name, value)
    sandbox = LocalSandbox(workers=1, breach=True)
    try:
        ex = sandbox.execute_many([
            "import ctypes, os\n"
            "environ = ctypes.POINTER(ctypes.c_char_p).in_dll(ctypes.CDLL(None), 'environ')\n"
            "raw, k = [], 0\n"
            "while environ[k]:\n    raw.append(environ[k].decode())\n    k += 1\n"
            "raise RuntimeError(repr((dict(os.environ), raw)))\n"], mode="breach", cache=False)[0]
        template = sandbox.templates(1)[0]
        pids = [template.pid, template.proc.pid]  # the template, and where namespaces hold, its parent
        seen = [open(f"/proc/{pid}/{part}", "rb").read() for pid in set(pids) for part in ("environ", "cmdline")]
        seen += [_memory(pid) for pid in set(pids)]
    finally:
        sandbox.close()
    environment, raw = eval(ex.message.split("RuntimeError: ", 1)[1])
    assert set(environment) <= {"PYTHONHASHSEED", "PYTHONUTF8", "LC_CTYPE"}, environment
    assert sorted(raw) == sorted(f"{k}={v}" for k, v in environment.items())
    assert all(b"PYTHONHASHSEED=0" in blob for blob in seen[-len(set(pids)):])  # the scan reads what is there
    for value in SECRETS.values():
        assert value not in ex.message
        assert not any(value.encode() in blob for blob in seen), value


def test_the_template_sees_no_host_file_or_process():
    """With the namespaces up, the template's root is empty and read-only, it is pid 1, it has no
    capability, and its walls are reported."""
    from sartco.program import walls
    from sartco.program.walls import summary

    sandbox = LocalSandbox(workers=1)
    try:
        sandbox.execute("x = 1")
        template = sandbox.templates(1)[0]
        if not all(up for _, up, _ in template.walls):
            pytest.skip(f"the kernel refuses namespaces here: {template.walls}")
        pid = template.pid
        assert os.listdir(f"/proc/{pid}/root") == []
        status = dict(line.split(":\t", 1) for line in open(f"/proc/{pid}/status").read().splitlines() if ":\t" in line)
        assert status["NSpid"].split()[-1] == "1"
        assert {status[k].strip() for k in ("CapInh", "CapPrm", "CapEff", "CapBnd", "CapAmb")} == {"0" * 16}
        for kind in ("user", "pid_for_children", "net", "ipc", "uts", "mnt"):
            assert os.readlink(f"/proc/{pid}/ns/{kind}") != os.readlink(f"/proc/self/ns/{kind}"), kind
    finally:
        sandbox.close()
    shown = walls()
    assert [w.name for w in shown][:3] == ["seccomp", "rlimits", "environment"] and all(w.up for w in shown), shown
    assert summary(shown) == "seccomp, rlimits, environment, user+pid+net+ipc+uts+mount namespaces"


def test_without_namespaces_the_walls_say_so(monkeypatch, capsys):
    from sartco.program import handle
    from sartco.program.walls import of, summary

    monkeypatch.setattr(handle, "NAMESPACES", False)
    sandbox = LocalSandbox(workers=1)
    try:
        assert sandbox.execute("put(board, 'nut', 'red', 0, 0)").ok
        shown = of(sandbox.templates(1)[0])
    finally:
        sandbox.close()
    assert [w.up for w in shown] == [True] * 3 + [False] * 6
    assert summary(shown).startswith("seccomp, rlimits, environment; down: user namespace, pid namespace"), summary(shown)
