"""What the function probes cost: per probed episode of an instance file, the time of the
episode's own build (sartco.clem.core.answer_builds.build_for, the baseline) beside the time of its probes
(sartco.clem.core.probes.run_probes), both on the gold answer, in the same command.

    .venv/bin/python tools/bench_probes.py [INSTANCE_FILE] [--per-cell N]
"""
from __future__ import annotations

import argparse
import json
import statistics
import time
from pathlib import Path

from sartco.clem.core.answer_builds import build_for
from sartco.clem.core.probes import probed, run_probes

DEFAULT = Path(__file__).resolve().parents[1] / "games" / "cobot_instruct" / "in" / "instances.json"


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("instances", nargs="?", type=Path, default=DEFAULT)
    parser.add_argument("--per-cell", type=int, default=20, help="episodes per experiment (default 20)")
    args = parser.parse_args()
    episodes = [ep for e in json.loads(args.instances.read_text())["experiments"]
                for ep in e["game_instances"][:args.per_cell] if probed(ep)]
    build_for(episodes[0], episodes[0]["gold_code"])  # start the workers outside the timing
    own, probes, shares, counts = [], [], [], []
    for ep in episodes:
        t = time.perf_counter()
        build_for(ep, ep["gold_code"])
        own.append(time.perf_counter() - t)
        t = time.perf_counter()
        result = run_probes(ep, ep["gold_code"])
        shares.append(result["share"])
        counts.append(len(result["probes"]))
        probes.append(time.perf_counter() - t)
    print(f"{len(episodes)} probed episodes; own build {1000 * statistics.mean(own):.1f} ms, probes "
          f"{1000 * statistics.mean(probes):.1f} ms per episode (median {1000 * statistics.median(probes):.1f} ms); "
          f"probes / own build = {sum(probes) / sum(own):.1f}; gold FG mean {statistics.mean(shares):.3f}; "
          f"probes per episode {min(counts)}..{max(counts)}")


if __name__ == "__main__":
    main()
