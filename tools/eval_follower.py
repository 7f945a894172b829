"""Run the rule-based follower on every published instruction and score the boards it builds.

    python tools/eval_follower.py [--data ../shared/sartco-data] [--json OUT] [--failures N]

For every sample of every published file and every instruction variant the follower's code is
executed on a fresh 8x8 board (after the given object function for regular boards) and the
board is compared with the gold board (gold_boards/<base file>.json; a test variant shares its
test file's boards). ES = 1 when the program ran and built exactly the gold board. The follower
never sees the gold code; this tool reads only instructions, the given object function, and the
gold boards. The programs run in the sandbox (sartco.program.execute_many) and are compared
with sartco.program.compare.
"""
from __future__ import annotations

import argparse
import json
import sys
from collections import defaultdict
from pathlib import Path

from sartco.dataset import DIALOGUE_KEYS, SHARED_DATA, SIMPLE
from sartco.follower import FollowError, follow
from sartco.program import compare, execute_many
from sartco.published import files as published
from sartco.world import DEFAULT_COLS, DEFAULT_ROWS


def evaluate(data: Path = SHARED_DATA, files: list[str] | None = None):
    """{(file, variant): {"n", "es", "parsed", "failures": [...]}} over the published files; a
    variant is a dialogue key of the file's board kind (multi_turn: one instruction per turn)."""
    results: dict[tuple[str, str], dict] = {}
    pending = []  # (result row, sample id, texts, program, gold board), run in one batch
    for path in sorted((data / "published").glob("*.json")):
        name = path.stem
        if files and name not in files:
            continue
        gold = published.gold_boards(data / "gold_boards", path.name) or {}
        kind = published.name_of(path.name).kind
        regular = kind != SIMPLE
        for sid, sample in published.read_samples(path):
            for variant, dialogue in sample["dialogues"].items():
                if variant not in DIALOGUE_KEYS or DIALOGUE_KEYS[variant].task not in kind.tasks():
                    continue
                task, source = DIALOGUE_KEYS[variant].task, DIALOGUE_KEYS[variant].instructions
                texts = [turn["<Programmer>"] for turn in dialogue["instructions"]]
                context = sample["code"]["function"] if regular else ""
                r = results.setdefault((name, variant), {"source": source, "task": task, "n": 0, "es": 0,
                                                         "parsed": 0, "failures": []})
                r["n"] += 1
                try:
                    code = follow(texts, task, context=context)
                except FollowError as exc:
                    r["failures"].append((sid, "parse", str(exc), texts))
                    continue
                r["parsed"] += 1
                program = ((context + "\n" if regular else "")
                           + f"board = init_board({DEFAULT_ROWS}, {DEFAULT_COLS})\n" + code)
                pending.append((r, sid, texts, program, gold[sid]))
    outcomes = execute_many([program for *_, program, _ in pending], rows=DEFAULT_ROWS, cols=DEFAULT_COLS)
    for (r, sid, texts, _, target), ex in zip(pending, outcomes):
        if ex.ok and compare(ex.cells, target).es:
            r["es"] += 1
        else:
            r["failures"].append((sid, "run" if not ex.ok else "board", ex.message, texts))
    return results


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--data", type=Path, default=SHARED_DATA)
    ap.add_argument("--file", action="append", help="only these published files (stem), repeatable")
    ap.add_argument("--failures", type=int, default=0, help="show this many failures per file/variant")
    ap.add_argument("--json", type=Path, help="write the table as JSON")
    args = ap.parse_args(argv)
    if not (args.data / "published").is_dir():
        print(f"eval_follower: no published data in {args.data}", file=sys.stderr)
        return 2
    results = evaluate(args.data, args.file)
    print(f"{'file':24} {'variant':20} {'source':9} {'task':18} {'n':>5} {'parsed':>7} {'run err':>7} "
          f"{'other':>6} {'ES %':>7}")
    totals = defaultdict(lambda: [0, 0])
    for (name, variant), r in sorted(results.items()):
        kinds = [kind for _, kind, _, _ in r["failures"]]
        r["run_errors"], r["other_board"] = kinds.count("run"), kinds.count("board")
        print(f"{name:24} {variant:20} {r['source']:9} {r['task']:18} {r['n']:5d} {r['parsed']:7d} "
              f"{r['run_errors']:7d} {r['other_board']:6d} {100 * r['es'] / r['n']:7.1f}")
        totals[r["source"]][0] += r["es"]
        totals[r["source"]][1] += r["n"]
        for sid, kind, message, texts in r["failures"][: args.failures]:
            print(f"    [{kind}] {sid}: {message[:160]}\n        {' || '.join(texts)[:300]!r}")
    for source, (es, n) in totals.items():
        print(f"total {source:9} {es}/{n} = {100 * es / n:.1f}%")
    print("parsed: the follower wrote code; run err: the code failed under the world's rules; "
          "other: it ran but built another board")
    if args.json:
        table = [{"file": f, "variant": v, **{k: r[k] for k in ("source", "task", "n", "parsed", "run_errors", "other_board", "es")},
                  "es_percent": round(100 * r["es"] / r["n"], 1)} for (f, v), r in sorted(results.items())]
        args.json.write_text(json.dumps(table, indent=1) + "\n")
    template_ok = all(r["es"] == r["n"] for r in results.values() if r["source"] == "template")
    return 0 if template_ok else 1


if __name__ == "__main__":
    sys.exit(main())
