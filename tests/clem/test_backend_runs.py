"""The openai_batching backend in real `clem run`s against the stub server: the response cache
serves a repeated run without a request reaching the server, and a hung server with a 2 s
timeout ends every request (retried, then aborted, logged) instead of hanging the run."""
import json
import time

from sartco.clem import benchrun
from sartco.clem.stub_server import StubServer, answer_table

EXPERIMENTS = ["rb_so_repetition_template", "sb_so_first_order_template"]


def setup(tmp_path, server: StubServer, **config) -> tuple:
    instances = benchrun.select_instances(EXPERIMENTS, 2)
    file = tmp_path / "instances_small.json"
    file.write_text(json.dumps(instances))
    benchrun.write_scratch(tmp_path, server.base_url, "openai_batching", 4)
    registry = json.loads((tmp_path / "model_registry.json").read_text())
    registry[0]["model_config"].update(config)
    (tmp_path / "model_registry.json").write_text(json.dumps(registry))
    return instances, file.with_suffix("")


def run(tmp_path, instances_file, results: str, batch: int) -> None:
    benchrun.clem(["run", "-g", benchrun.GAME, "-m", benchrun.MODEL, "-b", str(batch), "-i", str(instances_file),
                   "-r", str(tmp_path / results)], tmp_path)
    benchrun.clem(["score", "-g", benchrun.GAME, "-r", str(tmp_path / results)], tmp_path)


def test_the_cache_serves_a_repeated_run_without_the_server(tmp_path):
    games = [i for e in benchrun.select_instances(EXPERIMENTS, 2)["experiments"] for i in e["game_instances"]]
    with StubServer(answer_table(games), latency=0.0) as server:
        _, file = setup(tmp_path, server, cache="cache")
        run(tmp_path, file, "first", 4)
        asked = server.requests
        assert asked >= len(games) and server.unknown == 0
        run(tmp_path, file, "again", 4)
        assert server.requests == asked   # the second run: every answer from the cache
    first, again = benchrun.scores_of(tmp_path / "first"), benchrun.scores_of(tmp_path / "again")
    assert len(first) == len(games) and first == again
    assert len(list((tmp_path / "cache").rglob("*.json"))) == asked


def test_a_hung_server_with_a_2s_timeout_ends_the_run(tmp_path):
    with StubServer({}, hang=True, max_seconds=300) as server:
        _, file = setup(tmp_path, server, timeout=2, retries=1, backoff=0.01)
        start = time.monotonic()
        run(tmp_path, file, "results", 1)   # sequential: each episode's request fails, the run goes on
        took = time.monotonic() - start
        assert server.requests == 2 * 4       # 4 episodes, 2 tries each
    assert took < 120, took
    log = (tmp_path / "clembench.log").read_text()
    assert log.count("request aborted") == 4 and "APITimeoutError after 2 tries" in log
    assert not list((tmp_path / "results").rglob("scores.json"))   # no episode scored as if the model had answered


def test_sample_plays_every_episode_n_times_through_openai_batching(tmp_path):
    import os
    import subprocess
    import sys
    games = [i for e in benchrun.select_instances(EXPERIMENTS, 2)["experiments"] for i in e["game_instances"]]
    with StubServer(answer_table(games), latency=0.0) as server:
        _, file = setup(tmp_path, server, cache="cache")   # temperature 0.7: the cache must not answer
        done = subprocess.run([sys.executable, "-m", "sartco", "sample", "-g", benchrun.GAME, "-m", benchrun.MODEL,
                               "-n", "2", "-t", "0.7", "-b", "4", "-i", str(file), "-r", "res"], cwd=tmp_path,
                              env=dict(os.environ, CLEMBENCH_HOME=str(benchrun.GAME_DIR.parents[1])),
                              capture_output=True, text=True, timeout=600)
        assert done.returncode == 0, done.stderr[-2000:]
        one_run = sum(len(i["turns"]) for i in games)
        assert server.requests == 2 * one_run and server.unknown == 0
    for k in (1, 2):
        assert len(list((tmp_path / "res" / "samples" / f"s{k}").rglob("scores.json"))) == len(games)
    assert not (tmp_path / "cache").exists()
