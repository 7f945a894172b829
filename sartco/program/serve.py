"""`sartco execute`: JSON lines on stdin -> one JSON line per input on stdout, in order.

The fields of each line are described in lines.py. Blank lines are skipped (they are no input).

Input is read in whatever the pipe holds at the moment (up to --batch complete lines), and
those lines run as one batch split over the workers; so a long file streams in big batches while
an interactive caller gets each answer as soon as its line arrives.
"""
from __future__ import annotations

import os
import queue
import select
import threading
from collections import deque

from sartco.errors import UserError
from sartco.world import DEFAULT_COLS, DEFAULT_ROWS
from sartco.world.board import MAX_SIDE

from .execution import Limits
from .lines import finish, parse_line
from .sandbox import execute_many

CHUNK = 1 << 16
IN_FLIGHT = 2  # batches being run at once (the next one queues on each worker's lock)


def configure(parser) -> None:
    parser.add_argument("--rows", type=int, default=DEFAULT_ROWS, help=f"board rows (default {DEFAULT_ROWS})")
    parser.add_argument("--cols", type=int, default=DEFAULT_COLS, help=f"board columns (default {DEFAULT_COLS})")
    parser.add_argument("--workers", type=int, default=None, help="worker processes (default min(2, CPUs))")
    parser.add_argument("--batch", type=int, default=1024, help="most programs per batch (default 1024)")
    parser.add_argument("--wall-time", type=float, default=Limits().wall_time, help="seconds per program (default %(default)s)")


def run(args) -> int:
    import sys

    for name in ("rows", "cols"):
        if not 1 <= getattr(args, name) <= MAX_SIDE:
            raise UserError(f"--{name} must be between 1 and {MAX_SIDE}, got {getattr(args, name)}")
    if args.batch < 1 or (args.workers is not None and args.workers < 1) or args.wall_time <= 0:
        raise UserError("--batch and --workers must be at least 1, --wall-time positive")
    from .walls import summary, walls

    print(f"walls: {summary(walls())}", file=sys.stderr, flush=True)
    serve(sys.stdin.buffer, sys.stdout.buffer, args.rows, args.cols,
          Limits(wall_time=args.wall_time), workers=args.workers, batch=args.batch)
    return 0


def _chunks(stream, batch: int):
    """Byte chunks as they arrive: on a real file descriptor, everything readable right now
    (up to about `batch` lines), else read() of a fixed size."""
    try:
        fd = stream.fileno()
    except (AttributeError, OSError, ValueError):
        fd = None
    while True:
        if fd is None:
            chunk = stream.read(CHUNK * 16)
        else:
            chunk = os.read(fd, CHUNK)
            while chunk and chunk.count(b"\n") < batch and select.select([fd], [], [], 0)[0]:
                more = os.read(fd, CHUNK)
                if not more:
                    break
                chunk += more
        if not chunk:
            return
        yield chunk


def _batches(stream, batch: int):
    """Lists of (line number, raw line) with all complete lines available, at most `batch`."""
    tail, number = b"", 0
    for chunk in _chunks(stream, batch):
        parts = (tail + chunk).split(b"\n")
        tail = parts.pop()
        lines = []
        for raw in parts:
            number += 1
            if raw.strip():
                lines.append((number, raw))
        for k in range(0, len(lines), batch):
            yield lines[k:k + batch]
    if tail.strip():
        yield [(number + 1, tail)]


def _answers(lines, rows, cols, limits, workers, cache) -> bytes:
    """The output text of one batch (every line answered, whatever happens): each line parsed
    here, its program run in the sandbox in use, the answer formatted here (lines.py)."""
    parsed = [parse_line(number, raw, check_target=False) for number, raw in lines]
    todo = [k for k, p in enumerate(parsed) if p[3] is None]
    runs = execute_many([parsed[k][1] for k in todo], rows, cols, limits, workers=workers, cache=cache)
    done = dict(zip(todo, runs))
    text = []
    for k, (number, _) in enumerate(lines):
        ex = done.get(k)
        text.append(finish(number, parsed[k], lambda ex=ex: (ex.ok, ex.error, ex.message, ex.cells)).encode())
    return b"\n".join(text) + b"\n"


def serve(inp, out, rows: int = DEFAULT_ROWS, cols: int = DEFAULT_COLS, limits: Limits | None = None, *,
          workers: int | None = None, batch: int = 1024, cache: bool = True) -> int:
    """The JSON-lines loop over binary streams; returns the number of lines answered.

    This process parses each line, runs its program in the sandbox in use (a confined process
    per program; with the cache on, equal sources of a batch run once), compares and formats
    the answer (lines.py).

    Pipelined: a reader thread collects the next batch while the current one runs, and up to
    two batches are in flight, so a worker that finishes its share of one batch goes on with
    its share of the next (each worker's lock keeps them in order) instead of waiting for the
    other worker and for the parent. Answers are written strictly in input order, each batch
    as soon as it is complete, and no batch waits for input that has not arrived (an
    interactive caller gets each answer without sending more)."""
    limits = limits or Limits()
    events: queue.SimpleQueue = queue.SimpleQueue()  # ("batch", lines) | ("done", (slot, (text, n))) | ("end", exc)
    room = threading.Semaphore(IN_FLIGHT + 1)  # batches read but not yet written

    def read():
        try:
            for lines in _batches(inp, batch):
                room.acquire()
                events.put(("batch", lines))
            events.put(("end", None))
        except BaseException as exc:  # handed to the main thread
            events.put(("end", exc))

    def work(slot, lines):
        try:
            events.put(("done", (slot, (_answers(lines, rows, cols, limits, workers, cache), len(lines)))))
        except BaseException as exc:  # cannot happen (_answers catches); never hang
            events.put(("done", (slot, exc)))

    threading.Thread(target=read, daemon=True).start()
    backlog: deque = deque()  # (slot, lines) read, not yet started
    results: dict = {}  # slot -> output text, done but not yet written
    started = written = answered = 0
    running = 0
    ended, failure = False, None
    while not (ended and written == started and not backlog):
        kind, value = events.get()
        if kind == "batch":
            backlog.append((started, value))
            started += 1
        elif kind == "end":
            ended, failure = True, value
        else:
            slot, done = value
            running -= 1
            if isinstance(done, BaseException):
                raise done
            results[slot] = done
            while written in results:
                text, n = results.pop(written)
                out.write(text)
                out.flush()
                answered += n
                written += 1
                room.release()
        while backlog and running < IN_FLIGHT:
            slot, lines = backlog.popleft()
            running += 1
            threading.Thread(target=work, args=(slot, lines), daemon=True).start()
    if failure is not None:
        raise failure
    return answered
