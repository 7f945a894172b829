"""Runs that repeat exactly (issue 33), through the real commands on small results folders:
`sartco resume` plays the episodes the run chose (`-e`) with the run's settings (`-l`, `-t`, `-b`)
and its result equals an uninterrupted run's byte for byte (timestamps aside), also after two
resumes in a row and after a harness-error episode left unscored; run.json records what is needed
to repeat the run and is rewritten as episodes are played; `sartco report` prints the settings its
numbers come from."""
import json
from importlib import metadata
import shutil
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from forkserver import command
from play_helpers import REPO, clem, clem_process, sartco, sh, stub_scratch
from sartco.clem.tooling import benchrun
from sartco.clem.tooling.stub_server import StubServer, answer_table, conversation_key

BIN = Path(sys.executable).parent
GAME = "cobot_instruct"
EXPERIMENT = "sb_so_optimal_function_template"   # 2 episodes in instances_smoke
SETTINGS = ["-l", "250", "-t", "0.0", "-b", "2"]
EXPERIMENTS_SMALL = ["rb_so_repetition_template", "sb_so_first_order_template"]   # the stub server's runs


def sartco_process(*args, cwd, env) -> subprocess.CompletedProcess:
    """The `sartco` process, for a resume whose model is the stub server's (backend files, key.json
    and model registry in `cwd`); the other commands run in this process (play_helpers.sartco)."""
    return command([BIN / "sartco", *args], cwd=cwd, timeout=600, env=env)


def played(results: Path, *extra: str) -> Path:
    """The `clem run` process (it writes run.json), then `clem score` in this process."""
    sh(str(BIN / "clem"), "run", "-g", GAME, "-m", "mock", "-i", "instances_smoke", "-e", EXPERIMENT, *extra,
       "-r", str(results))
    clem("score", "-r", results)
    return results / "mock" / GAME


def without_times(value):
    if isinstance(value, dict):
        return {k: without_times(v) for k, v in value.items() if k != "timestamp"}
    if isinstance(value, list):
        return [without_times(v) for v in value]
    return value


def episode_files(game_dir: Path) -> dict:
    """Every episode's scores.json and instance.json (bytes) and interactions.json (without its
    timestamps), by path below the game folder."""
    out = {}
    for path in sorted(game_dir.glob("*/instance_*/*.json")):
        key = str(path.relative_to(game_dir))
        if path.name in ("scores.json", "instance.json"):
            out[key] = path.read_bytes()
        elif path.name == "interactions.json":
            out[key] = without_times(json.loads(path.read_text()))
    return out


@pytest.fixture(scope="module")
def clean(tmp_path_factory):
    return played(tmp_path_factory.mktemp("clean") / "results", *SETTINGS)


def test_resume_of_one_experiment_plays_it_alone_with_the_runs_settings(tmp_path, clean):
    game_dir = played(tmp_path / "results", *SETTINGS)
    for resume_no, game_id in enumerate((1, 0), start=1):   # two resumes in a row, each after a lost episode
        shutil.rmtree(game_dir / EXPERIMENT / f"instance_{game_id:05d}")
        done = sartco("resume", "-r", tmp_path / "results", "-g", GAME, "-m", "mock")
        assert done.returncode == 0, done.stdout[-2000:] + done.stderr[-2000:]
        assert (f"2 episodes in instances_smoke.json (experiment {EXPERIMENT}), 1 to play, 0 to score "
                f"(temperature 0.0, max_tokens 250, batch size 2)") in done.stdout
        assert "all 2 episodes scored" in done.stdout
    assert sorted(p.name for p in game_dir.iterdir() if p.is_dir()) == [EXPERIMENT]   # nothing else played
    assert episode_files(game_dir) == episode_files(clean)   # byte for byte, max_tokens 250 included

    run = json.loads((game_dir / "run.json").read_text())
    assert [(s["experiment"], s["resume"], s["generation"], s["batch_size"], s["episodes_played"])
            for s in run["sessions"]] == [
        (EXPERIMENT, False, {"temperature": 0.0, "max_tokens": 250}, 2, 2),
        (None, True, {"temperature": 0.0, "max_tokens": 250}, 2, 1),
        (None, True, {"temperature": 0.0, "max_tokens": 250}, 2, 1)]
    assert [s["episodes"] for s in run["sessions"][1:]] == [[[EXPERIMENT, 1]], [[EXPERIMENT, 0]]]
    assert run["generation"] == {"temperature": 0.0, "max_tokens": 250} and run["batch_size"] == 2
    assert set(run["packages"]) == {"sartco-bench", "clemcore", "codebleu", "tree-sitter", "tree-sitter-python", "numpy"}
    assert all(run["packages"].values()) and run["python"]["version"].count(".") == 2
    assert run["seeds"] == {"erring_players": 42, "erring_slip_rate": 0.3, "erring_fix_rate": 0.5, "function_probes": 0}
    assert run["instance_file"]["generated"]["dataset"]["generator_seed"] == 42
    assert run["instance_file"]["generated"]["generator"] == {"package": "sartco-bench",
                                                              "version": metadata.version("sartco-bench")}
    assert run["instance_file"]["generated"]["dataset_manifest"]["path"] == "instances/v1/manifest.json"

    report = sartco("report", "-r", tmp_path / "results", "--out", tmp_path / "scores")
    assert report.returncode == 0, report.stderr
    assert (f"run mock / cobot_instruct: played with temperature 0.0, max_tokens 250, batch size 2 ({EXPERIMENT}); "
            "games/cobot_instruct/in/instances_smoke.json sha256") in report.stdout
    assert "| 2 | 2 | 0 | 0 | 0 | 0 |" in (tmp_path / "scores" / "completeness.md").read_text()

    # an option against run.json is refused, naming it; nothing is played
    shutil.rmtree(game_dir / EXPERIMENT / "instance_00001")
    done = sartco("resume", "-r", tmp_path / "results", "-g", GAME, "-m", "mock", "-l", "300")
    assert done.returncode == 2
    assert ("-l 300 differs from the max_tokens 250 that sb_so_optimal_function_template was played with "
            "(run.json); leave -l out") in done.stderr
    assert not (game_dir / EXPERIMENT / "instance_00001").exists()


def test_a_killed_run_says_how_far_it_got(tmp_path):
    results = tmp_path / "results"
    game_dir = results / "mock" / GAME
    run = subprocess.Popen([str(BIN / "clem"), "run", "-g", GAME, "-m", "mock", "-e", EXPERIMENT, "-r", str(results)],
                           cwd=REPO, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    try:
        deadline = time.monotonic() + 300
        while len(list(game_dir.glob("*/instance_*/interactions.json"))) < 5 and time.monotonic() < deadline:
            assert run.poll() is None, "the run of 130 episodes ended before it could be stopped"
            time.sleep(0.05)
    finally:
        run.send_signal(signal.SIGKILL)
        run.wait()
    finished = len(list(game_dir.glob("*/instance_*/interactions.json")))
    record = json.loads((game_dir / "run.json").read_text())
    assert record["end"] is None and finished >= 5
    # every started episode is counted: the finished ones and at most the one that was playing
    assert finished <= record["sessions"][0]["episodes_played"] <= finished + 1
    assert record["counts"]["episodes_played"] == record["sessions"][0]["episodes_played"]


def stub_setup(folder: Path, server: StubServer, **config) -> Path:
    return stub_scratch(folder, server.base_url, EXPERIMENTS_SMALL, **config)[1]


def stub_games() -> list[dict]:
    chosen = benchrun.select_instances(EXPERIMENTS_SMALL, 2)
    return [i for e in chosen["experiments"] for i in e["game_instances"]]


def test_one_resume_plays_the_unscored_harness_errors_again(tmp_path):
    """A run whose model server failed one episode, not yet scored: one resume scores the others,
    plays that one again and leaves the folder as an uninterrupted run leaves it."""
    games = stub_games()
    env = benchrun.clem_env()
    with StubServer(answer_table(games), latency=0.0) as server:
        file = stub_setup(tmp_path / "clean", server)
        clem_process(["run", "-g", GAME, "-m", benchrun.MODEL, "-l", "512", "-b", "4", "-i", str(file), "-r", "results"],
                     tmp_path / "clean")
        clem("score", "-g", GAME, "-r", tmp_path / "clean" / "results")
    failing = frozenset({conversation_key(games[1]["turns"][:1])})
    with StubServer(answer_table(games), latency=0.0, failing=failing) as server:
        file = stub_setup(tmp_path / "run", server, retries=1, backoff=0.01)
        first_url = server.base_url
        clem_process(["run", "-g", GAME, "-m", benchrun.MODEL, "-l", "512", "-b", "4", "-i", str(file), "-r", "results"],
                     tmp_path / "run")   # not scored
    with StubServer(answer_table(games), latency=0.0) as server:
        benchrun.write_scratch(tmp_path / "run", server.base_url, "openai_batching", 4)
        done = sartco_process("resume", "-r", "results", "-g", GAME, "-m", benchrun.MODEL, cwd=tmp_path / "run",
                              env=env)
        assert done.returncode == 0, done.stdout[-2000:] + done.stderr[-2000:]
        assert server.requests == len(games[1]["turns"])   # the failed episode alone is asked again
    assert "4 episodes in instances_small.json (all experiments), 1 to play, 4 to score" in done.stdout
    assert "no answer again" not in done.stdout
    clean, resumed = (episode_files(tmp_path / d / "results" / "stub" / GAME) for d in ("clean", "run"))
    for files in (clean, resumed):   # of the model entry the generation settings: its registry's path differs
        for key in [k for k in files if k.endswith("scores.json")]:
            files[key] = json.loads(files[key])
        for key in [k for k in files if k.endswith("interactions.json") or k.endswith("scores.json")]:
            files[key]["player_models"] = {i: m["gen_args"] for i, m in files[key]["player_models"].items()}
    assert resumed == clean and len(clean) == 12
    run = json.loads((tmp_path / "run" / "results" / "stub" / GAME / "run.json").read_text())
    assert [m["base_url"].rstrip("/") for s in run["sessions"] for m in s["models"]] == [first_url, server.base_url]
    assert "api_key" not in json.dumps(run)   # key.json's key is never recorded
    assert (run["generation"], run["batch_size"]) == ({"temperature": 0.0, "max_tokens": 512}, 4)


def test_resume_without_play_says_nothing_about_the_server(tmp_path, clean):
    results = tmp_path / "results"
    shutil.copytree(clean.parent, results / "mock")
    (results / "mock" / GAME / EXPERIMENT / "instance_00000" / "scores.json").unlink()
    done = sartco("resume", "-r", results, "-g", GAME, "-m", "mock")
    assert done.returncode == 0 and "0 to play, 1 to score (nothing to play)" in done.stdout, done.stdout[-2000:]


def test_run_json_keeps_the_settings_and_no_secret():
    from sartco.clem.core.provenance import without_secrets
    entry = {"max_tokens": 250, "temperature": 0.7, "apiKey": "k", "api_key": "k", "session-token": "t",
             "model_config": {"base_url": "http://h/v1", "Authorization": "Bearer y", "keys": ["k"]}}
    assert without_secrets(entry) == {"max_tokens": 250, "temperature": 0.7, "model_config": {"base_url": "http://h/v1"}}


def test_clem_serve_records_stay_out_of_git():
    done = subprocess.run(["git", "check-ignore", "openenv-records/episode.json"], cwd=REPO, capture_output=True, text=True)
    assert done.returncode == 0, "openenv-records/ (clem serve's default records folder) is not ignored"
