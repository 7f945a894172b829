"""One line of the `sartco execute` contract: parse an input line, build its output object.

Used by serve.py in the parent: each input line is parsed here, its program run in the sandbox
(a confined process of its own), and the answer compared and formatted here.

in:  {"id": str, "code": str, "target": optional cells}
out: {"id", "ok", "error": null | code, "message", "cells"} and, when a target was given,
     "es" (0|1), "category" (null, the program's error code, or a mismatch code),
     "precision", "recall", "f1".
A program that fails has es 0 and its error as the category; P/R/F1 are still computed on the
board it built so far (compare.judge). A malformed line (not JSON, not an object, id/code/target
of the wrong type) gives {"id": <its id if a string, else null>, "ok": false, "error": "parse_error",
"message": "input line N: ...", "cells": {}} and no comparison fields. Ids and messages are
written clean (execution.clean: no lone surrogates or control characters), so that every output
line is strict JSON and valid UTF-8 whatever the program or the input held.
"""
from __future__ import annotations

import json
import re

from sartco.world import ErrorCode
from sartco.world.board import KEY

from .compare import judge
from .execution import clean

KEYS = re.compile(rf"{KEY.pattern}(?:,{KEY.pattern})*")  # keys joined by commas
# the output holds only fresh dicts, lists and strings (no cycles): skip the encoder's cycle check
encode = json.JSONEncoder(check_circular=False).encode


def _check_cells(cells) -> str | None:
    if type(cells) is not dict:
        return "target must be an object of cells"
    joined = ",".join(cells)  # all keys at once: as many commas as separators, each key row:col
    if cells and not (KEYS.fullmatch(joined) and joined.count(",") == len(cells) - 1):
        for key in cells:
            if not KEY.fullmatch(key):
                return f"target cell key {key!r:.40} is not 'row:col'"
    for key, stack in cells.items():
        if type(stack) is not list:
            return f"target cell {key} must be a list of [shape, colour] pairs"
        for p in stack:
            if type(p) is not list or len(p) != 2 or type(p[0]) is not str or type(p[1]) is not str:
                return f"target cell {key} must be a list of [shape, colour] pairs"
    return None


def parse_line(number: int, raw: bytes, check_target: bool = True):
    """(id, code, target or None, None) or (id or None, None, None, problem). With check_target
    False the target's cells are left unchecked (see finish)."""
    try:
        item = json.loads(raw)
    except (ValueError, RecursionError) as exc:
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
    if target is not None and check_target:
        problem = _check_cells(target)
        if problem:
            return ident, None, None, f"input line {number}: {problem}"
    return ident, code, target, None


def answer(ident, ok: bool, error, message: str, cells: dict, target) -> dict:
    out = {"id": clean(ident), "ok": ok, "error": error, "message": clean(message), "cells": cells}
    if target is not None:
        verdict = judge(ok, error, cells, target)
        out["es"], out["category"] = verdict.es, verdict.category
        out["precision"], out["recall"], out["f1"] = verdict.precision, verdict.recall, verdict.f1
    return out


def malformed(ident, problem: str) -> dict:
    return {"id": None if ident is None else clean(ident), "ok": False, "error": ErrorCode.PARSE_ERROR,
            "message": clean(problem), "cells": {}}


def finish(number: int, parsed: tuple, run) -> str:
    """The output line (JSON text) for one input line, given what parse_line(number, raw,
    check_target=False) made of it; `run()` runs its code -> (ok, error, message, cells)."""
    ident, _, target, problem = parsed
    if problem is not None:
        return encode(malformed(ident, problem))
    ok, error, message, cells = run()
    # the target's cells are checked only when they differ from the built board's: equal to
    # well-formed cells, they are well-formed (the common case, and a third of the JSON work).
    # A malformed target so costs a run, but answers the same malformed line.
    if target is not None and target != cells:
        problem = _check_cells(target)
        if problem:
            return encode(malformed(ident, f"input line {number}: {problem}"))
    return encode(answer(ident, ok, error, message, cells, target))
