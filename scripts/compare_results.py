#!/usr/bin/env python3
"""Compare every file of two `make main` outputs (results folder and tables folder), e.g. of two
checkouts, to show that a change moved no result.

    scripts/compare_results.py BASE_RESULTS NEW_RESULTS [BASE_SCORES NEW_SCORES]
                               [--checkouts BASE_CHECKOUT NEW_CHECKOUT]

Every file is read in both, by its path relative to its folder:
- the result files: every scores.json, results.csv, raw.csv and every file of the tables folder
  must be byte-identical, what states a time or a commit aside (a date-time, "took 1.2 s",
  "git 21e2b2fb7c9b"); every
  interactions.json must be equal as JSON once its timestamps are set aside. Any difference, or
  one of them missing on one side, is a differing file: exit status 1.
- the other files (transcripts, instance.json, board pictures, clemcore's and sartco's run.json,
  requests, main.log, ...): byte-identical, or equal once times, durations, the checkout's
  path, the git commit, the interpreter's path and what each run.json records of its versions are
  set aside; these are listed apart and do not fail the comparison (run.json records more since
  the base, and a log holds timings).
On each side, its own folders' paths (results, tables, and with --checkouts the checkout clem ran
in, which clemcore writes into every episode as the model registry's `lookup_source`) read as
<results>, <tables> and <checkout>. Prints the counts and the first differing files with their
first differing line.
"""
from __future__ import annotations

import json
import os
import re
import sys
from pathlib import Path

RESULT_NAMES = {"scores.json", "results.csv", "raw.csv"}
TIME = re.compile(rb"\d{4}-\d\d-\d\d[T ]\d\d:\d\d:\d\d(?:[.,]\d+)?(?:[+-]\d\d:\d\d|Z)?|\b\d+:\d\d:\d\d(?:\.\d+)?\b"
                  rb"|\b\d+(?:\.\d+)? ?(?:s|ms|seconds|min)\b|\bgit [0-9a-f]{7,40}\b")
# keys whose values state when or where a run happened, not what it did
VOLATILE = {"timestamp", "start", "end", "created", "benchmark_start", "benchmark_end", "duration",
            "duration_seconds", "git_commit", "executable", "game_path", "python", "packages", "sartco_version",
            "path"}


def files(root: Path) -> dict[str, Path]:
    return {str(p.relative_to(root)): p for p in root.rglob("*") if p.is_file()}


def placed(data: bytes, places: dict[Path, bytes]) -> bytes:
    """The side's own folders (longest first) as their labels."""
    for path in sorted(places, key=lambda p: -len(str(p))):
        data = data.replace(str(path).encode(), places[path])
    return data


def without_times(data: bytes) -> bytes:
    return TIME.sub(b"<time>", data)


def strip(value, keys=frozenset({"timestamp"})):
    if isinstance(value, dict):
        return {k: strip(v, keys) for k, v in value.items() if k not in keys}
    if isinstance(value, list):
        return [strip(v, keys) for v in value]
    return value


def first_difference(a: bytes, b: bytes) -> str:
    for n, (x, y) in enumerate(zip(a.splitlines(), b.splitlines()), 1):
        if x != y:
            return f"line {n}: {x[:120]!r} / {y[:120]!r}"
    return f"lengths {len(a)} / {len(b)} bytes"


def compare(name: str, a: Path, b: Path, places: tuple[dict, dict], strict: bool) -> str | None:
    """None when equal (as the module doc says for this kind of file), else how they differ."""
    x, y = placed(a.read_bytes(), places[0]), placed(b.read_bytes(), places[1])
    if x == y:
        return None
    base = Path(name).name
    if base == "interactions.json" or (not strict and base.endswith(".json")):
        keys = frozenset({"timestamp"}) if strict else frozenset(VOLATILE)
        try:
            jx, jy = (strip(json.loads(v if strict else without_times(v)), keys) for v in (x, y))
        except ValueError as exc:
            return f"not JSON ({exc})"
        if jx == jy:
            return None
        return first_difference(json.dumps(jx, indent=1, sort_keys=True).encode(),
                                json.dumps(jy, indent=1, sort_keys=True).encode())
    tx, ty = without_times(x), without_times(y)
    return None if tx == ty else first_difference(tx, ty)


def main(argv: list[str]) -> int:
    checkouts: list[Path] = []
    if "--checkouts" in argv:
        i = argv.index("--checkouts")
        checkouts, argv = [Path(p).resolve() for p in argv[i + 1:i + 3]], argv[:i] + argv[i + 3:]
    if len(argv) not in (2, 4) or len(checkouts) not in (0, 2):
        print(__doc__, file=sys.stderr)
        return 2
    pairs = [(Path(argv[0]), Path(argv[1]))] + ([(Path(argv[2]), Path(argv[3]))] if len(argv) == 4 else [])
    places: tuple[dict, dict] = ({}, {})
    for side in (0, 1):
        for (label, pair) in zip((b"<results>", b"<tables>"), pairs):
            places[side][pair[side].resolve()] = label
        if len(pairs) == 2:  # the report links the transcripts by the results folder's path from the tables'
            relative = os.path.relpath(pairs[0][side].resolve(), pairs[1][side].resolve())
            places[side][Path(relative)] = b"<results>"
        if checkouts:
            places[side][checkouts[side]] = b"<checkout>"
    counts = {"result": [0, 0], "other": [0, 0]}
    shown: dict[str, list[str]] = {"result": [], "other": []}
    for k, (base, new) in enumerate(pairs):
        tables = k == 1
        fb, fn = files(base), files(new)
        for name in sorted(set(fb) | set(fn)):
            strict = tables or Path(name).name in RESULT_NAMES or Path(name).name == "interactions.json"
            kind = "result" if strict else "other"
            if name not in fb or name not in fn:
                why = f"only in {'the new' if name in fn else 'the base'} folder"
            else:
                why = compare(name, fb[name], fn[name], places, strict)
            counts[kind][why is not None] += 1
            if why is not None and len(shown[kind]) < 20:
                shown[kind].append(f"  {new.name if name in fn else base.name}/{name}: {why}")
    for kind, label in (("result", "result files (scores.json, results.csv, raw.csv, tables, interactions.json)"),
                        ("other", "other files (transcripts, pictures, instance files, run.json, logs)")):
        same, differ = counts[kind]
        print(f"{label}: {same} equal, {differ} differ")
        print("\n".join(shown[kind]))
    return 1 if counts["result"][1] else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
