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

from sartco.follower import FollowError, follow
from sartco.program import compare, execute_many
from sartco.program.gold import DEFAULT_DATA, base_of, samples
from sartco.world import DEFAULT_COLS, DEFAULT_ROWS

# dialogue key -> (task, source); multi_turn is the first-order task, one instruction per turn
SIMPLE_VARIANTS = {
    "multi_turn": ("first_order", "template"),
    "single_turn_sc": ("sequence_function", "template"),
    "single_turn": ("optimal_function", "template"),
    "single_turn_hai": ("optimal_function", "human"),
    "single_turn_hai_sc": ("sequence_function", "human"),
    "single_turn_mg": ("optimal_function", "model"),
}
REGULAR_VARIANTS = {"regular": ("repetition", "template"), "regular_hai": ("repetition", "human"),
                    "regular_mg": ("repetition", "model")}


def evaluate(data: Path = DEFAULT_DATA, files: list[str] | None = None):
    """{(file, variant): {"n", "es", "parsed", "failures": [...]}} over the published files."""
    results: dict[tuple[str, str], dict] = {}
    pending = []  # (result row, sample id, texts, program, gold board), run in one batch
    gold_stems = sorted(p.stem for p in (data / "gold_boards").glob("*.json"))
    for path in sorted((data / "published").glob("*.json")):
        name = path.stem
        if files and name not in files:
            continue
        gold = json.loads((data / "gold_boards" / f"{base_of(name, gold_stems) or name}.json").read_text())
        doc = json.loads(path.read_text())
        for _, sid, sample in samples(doc):
            regular = "occupied_rows" in sample
            variants = REGULAR_VARIANTS if regular else SIMPLE_VARIANTS
            for variant, dialogue in sample["dialogues"].items():
                if variant not in variants:
                    continue
                task, source = variants[variant]
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
    ap.add_argument("--data", type=Path, default=DEFAULT_DATA)
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
