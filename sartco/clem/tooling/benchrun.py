"""`sartco bench-run`: what the batching backend (sartco.clem.tooling.batching) buys against a model
server with a fixed latency, measured with the real `clem run`.

A local stub server (sartco.clem.tooling.stub_server: 127.0.0.1, `--latency` seconds per request,
answers from the episodes' gold code, stops by itself after its request or time budget) serves
the same cobot_instruct episodes twice, each run in its own scratch folder below `--out` that
holds its key.json and model_registry.json (the user's own files are never read or written) and
its results; both name the model `stub`:
  sequential/  `clem run -m stub` through clemcore's own openai_compatible backend (one request
               at a time: what a user has without this backend)
  batched/     `clem run -b <batch> -m stub` through openai_batching, `--concurrency` requests
               in flight
Printed per run: the wall time of `clem run` (process start to exit), the play span (first
request in to last answer out, as the server saw it) and the harness overhead: the share of the
play span in which no request was in flight (clemcore and the game stepping, executing,
scoring-side logging and saving files while the server waits), measured in that run; then the
speed-up (sequential / batched, of the play span and of the wall time). Both runs are scored
(`clem score`) and every scores.json of the batched run must equal the sequential run's (all of
it: meta, players, round and episode scores; only `player_models`, the registry entry with its
backend name, differs by design).
"""
from __future__ import annotations

import json
import os
import subprocess
import sys
import time
from pathlib import Path

from sartco.errors import UserError
from sartco.register import write_backends
from sartco.settings import workspace

from .stub_server import StubServer, answer_table

GAME = "cobot_instruct"
GAME_DIR = workspace() / "games" / GAME
DEFAULT_EXPERIMENTS = "sb_so_optimal_function_template,rb_so_repetition_template,rb_co_repetition_template"
MODEL = "stub"


def configure(parser) -> None:
    parser.add_argument("--experiments", default=DEFAULT_EXPERIMENTS,
                        help=f"cobot_instruct experiments, comma-separated (default: {DEFAULT_EXPERIMENTS})")
    parser.add_argument("--episodes", type=int, default=0, help="episodes per experiment (default: all)")
    parser.add_argument("--latency", type=float, default=0.5, help="seconds per request (default 0.5)")
    parser.add_argument("--concurrency", type=int, default=16, help="requests in flight (default 16)")
    parser.add_argument("--batch-size", type=int, default=0, help="clem run -b (default: --concurrency)")
    parser.add_argument("--out", default="results-bench", help="scratch and results folder (default results-bench)")
    parser.add_argument("--max-seconds", type=float, default=1800.0, help="the stub server's time budget")


def select_instances(experiments: list[str], episodes: int) -> dict:
    """The game's instances file cut to the named experiments (first `episodes` of each)."""
    data = json.loads((GAME_DIR / "in" / "instances.json").read_text(encoding="utf-8"))
    by_name = {e["name"]: e for e in data["experiments"]}
    unknown = [name for name in experiments if name not in by_name]
    if unknown:
        raise UserError(f"unknown {GAME} experiment(s) {', '.join(unknown)}; known: {', '.join(sorted(by_name))}")
    chosen = []
    for name in experiments:
        experiment = dict(by_name[name])
        if episodes > 0:
            experiment["game_instances"] = experiment["game_instances"][:episodes]
        chosen.append(experiment)
    return {**data, "experiments": chosen}


def write_scratch(folder: Path, base_url: str, backend: str, concurrency: int) -> None:
    """key.json, model_registry.json (the model `stub` on `backend`) and sartco's backend files
    (sartco.register), in `folder` (the cwd of clem). Both runs name the model `stub`, so their files can be compared."""
    folder.mkdir(parents=True, exist_ok=True)
    write_backends(folder)
    (folder / "key.json").write_text(json.dumps({"openai_compatible": {"api_key": "none", "base_url": base_url}}))
    entry = {"model_name": MODEL, "model_id": MODEL, "backend": backend, "release_date": None, "open_weight": True,
             "parameters": "0", "languages": ["en"], "context_size": "n/a", "license": {"name": "none", "url": ""},
             "model_config": {"concurrency": concurrency} if backend == "openai_batching" else {}}
    (folder / "model_registry.json").write_text(json.dumps([entry], indent=1))


def clem_env() -> dict[str, str]:
    """The environment of a clem process that finds the workspace's games (sartco.settings)."""
    return dict(os.environ, CLEMBENCH_HOME=str(GAME_DIR.parents[1]))


def clem(args: list[str], cwd: Path) -> float:
    """Run a clem command in `cwd` (games from the workspace, sartco.settings); its wall time in seconds."""
    env = clem_env()
    clem_bin = Path(sys.executable).parent / "clem"
    start = time.monotonic()
    done = subprocess.run([str(clem_bin), *args], cwd=cwd, env=env, capture_output=True, text=True)
    if done.returncode != 0:
        raise UserError(f"clem {' '.join(args)} failed: {(done.stderr or done.stdout).strip().splitlines()[-1:]}")
    return time.monotonic() - start


def timed_run(server: StubServer, backend: str, batch: int, instances: Path, folder: Path, concurrency: int) -> dict:
    """One `clem run` of the model `stub` on `backend` (scratch folder `folder`, results in
    folder/results), timed; the play span and busy time from the server's intervals of this run."""
    write_scratch(folder, server.base_url, backend, concurrency)
    first = len(server.intervals)
    wall = clem(["run", "-g", GAME, "-m", MODEL, "-b", str(batch), "-i", str(instances.with_suffix("")),
                 "-r", str(folder / "results"), "-l", "512"], folder)
    clem(["score", "-g", GAME, "-r", str(folder / "results")], folder)
    mine = server.intervals[first:]
    if not mine:
        raise UserError(f"the {backend} run sent no request to the stub server")
    start, end = min(a for a, _ in mine), max(b for _, b in mine)
    span = end - start
    busy = server.busy_time(start, end)
    return {"wall": wall, "span": span, "requests": len(mine), "overhead": 1 - busy / span if span else 0.0,
            "scores": scores_of(folder / "results")}


def scores_of(results: Path) -> dict[str, dict]:
    """Every scores.json below a results folder, by relative path, without `player_models` (the
    registry entry: backend name, config and lookup path differ between the two runs by design)."""
    out = {}
    for path in sorted(results.rglob("scores.json")):
        data = json.loads(path.read_text(encoding="utf-8"))
        data.pop("player_models", None)
        out[str(path.relative_to(results))] = data
    return out


def bench(experiments: list[str], episodes: int, latency: float, concurrency: int, batch: int, out: Path,
          max_seconds: float) -> dict:
    instances = select_instances(experiments, episodes)
    games = [i for e in instances["experiments"] for i in e["game_instances"]]
    requests = sum(len(i["turns"]) for i in games)
    out = out.resolve()
    if out.exists():
        raise UserError(f"{out} exists: remove it or choose another --out")
    out.mkdir(parents=True)
    instances_file = out / "instances_bench.json"
    instances_file.write_text(json.dumps(instances), encoding="utf-8")
    with StubServer(answer_table(games), latency=latency, max_requests=2 * requests + 50,
                    max_seconds=max_seconds) as server:
        sequential = timed_run(server, "openai_compatible", 1, instances_file, out / "sequential", concurrency)
        batched = timed_run(server, "openai_batching", batch, instances_file, out / "batched", concurrency)
    seq_scores, batch_scores = sequential.pop("scores"), batched.pop("scores")
    return {"episodes": len(games), "requests": requests, "unknown": server.unknown, "sequential": sequential,
            "batched": batched, "scores": len(seq_scores),
            "scores_equal": len(seq_scores) == len(games) and seq_scores == batch_scores}


def run(args) -> int:
    if args.latency < 0 or args.concurrency < 1:
        raise UserError("--latency >= 0 and --concurrency >= 1 expected")
    batch = args.batch_size or args.concurrency
    experiments = [e.strip() for e in args.experiments.split(",") if e.strip()]
    print(f"bench-run: {GAME} {', '.join(experiments)}; stub server latency {args.latency:g} s; "
          f"batched: -b {batch}, concurrency {args.concurrency}", flush=True)
    r = bench(experiments, args.episodes, args.latency, args.concurrency, batch, Path(args.out), args.max_seconds)
    print(f"episodes {r['episodes']}, requests {r['requests']} per run, unanswerable {r['unknown']}")
    for name in ("sequential", "batched"):
        m = r[name]
        print(f"{name:>10}: clem run {m['wall']:7.1f} s, play span {m['span']:7.1f} s "
              f"({m['requests']} requests), harness overhead {100 * m['overhead']:4.1f} % of the play span")
    s, b = r["sequential"], r["batched"]
    print(f"speed-up batched vs sequential: {s['span'] / b['span']:.1f}x play span, {s['wall'] / b['wall']:.1f}x "
          f"wall time (ideal {min(args.concurrency, batch)}x)")
    print(f"scores.json: {r['scores']} per run, batched == sequential: {'yes' if r['scores_equal'] else 'NO'}")
    return 0 if r["scores_equal"] and r["unknown"] == 0 else 1
