"""Time code_bleu per call on the gold programs of a dataset (not a test: numbers depend on the machine).

    python -m sartco.scores.bench_codebleu instances/published [-n 1000]

Pairs each gold program with another one (gold i against gold i+7), which is as hard as a real
answer (same length and vocabulary). Four measurements:
  calc_codebleu (package)      codebleu's own function, for comparison
  code_bleu, nothing memoised  every per-program analysis done afresh (the first episode of a gold)
  code_bleu, gold memoised     the gold was analysed before, the answer is new (the usual case)
  code_bleu, same pair again   an answer scored before (e.g. the mock player, re-scoring)
"""
from __future__ import annotations

import argparse
import json
import logging
import statistics
import time
from pathlib import Path

from sartco.instances.storage import FILE_ORDER

from . import metrics
from .metrics import LANG, WEIGHTS, code_bleu


def _timed(fn, pairs, before=None) -> list[float]:
    times = []
    for pred, gold in pairs:
        if before:
            before(gold)
        start = time.perf_counter()
        fn(pred, gold)
        times.append(time.perf_counter() - start)
    return times


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("dataset", type=Path, help="a dataset folder (sartco import / sartco generate)")
    parser.add_argument("-n", type=int, default=1000, help="number of pairs (at most 1,000 keeps the memo from thrashing)")
    args = parser.parse_args(argv)
    from codebleu import calc_codebleu

    programs = []
    for name in sorted(FILE_ORDER):
        path = args.dataset / name
        if not path.is_file():
            continue
        for record in json.loads(path.read_text()):
            programs += [code["total_code"] for code in record["code"].values()]
    if not programs:
        parser.error(f"no dataset files in {args.dataset}")
    programs = programs[:: max(1, len(programs) // args.n)][: args.n]
    pairs = [(programs[i], programs[(i + 7) % len(programs)]) for i in range(len(programs))]
    # answers unlike any gold (a comment makes them new texts), so that only the gold is memoised
    fresh = [(pred + f"\n# answer {i}", gold) for i, (pred, gold) in enumerate(pairs)]
    logging.disable(logging.WARNING)  # calc_codebleu's data-flow warning

    def cold(_gold):
        metrics._analyse.cache_clear()
        metrics._code_bleu.cache_clear()

    def gold_seen(gold):
        metrics._code_bleu.cache_clear()
        metrics._analyse(gold.strip())

    runs = [
        ("calc_codebleu (package)", _timed(lambda p, g: calc_codebleu([g], [p], LANG, WEIGHTS)["codebleu"], pairs)),
        ("code_bleu, nothing memoised", _timed(code_bleu, pairs, cold)),
        ("code_bleu, gold memoised", _timed(code_bleu, fresh, gold_seen)),
    ]
    for pred, gold in fresh:  # fill the pair memo
        code_bleu(pred, gold)
    runs.append(("code_bleu, same pair again", _timed(code_bleu, fresh)))
    for name, times in runs:
        print(f"{name:28} {len(times)} calls: mean {statistics.mean(times) * 1e3:.2f} ms, "
              f"median {statistics.median(times) * 1e3:.2f} ms, max {max(times) * 1e3:.2f} ms")
    lengths = [len(p) for p, _ in pairs]
    print(f"programs: {len(pairs)}, {min(lengths)}..{max(lengths)} characters, mean {statistics.mean(lengths):.0f}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
