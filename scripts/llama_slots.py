"""One address, N llama.cpp servers: parallel slots for llama-cpp-python's server.

    python scripts/llama_slots.py --port PORT --slots N -- SERVER_ARGS...

`python -m llama_cpp.server` answers one request at a time (a global lock; no release up to 0.3.36
has llama.cpp's `--parallel` slots), so a batched client gets no parallelism from one server. This
starts N of them (`python -m llama_cpp.server SERVER_ARGS --host 127.0.0.1 --port P`, each P a port the
kernel reports free at that moment, never PORT+k, which another program may hold), waits until each
answers GET /v1/models, then listens on 127.0.0.1:PORT and hands every request to a free server (a
request waits while all N are busy). Used by scripts/local_model.sh with one
server per core (`--n_threads 1` each) and the `openai_batching` backend with concurrency N.

If any server exits, this prints one line naming it and its exit status (e.g. SIGSEGV) and exits
1 at once, stopping the others: the caller watches this one process. SIGTERM/SIGINT stop all.
"""
from __future__ import annotations

import argparse
import http.client
import os
import queue
import signal
import socket
import subprocess
import sys
import threading
import time
from http.server import BaseHTTPRequestHandler, ThreadingHTTPServer

HOP_HEADERS = {"connection", "keep-alive", "transfer-encoding", "host", "content-length"}


def describe(code: int) -> str:
    """An exit status as a reader wants it: 'exit code 1' or 'signal 11 (SIGSEGV)'."""
    if code < 0:
        try:
            return f"signal {-code} ({signal.Signals(-code).name})"
        except ValueError:
            return f"signal {-code}"
    return f"exit code {code}"


def free_ports(n: int) -> list[int]:
    """n distinct ports that nothing listens on or connects from now (all held open together, so
    the kernel gives n different ones)."""
    sockets = [socket.socket() for _ in range(n)]
    try:
        for s in sockets:
            s.bind(("127.0.0.1", 0))
        return [s.getsockname()[1] for s in sockets]
    finally:
        for s in sockets:
            s.close()


class Slots:
    def __init__(self, n: int, server_args: list[str]):
        self.ports = free_ports(n)
        self.free: queue.Queue[int] = queue.Queue()
        self.procs = [subprocess.Popen([sys.executable, "-m", "llama_cpp.server", *server_args,
                                        "--host", "127.0.0.1", "--port", str(p)]) for p in self.ports]

    def stop(self) -> None:
        for proc in self.procs:
            if proc.poll() is None:
                proc.terminate()
        for proc in self.procs:
            try:
                proc.wait(10)
            except subprocess.TimeoutExpired:
                proc.kill()

    def dead(self) -> str | None:
        for port, proc in zip(self.ports, self.procs):
            if proc.poll() is not None:
                return f"llama_slots: the llama.cpp server on port {port} died ({describe(proc.returncode)})"
        return None

    def wait_ready(self, seconds: float) -> None:
        pending, deadline = list(self.ports), time.monotonic() + seconds
        while pending:
            if (why := self.dead()) is not None:
                raise SystemExit(why + " while loading the model")
            if time.monotonic() > deadline:
                raise SystemExit(f"llama_slots: the llama.cpp servers on ports {pending} did not answer in {seconds:.0f} s")
            for port in list(pending):
                try:
                    conn = http.client.HTTPConnection("127.0.0.1", port, timeout=2)
                    conn.request("GET", "/v1/models")
                    if conn.getresponse().status == 200:
                        pending.remove(port)
                        self.free.put(port)
                except OSError:
                    pass
            time.sleep(0.5)

    def watch(self) -> None:
        """Exit the whole process the moment one server dies (checked every 0.2 s)."""
        while (why := self.dead()) is None:
            time.sleep(0.2)
        print(why, file=sys.stderr, flush=True)
        self.stop()
        os._exit(1)


def handler_for(slots: Slots):
    class Forward(BaseHTTPRequestHandler):
        protocol_version = "HTTP/1.1"

        def _forward(self) -> None:
            body = self.rfile.read(int(self.headers.get("Content-Length") or 0))
            headers = {k: v for k, v in self.headers.items() if k.lower() not in HOP_HEADERS}
            port = slots.free.get()
            try:
                conn = http.client.HTTPConnection("127.0.0.1", port)
                conn.request(self.command, self.path, body=body or None, headers=headers)
                answer = conn.getresponse()
                status, data = answer.status, answer.read()
                kept = [(k, v) for k, v in answer.getheaders() if k.lower() not in HOP_HEADERS]
            except OSError as exc:
                status, data, kept = 502, f"llama_slots: server on port {port}: {exc}".encode(), []
            finally:
                slots.free.put(port)
            self.send_response(status)
            for key, value in kept:
                self.send_header(key, value)
            self.send_header("Content-Length", str(len(data)))
            self.end_headers()
            self.wfile.write(data)

        do_GET = do_POST = _forward

        def log_message(self, *args) -> None:  # the servers log each request already
            pass

    return Forward


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--port", type=int, required=True)
    parser.add_argument("--slots", type=int, default=os.cpu_count() or 1)
    parser.add_argument("--ready-timeout", type=float, default=300.0)
    parser.add_argument("server_args", nargs=argparse.REMAINDER)
    args = parser.parse_args()
    server_args = args.server_args[1:] if args.server_args[:1] == ["--"] else args.server_args
    if args.slots < 1:
        parser.error(f"--slots: at least 1 expected, got {args.slots}")
    slots = Slots(args.slots, server_args)
    signal.signal(signal.SIGTERM, lambda *_: (slots.stop(), os._exit(0)))
    try:
        slots.wait_ready(args.ready_timeout)
    except (SystemExit, KeyboardInterrupt):
        slots.stop()
        raise
    threading.Thread(target=slots.watch, daemon=True).start()
    server = ThreadingHTTPServer(("127.0.0.1", args.port), handler_for(slots))
    ports = ", ".join(map(str, slots.ports))
    print(f"llama_slots: {args.slots} llama.cpp servers (ports {ports}) behind 127.0.0.1:{args.port}", file=sys.stderr, flush=True)
    try:
        server.serve_forever()
    except KeyboardInterrupt:
        slots.stop()


if __name__ == "__main__":
    main()
