"""Command processes for the tests, forked from a warm parent: `command(args, ...)` is
subprocess.run(args, capture_output=True, text=True, ...) for a Python program (a script whose
#! line names a Python interpreter, such as the `clem` and `sartco` scripts of a venv, `python -m
MODULE`, `python SCRIPT.py`): `clem list games` takes 1.6 s of CPU so, 4.5-5 s as a fresh process.

Why: a `clem` process spends about 3.4 s of its 4 importing clemcore.clemgame, 3.0 s of them in
one third-party package it imports, openenv.core (gradio, fastmcp, uvicorn, pandas; `python -X
importtime -c "import clemcore.clemgame"`). The tests start about 80 such processes.

How: one server process per interpreter and set of PYTHON* variables (this venv's python, the
wheel's venv's; started at its first command, ended with the pytest process) that has imported
PRELOAD, and nothing of clemcore or sartco (it checks), forks a child per command. The child is
the command's own process: its own pid, stdin, stdout and stderr (the caller's pipes, passed over
a Unix socket), working folder, environment and sys.argv; it runs the script with runpy as the
interpreter would (`__main__`, sys.path[0] the script's folder, or the working folder for -m)
and ends as a Python process ends (an uncaught exception: traceback and status 1; SystemExit's
code; threads joined, atexit handlers run, streams flushed). clemcore and sartco are imported in
the child, so everything they do at import (clemcore's logging config and its clembench.log in
the working folder, settings read from the environment) happens there, as in a fresh process.

What differs from a fresh interpreter, and when a fresh process runs instead:
- PRELOAD's modules were imported before the child's environment and folder were set. They are
  third-party and read neither for anything these commands use.
- The children of one server share its hash seed (string hashing): a command whose environment
  sets PYTHONHASHSEED runs in a fresh process, as does anything but a Python program (`bash`,
  `git`), `python -c`, and every command when SARTCO_TEST_FRESH_PROCESSES=1 is set.
Tests that signal a running process keep subprocess.Popen (tests/clem/test_resume_settings.py).
"""
from __future__ import annotations

import atexit
import json
import os
import selectors
import shutil
import signal
import socket
import struct
import subprocess
import sys
import time
from pathlib import Path

# What a `clem` or `sartco` command imports that is third-party, reads nothing of its folder or
# environment at import, and takes longest (`python -X importtime -c "import clemcore.clemgame"`):
# openenv.core about 3 s, then, in a process that holds it, gymnasium.spaces and pettingzoo (the
# PettingZoo env) 0.19 s, requests 0.14 s and nltk 0.15 s of clemcore.clemgame's other 0.43 s
# (29 Nov 2026: openenv.core alone, 1.85-1.91 s a forked `clem list games`; all five, 1.58-1.64 s);
# and openai, 0.57 s of every command that plays a model through a server (the stub's).
# gymnasium and pettingzoo set two of pygame's variables in os.environ at import; a child's
# environment is its request's, without them (nothing here runs pygame). openai reads the
# settings of its module-level client (OPENAI_API_TYPE, ...) at import; clemcore makes clients
# of its own from key.json.
PRELOAD = ("openenv.core", "gymnasium.spaces", "pettingzoo", "requests", "nltk", "openai")
_servers: dict[tuple, tuple[subprocess.Popen, socket.socket]] = {}   # by interpreter and PYTHON* variables


# ---- in the server -------------------------------------------------------------------------------

def serve(fd: int) -> None:
    import importlib
    import threading
    for name in PRELOAD:
        importlib.import_module(name)
    ours = sorted(n for n in sys.modules if n.split(".")[0] in ("clemcore", "sartco"))
    assert not ours, f"the fork server must not import clemcore or sartco: {ours[:5]}"
    assert threading.active_count() == 1, "the fork server must not run threads (a child gets only one)"
    sock = socket.socket(fileno=fd)
    while True:
        msg, fds, _, _ = socket.recv_fds(sock, 1 << 20, 3)
        if not msg:
            return
        request = json.loads(msg)
        sys.stdout.flush()
        sys.stderr.flush()
        pid = os.fork()
        if pid == 0:
            sock.close()
            _child(request, fds)  # ends as the process ends: SystemExit or an uncaught exception
            raise SystemExit(0)
        for f in fds:
            os.close(f)
        sock.sendall(struct.pack("!q", pid))
        _, status = os.waitpid(pid, 0)
        sock.sendall(struct.pack("!q", os.waitstatus_to_exitcode(status)))


def _child(request: dict, fds: list[int]) -> None:
    import runpy
    for target, f in zip((0, 1, 2), fds):
        os.dup2(f, target)
        os.close(f)
    os.chdir(request["cwd"])
    os.environ.clear()
    os.environ.update(request["env"])
    args = request["args"]
    if args[0] == "-m":
        sys.argv = [args[1], *args[2:]]
        sys.path[0] = os.getcwd()
        runpy.run_module(args[1], run_name="__main__", alter_sys=True)
    else:
        sys.argv = list(args)
        sys.path[0] = os.path.dirname(os.path.abspath(args[0]))
        runpy.run_path(args[0], run_name="__main__")


# ---- in the tests --------------------------------------------------------------------------------

def _interpreter(name: str, env: dict) -> Path | None:
    """`name` (a path, or a command found on env's PATH) when it is a Python interpreter."""
    found = name if os.sep in name else shutil.which(name, path=env.get("PATH", os.defpath))
    return Path(found) if found and Path(found).name.startswith("python") and os.path.isfile(found) else None


def _python_args(args: list[str], env: dict) -> tuple[str, list[str]] | None:
    """(the interpreter, what its server runs: ["-m", module, ...] or [script, ...]) for `args`,
    or None for a fresh process."""
    python = _interpreter(args[0], env)
    if python is not None:
        if len(args) > 2 and args[1] == "-m" or len(args) > 1 and args[1].endswith(".py"):
            return str(python), args[1:]
        return None
    script = args[0] if os.sep in args[0] else shutil.which(args[0], path=env.get("PATH", os.defpath))
    if script and os.path.isabs(script) and os.path.isfile(script):
        with open(script, "rb") as f:
            first = f.readline().strip()
        python = _interpreter(first[2:].decode(errors="replace"), env) if first.startswith(b"#!/") else None
        if python is not None and os.path.isabs(python):
            return str(python), [script, *args[1:]]
    return None


def _start(python: str = sys.executable, env: dict | None = None) -> tuple[subprocess.Popen, socket.socket]:
    """The server of `python` with env's PYTHON* variables (started with `env`)."""
    env = dict(os.environ if env is None else env)
    key = (python, tuple(sorted((k, v) for k, v in env.items() if k.startswith("PYTHON"))))
    if key not in _servers:
        ours, theirs = socket.socketpair()
        here = str(Path(__file__).resolve().parent)
        proc = subprocess.Popen([python, "-c", f"import sys; sys.path.insert(0, {here!r}); import forkserver; "
                                 f"sys.path.remove({here!r}); forkserver.serve({theirs.fileno()})"],
                                pass_fds=[theirs.fileno()], stdin=subprocess.DEVNULL, cwd="/", env=env)
        theirs.close()
        _servers[key] = (proc, ours)
        if len(_servers) == 1:
            atexit.register(_stop)
    return _servers[key]


def _stop() -> None:
    while _servers:
        _, (proc, sock) = _servers.popitem()
        sock.close()
        try:
            proc.wait(timeout=30)
        except subprocess.TimeoutExpired:
            proc.kill()


def command(args, *, cwd=None, env: dict | None = None, timeout: float | None = None, input: str | bytes | None = None,
            text: bool = True, capture_output: bool = True) -> subprocess.CompletedProcess:
    """subprocess.run(args, cwd=cwd, env=env, capture_output=True, text=text, timeout=timeout,
    input=input) with stdin empty when no input is given, forked from the server where it can (the
    module doc)."""
    assert capture_output, "command() always captures stdout and stderr"
    args = [str(a) for a in args]
    env = dict(os.environ if env is None else env)
    found = _python_args(args, env)
    if found is None or os.environ.get("SARTCO_TEST_FRESH_PROCESSES") == "1" or "PYTHONHASHSEED" in env:
        return subprocess.run(args, cwd=cwd, env=env, capture_output=True, text=text, timeout=timeout,
                              input=input, stdin=None if input is not None else subprocess.DEVNULL)
    python, program = found
    _, sock = _start(python, env)
    stdin_r, stdin_w = os.pipe()
    out_r, out_w = os.pipe()
    err_r, err_w = os.pipe()
    request = {"args": program, "cwd": str(Path(cwd or os.getcwd()).resolve()), "env": env}
    socket.send_fds(sock, [json.dumps(request).encode()], [stdin_r, out_w, err_w])
    for f in (stdin_r, out_w, err_w):
        os.close(f)
    pid = struct.unpack("!q", _recv(sock, 8))[0]
    data = input.encode() if isinstance(input, str) else input or b""
    output = _collect(stdin_w, data, out_r, err_r, pid, timeout)
    code = struct.unpack("!q", _recv(sock, 8))[0]
    if output is None:
        raise subprocess.TimeoutExpired(args, timeout)
    if not text:
        return subprocess.CompletedProcess(args, code, *output)
    stdout, stderr = (o.decode() for o in output)  # as text=True decodes: the locale's UTF-8, strict
    return subprocess.CompletedProcess(args, code, stdout.replace("\r\n", "\n"), stderr.replace("\r\n", "\n"))


def _recv(sock: socket.socket, n: int) -> bytes:
    data = b""
    while len(data) < n:
        chunk = sock.recv(n - len(data))
        if not chunk:
            raise RuntimeError("the tests' fork server ended (tests/helpers/forkserver.py)")
        data += chunk
    return data


def _collect(stdin_w: int, data: bytes, out_r: int, err_r: int, pid: int,
             timeout: float | None) -> tuple[bytes, bytes] | None:
    """Write `data` to the child's stdin, read its stdout and stderr to their ends; kill it at
    `timeout` (then None)."""
    deadline = None if timeout is None else time.monotonic() + timeout
    chunks: dict[int, list[bytes]] = {out_r: [], err_r: []}
    sel = selectors.DefaultSelector()
    sel.register(out_r, selectors.EVENT_READ)
    sel.register(err_r, selectors.EVENT_READ)
    if data:
        sel.register(stdin_w, selectors.EVENT_WRITE)
    else:
        os.close(stdin_w)
    view = memoryview(data)
    while len(sel.get_map()):
        left = None if deadline is None else deadline - time.monotonic()
        if left is not None and left <= 0:
            os.kill(pid, signal.SIGKILL)
            for f in list(sel.get_map()):
                sel.unregister(f)
                os.close(f)
            return None
        for key, _ in sel.select(left):
            f = key.fd
            if f == stdin_w:
                try:
                    view = view[os.write(f, view[:65536]):]
                except BrokenPipeError:
                    view = view[:0]
                if not view:
                    sel.unregister(f)
                    os.close(f)
                continue
            chunk = os.read(f, 65536)
            if chunk:
                chunks[f].append(chunk)
            else:
                sel.unregister(f)
                os.close(f)
    return b"".join(chunks[out_r]), b"".join(chunks[err_r])
