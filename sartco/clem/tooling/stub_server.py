"""A local OpenAI-compatible stub server for measuring the harness (`sartco bench-run`) and for
tests: it answers `POST /v1/chat/completions` from the episodes' gold code after a fixed latency.

- 127.0.0.1 only, a free port; each request is handled in its own thread (concurrent requests
  overlap, as on a server with parallel slots), sleeps `latency` seconds, then answers.
- The answer: the gold code of the turn, found by the user messages of the conversation so far
  (`answer_table`: the turns an episode's builder is sent -> that turn's gold code, fenced);
  an unknown conversation gets "I have no code for this."
- Bounded: after `max_requests` requests or `max_seconds` it answers 503 and stops by itself.
- `intervals` records (start, end) of every answered request (time.monotonic), from which
  `busy_time` (the union: time with at least one request in flight) follows.
- `fail_first`: the first n requests get 500 (for the backend's retry test).
- `failing`: conversation keys (`conversation_key` of its user messages) whose every request gets
  500, the others are answered (a server that fails some requests only).
- `hang`: every request is counted and then never answered until the server stops (a hung
  model server, for the backend's timeout test); `requests` counts every request that arrived.
"""
from __future__ import annotations

import hashlib
import json
import threading
import time
from http.server import BaseHTTPRequestHandler, ThreadingHTTPServer

from sartco.clem.players.answers import NO_CODE  # the stub answers an unknown conversation as mock answers an episode without gold
from sartco.clem.players.sourced import fenced


def conversation_key(user_texts) -> str:
    return hashlib.sha256("\x00".join(user_texts).encode("utf-8")).hexdigest()


def answer_table(game_instances) -> dict[str, str]:
    """cobot_instruct instances -> {conversation key: fenced gold code of that turn}. The k-th
    request of an episode holds the turns 0..k (the first with the prompt, as clemcore joins it)."""
    table = {}
    for instance in game_instances:
        turns = instance["turns"]
        for k, gold in enumerate(instance["gold_turns"][:len(turns)]):
            table.setdefault(conversation_key(turns[:k + 1]), fenced(gold))
    return table


class StubServer:
    def __init__(self, answers: dict[str, str], *, latency: float = 0.5, max_requests: int = 10_000,
                 max_seconds: float = 1800.0, fail_first: int = 0, hang: bool = False,
                 failing: frozenset[str] = frozenset()):
        self.answers, self.latency = answers, latency
        self.max_requests, self.max_seconds, self.fail_first = max_requests, max_seconds, fail_first
        self.hang, self.failing = hang, failing
        self.requests = 0
        self.intervals: list[tuple[float, float]] = []
        self.unknown = 0      # conversations without a gold answer
        self.misrouted = 0    # requests to another path (404)
        self._lock = threading.Lock()
        self._stopped = threading.Event()
        self._httpd = ThreadingHTTPServer(("127.0.0.1", 0), self._handler())
        self._httpd.daemon_threads = True

    @property
    def base_url(self) -> str:
        return f"http://127.0.0.1:{self._httpd.server_address[1]}/v1"

    def __enter__(self) -> "StubServer":
        threading.Thread(target=self._httpd.serve_forever, daemon=True).start()
        timer = threading.Timer(self.max_seconds, self.stop)
        timer.daemon = True
        timer.start()
        return self

    def __exit__(self, *exc) -> None:
        self.stop()

    def stop(self) -> None:
        if not self._stopped.is_set():
            self._stopped.set()
            threading.Thread(target=self._httpd.shutdown, daemon=True).start()  # not from a handler thread's lock

    def busy_time(self, start: float | None = None, end: float | None = None) -> float:
        """Seconds in [start, end] during which at least one request was in flight."""
        total, reach = 0.0, None
        for a, b in sorted(self.intervals):
            a, b = max(a, start if start is not None else a), min(b, end if end is not None else b)
            if b <= a:
                continue
            if reach is None or a > reach:
                total += b - a
                reach = b
            elif b > reach:
                total += b - reach
                reach = b
        return total

    def _answer(self, body: dict) -> tuple[int, dict]:
        with self._lock:
            self.requests += 1
            number = self.requests
        if number > self.max_requests or self._stopped.is_set():
            self.stop()
            return 503, {"error": {"message": "stub server: request budget or time used up"}}
        if self.hang:
            self._stopped.wait(self.max_seconds)
            return 503, {"error": {"message": "stub server: stopped while hanging"}}
        if number <= self.fail_first:
            return 500, {"error": {"message": "stub server: a planned failure"}}
        users = [m.get("content") for m in body.get("messages", []) if m.get("role") == "user"]
        key = conversation_key([u if isinstance(u, str) else json.dumps(u) for u in users])
        if key in self.failing:
            return 500, {"error": {"message": "stub server: this conversation always fails"}}
        start = time.monotonic()
        time.sleep(self.latency)
        text = self.answers.get(key)
        if text is None:
            with self._lock:
                self.unknown += 1
            text = NO_CODE
        with self._lock:
            self.intervals.append((start, time.monotonic()))
        return 200, {
            "id": f"stub-{number}", "object": "chat.completion", "created": 0, "model": body.get("model", "stub"),
            "choices": [{"index": 0, "finish_reason": "stop", "message": {"role": "assistant", "content": text}}],
            "usage": {"prompt_tokens": 0, "completion_tokens": 0, "total_tokens": 0},
        }

    def _handler(self):
        server = self

        class Handler(BaseHTTPRequestHandler):
            protocol_version = "HTTP/1.1"

            def do_POST(self):  # http.server's name
                length = int(self.headers.get("Content-Length") or 0)
                try:
                    body = json.loads(self.rfile.read(length) or b"{}")
                except json.JSONDecodeError:
                    status, payload = 400, {"error": {"message": "stub server: the body is not JSON"}}
                else:
                    if self.path.rstrip("/") == "/v1/chat/completions":
                        status, payload = server._answer(body)
                    else:
                        server.misrouted += 1
                        status, payload = 404, {"error": {"message": f"stub server: no route {self.path}"}}
                data = json.dumps(payload).encode("utf-8")
                self.send_response(status)
                self.send_header("Content-Type", "application/json")
                self.send_header("Content-Length", str(len(data)))
                self.end_headers()
                try:
                    self.wfile.write(data)
                except (BrokenPipeError, ConnectionResetError):  # the client gave up (its timeout)
                    pass

            def log_message(self, *args):  # quiet
                pass

        return Handler
