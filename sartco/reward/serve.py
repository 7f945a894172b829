"""`sartco serve-reward`: the reward over HTTP, as OpenRLHF's `--remote_rm_url` calls it.

    sartco serve-reward [--host 127.0.0.1] [--port 5000] [--reward es|cell_f1]
    -> POST http://HOST:PORT/get_reward  {"query": [...], "prompts": [...], "labels": [...]}
       200 {"rewards": [...], "scores": [...], "extra_logs": {"es": [...], "cell_f1": [...]}}

OpenRLHF's request and answer (its own openrlhf.cli.serve_rm answers the same way): a query is
the decoded prompt and response, a prompt the prompt text (the answer is the query after it), a
label the `episode` column of `sartco export-dataset` (`--label_key episode`); one reward per
query (sartco.reward.trainers.openrlhf_pairs, openrlhf_answer). JSON in and out, nothing else.

A bad request gets 400 and {"error": "<one line naming the field>"} (not JSON, not an object, a
field missing or of another type, a query that does not start with its prompt, a label that is
no episode); another path 404; a failure of the scorer 500. Every request is handled in its own
thread; the requests waiting while a batch is scored are scored together in the next one (one
sandbox batch: what sartco.reward scores fastest). The server runs until interrupted.
"""
from __future__ import annotations

import json
import queue
import threading
from http.server import BaseHTTPRequestHandler, ThreadingHTTPServer

from sartco.errors import UserError

from .core import Reward
from .trainers import REWARDS, openrlhf_answer, openrlhf_pairs, openrlhf_score

PATH = "/get_reward"
MAX_BODY = 256 * 1024 * 1024  # bytes of one request


def configure(parser) -> None:
    parser.add_argument("--host", default="127.0.0.1", help="address to listen on (default %(default)s)")
    parser.add_argument("--port", type=int, default=5000, help="port (default %(default)s; 0: a free one)")
    parser.add_argument("--reward", choices=REWARDS, default="es", help="the reward of `rewards` (default es)")


class Batcher:
    """Scores the pairs of concurrent requests together: one thread takes every request waiting
    and scores their pairs in one call."""

    def __init__(self):
        self._waiting: queue.Queue = queue.Queue()
        threading.Thread(target=self._run, daemon=True, name="sartco-reward-batcher").start()

    def rewards(self, pairs: list[tuple[str, str]]) -> list[Reward]:
        slot: dict = {"pairs": pairs, "done": threading.Event()}
        self._waiting.put(slot)
        slot["done"].wait()
        if "error" in slot:
            raise slot["error"]
        return slot["results"]

    def _run(self) -> None:
        while True:
            slots = [self._waiting.get()]
            while not self._waiting.empty():
                slots.append(self._waiting.get_nowait())
            try:
                results = openrlhf_score([pair for slot in slots for pair in slot["pairs"]])
            except Exception as exc:  # handed to every waiting request (its 500)
                for slot in slots:
                    slot["error"] = exc
            else:
                start = 0
                for slot in slots:
                    slot["results"] = results[start:start + len(slot["pairs"])]
                    start += len(slot["pairs"])
            for slot in slots:
                slot["done"].set()


class _HTTPServer(ThreadingHTTPServer):
    daemon_threads = True
    request_queue_size = 1024  # listen backlog: OpenRLHF sends one request per rollout, many at once


class RewardServer:
    """The HTTP server of `sartco serve-reward` (a context manager serving in a thread, for tests
    and embedding; `serve_forever` for the command)."""

    def __init__(self, host: str = "127.0.0.1", port: int = 0, reward: str = "es"):
        self.host, self.reward = host, reward
        self._httpd = _HTTPServer((host, port), self._handler())
        self.batcher = Batcher()

    @property
    def url(self) -> str:
        return f"http://{self.host}:{self._httpd.server_port}{PATH}"

    def serve_forever(self) -> None:
        self._httpd.serve_forever()

    def __enter__(self) -> "RewardServer":
        threading.Thread(target=self._httpd.serve_forever, daemon=True).start()
        return self

    def __exit__(self, *exc) -> None:
        self._httpd.shutdown()
        self._httpd.server_close()

    def answer(self, body: bytes) -> tuple[int, dict]:
        try:
            request = json.loads(body)
        except (UnicodeDecodeError, json.JSONDecodeError) as exc:
            return 400, {"error": f"the body is not JSON ({exc})"}
        if not isinstance(request, dict):
            return 400, {"error": f"the body must be a JSON object with 'query', 'prompts' and 'labels', got {type(request).__name__}"}
        missing = [name for name in ("query", "prompts", "labels") if name not in request]
        if missing:
            return 400, {"error": f"missing field(s) {', '.join(repr(m) for m in missing)}"}
        try:
            pairs = openrlhf_pairs(request["query"], request["prompts"], request["labels"])
        except ValueError as exc:
            return 400, {"error": str(exc)}
        try:
            return 200, openrlhf_answer(self.batcher.rewards(pairs), self.reward)
        except Exception as exc:
            return 500, {"error": f"scoring failed: {type(exc).__name__}: {exc}"}

    def _handler(self):
        server = self

        class Handler(BaseHTTPRequestHandler):
            protocol_version = "HTTP/1.1"

            def do_POST(self):  # http.server's name
                length = self.headers.get("Content-Length")
                if self.path != PATH:
                    self.reply(404, {"error": f"no route {self.path!r}; POST {PATH}"})
                elif length is None or not length.isdigit():
                    self.reply(411, {"error": "a Content-Length header is needed"})
                elif int(length) > MAX_BODY:
                    self.reply(413, {"error": f"the body is larger than {MAX_BODY} bytes"})
                else:
                    self.reply(*server.answer(self.rfile.read(int(length))))

            def reply(self, status: int, payload: dict) -> None:
                data = json.dumps(payload).encode("utf-8")
                self.send_response(status)
                self.send_header("Content-Type", "application/json")
                self.send_header("Content-Length", str(len(data)))
                if status >= 400:
                    self.send_header("Connection", "close")
                    self.close_connection = True
                self.end_headers()
                try:
                    self.wfile.write(data)
                except (BrokenPipeError, ConnectionResetError):  # the client gave up
                    pass

            def log_message(self, *args):  # quiet
                pass

        return Handler


def run(args) -> int:
    try:
        server = RewardServer(args.host, args.port, args.reward)
    except OSError as exc:
        raise UserError(f"cannot listen on {args.host}:{args.port} ({exc.strerror or exc})") from None
    print(f"sartco serve-reward: POST {server.url} (OpenRLHF --remote_rm_url; reward {args.reward}); Ctrl-C stops",
          flush=True)
    try:
        server.serve_forever()
    except KeyboardInterrupt:
        pass
    return 0
