"""`sartco execute`: JSON lines on stdin -> one JSON line per input on stdout, in order.

in:  {"id": str, "code": str, "target": optional cells}
out: {"id", "ok", "error": null | code, "message", "cells"} and, when a target was given,
     "es" (0|1), "category" (null, the program's error code, or a mismatch code),
     "precision", "recall", "f1".

A program that fails has es 0 and its error as the category; P/R/F1 are still computed on the
board it built so far. Blank lines are skipped. A malformed line (not JSON, not an object,
id/code/target of the wrong type) gives {"id": <its id if a string, else null>, "ok": false,
"error": "parse_error", "message": "input line N: ...", "cells": {}} and no comparison fields.

Input is read in whatever chunks the pipe delivers, and all complete lines of a chunk (at most
--batch) run as one call of execute_many, split over the workers; so a long file streams in big
batches while an interactive caller gets each answer as soon as its line arrives.
"""
from __future__ import annotations

import json
import os
import re

from sartco.cli import UserError
from sartco.world import ErrorCode

from .compare import compare
from .pool import execute_many
from .records import Limits

KEY = re.compile(r"\d+:\d+")
CHUNK = 1 << 16


def configure(parser) -> None:
    parser.add_argument("--rows", type=int, default=8, help="board rows (default 8)")
    parser.add_argument("--cols", type=int, default=8, help="board columns (default 8)")
    parser.add_argument("--workers", type=int, default=None, help="worker processes (default min(2, CPUs))")
    parser.add_argument("--batch", type=int, default=1024, help="most programs per batch (default 1024)")
    parser.add_argument("--wall-time", type=float, default=Limits().wall_time, help="seconds per program (default %(default)s)")


def run(args) -> int:
    import sys

    for name in ("rows", "cols"):
        if not 1 <= getattr(args, name) <= 64:
            raise UserError(f"--{name} must be between 1 and 64, got {getattr(args, name)}")
    if args.batch < 1 or (args.workers is not None and args.workers < 1) or args.wall_time <= 0:
        raise UserError("--batch and --workers must be at least 1, --wall-time positive")
    serve(sys.stdin.buffer, sys.stdout.buffer, args.rows, args.cols,
          Limits(wall_time=args.wall_time), workers=args.workers, batch=args.batch)
    return 0


def _chunks(stream):
    """Byte chunks as they arrive (os.read on a real file descriptor, else read())."""
    try:
        fd = stream.fileno()
    except (AttributeError, OSError, ValueError):
        fd = None
    while True:
        chunk = os.read(fd, CHUNK) if fd is not None else stream.read(CHUNK)
        if not chunk:
            return
        yield chunk


def _batches(stream, batch: int):
    """Lists of (line number, raw line) with all complete lines available, at most `batch`."""
    tail, number = b"", 0
    for chunk in _chunks(stream):
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


def _check_cells(cells) -> str | None:
    if type(cells) is not dict:
        return "target must be an object of cells"
    for key, stack in cells.items():
        if not KEY.fullmatch(key):
            return f"target cell key {key!r:.40} is not 'row:col'"
        if type(stack) is not list or not all(
            type(p) is list and len(p) == 2 and type(p[0]) is str and type(p[1]) is str for p in stack
        ):
            return f"target cell {key} must be a list of [shape, colour] pairs"
    return None


def parse_line(number: int, raw: bytes):
    """(id, code, target or None, None) or (id or None, None, None, error message)."""
    try:
        item = json.loads(raw)
    except ValueError as exc:
        return None, None, None, f"input line {number}: not JSON ({exc})"
    if type(item) is not dict:
        return None, None, None, f"input line {number}: expected a JSON object, got {type(item).__name__}"
    ident = item.get("id")
    if type(ident) is not str:
        return None, None, None, f"input line {number}: \"id\" must be a string"
    code = item.get("code")
    if type(code) is not str:
        return ident, None, None, f"input line {number}: \"code\" must be a string"
    target = item.get("target")
    if target is not None:
        problem = _check_cells(target)
        if problem:
            return ident, None, None, f"input line {number}: {problem}"
    return ident, code, target, None


def answer(ident, ex, target) -> dict:
    out = {"id": ident, "ok": ex.ok, "error": ex.error, "message": ex.message, "cells": ex.cells}
    if target is not None:
        cmp = compare(ex.cells, target)
        out["es"] = cmp.es if ex.ok else 0
        out["category"] = cmp.category if ex.ok else ex.error
        out["precision"], out["recall"], out["f1"] = cmp.precision, cmp.recall, cmp.f1
    return out


def serve(inp, out, rows: int = 8, cols: int = 8, limits: Limits | None = None, *,
          workers: int | None = None, batch: int = 1024, cache: bool = True) -> int:
    """The JSON-lines loop over binary streams; returns the number of lines answered."""
    answered = 0
    for lines in _batches(inp, batch):
        parsed = [parse_line(n, raw) for n, raw in lines]
        codes = [p[1] for p in parsed if p[3] is None]
        results = iter(execute_many(codes, rows, cols, limits, workers=workers, cache=cache))
        text = []
        for ident, _, target, problem in parsed:
            if problem is not None:
                row = {"id": ident, "ok": False, "error": ErrorCode.PARSE_ERROR, "message": problem, "cells": {}}
            else:
                row = answer(ident, next(results), target)
            text.append(json.dumps(row))
        out.write(("\n".join(text) + "\n").encode("utf-8"))
        out.flush()
        answered += len(text)
    return answered
