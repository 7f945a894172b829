#!/usr/bin/env python3
"""Rewards per second of sartco.reward.score with the sandbox on Ray, by the number of Ray worker
CPUs, beside this machine's local sandbox, all in this one command (docs/training.md).

    scripts/bench_ray.py [--limit N] [--batch 512] [--cpus 1 2]

The answers: the gold answers of the single-turn episodes of `sartco bench-reward`'s instance
files (cobot_instruct's instances.json and, when made, instances_published.json), scored without
probes (one program each: what a GRPO step's reward costs at least). For each setting a fresh
sandbox is put in use (`sartco.program.use`): the local one with N template processes, and a
local Ray instance started with num_cpus=N (`RaySandbox(None, num_cpus=N)`: each Ray worker runs
its programs in its own node-local sandbox, a fresh confined process per program). Each first
scores the erring player's answers (not timed: workers started, imports done), then the gold
answers are timed; rewards/s = answers / wall seconds. The machine's load average is printed.
"""
from __future__ import annotations

import argparse
import os
import sys
import time

from sartco.program import cluster, pool, use
from sartco.reward import Episodes, score
from sartco.reward.bench import answer_sets, instance_files


def rate(sandbox, gold: list, warm: list, episodes: Episodes, batch: int) -> float:
    use(sandbox)
    try:
        for i in range(0, len(warm), batch):
            score(warm[i:i + batch], episodes, probes=False)
        start = time.perf_counter()
        for i in range(0, len(gold), batch):
            score(gold[i:i + batch], episodes, probes=False)
        return len(gold) / (time.perf_counter() - start)
    finally:
        use(None)
        sandbox.close()


def main(argv: list[str]) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--limit", type=int, default=None, help="episodes per experiment (default: all)")
    parser.add_argument("--batch", type=int, default=512)
    parser.add_argument("--cpus", type=int, nargs="+", default=[1, 2])
    args = parser.parse_args(argv)
    episodes = Episodes.from_files(instance_files(None))
    if args.limit is not None:
        seen: dict[str, int] = {}
        keep = {}
        for key, instance in episodes.items():
            experiment = key.split("/", 1)[0]
            seen[experiment] = seen.get(experiment, 0) + 1
            if seen[experiment] <= args.limit:
                keep[key] = instance
        episodes = Episodes(keep)
    sets = answer_sets(episodes)
    gold, warm = sets[("gold", "single-turn")], sets[("erring", "single-turn")][:args.batch]
    print(f"scripts/bench_ray.py: {len(gold)} single-turn gold answers, no probes, batches of {args.batch}; "
          f"{os.cpu_count()} CPUs, load average {os.getloadavg()[0]:.1f}")
    print(f"{'sandbox':<34} {'rewards/s':>10}")
    for n in args.cpus:
        print(f"{f'local, {n} template process(es)':<34} {rate(pool.LocalSandbox(workers=n), gold, warm, episodes, args.batch):>10,.0f}",
              flush=True)
        ray = cluster.RaySandbox(None, num_cpus=n, include_dashboard=False)
        print(f"{f'Ray, local instance, {n} CPU(s)':<34} {rate(ray, gold, warm, episodes, args.batch):>10,.0f}", flush=True)
    print(f"load average at the end {os.getloadavg()[0]:.1f}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
