"""`sartco suite` for your own model (issue 44): -l recorded in run.json, the report's path, Ctrl-C
in one line that keeps the episodes, the same command again equal to an uninterrupted run, and a
second suite into a folder with runs refused before playing, with advice that works."""
from __future__ import annotations

import importlib.util
import json
import os
import re
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from forkserver import command
from sartco.clem.tooling import benchrun
from sartco.clem.tooling.stub_server import StubServer, answer_table

REPO = Path(__file__).resolve().parents[2]
BIN = Path(sys.executable).parent
SMOKE = REPO / "games" / "cobot_instruct" / "in" / "instances_smoke.json"


def suite_args(results: str) -> list[str]:
    return [str(BIN / "sartco"), "suite", "-r", results, "--out", f"{results}-tables", "-m", benchrun.MODEL, "--erring",
            "-g", "cobot_instruct", "-i", "instances_smoke", "-l", "512", "-j", "1"]


def _compare():
    spec = importlib.util.spec_from_file_location("compare_results", REPO / "scripts" / "compare_results.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


@pytest.mark.slow
def test_ctrl_c_keeps_the_episodes_and_the_same_command_plays_only_whats_missing(tmp_path):
    """Your own model (a stub server, 0.1 s an answer) over the smoke file: Ctrl-C after 3 of its 10
    episodes, then the same command; the results equal an uninterrupted run's."""
    games = [i for e in json.loads(SMOKE.read_text())["experiments"] for i in e["game_instances"]]
    env = benchrun.clem_env()
    with StubServer(answer_table(games), latency=0.1) as server:
        benchrun.write_scratch(tmp_path, server.base_url, "openai_compatible", 1)
        run = subprocess.Popen(suite_args("again"), cwd=tmp_path, env=env, stdout=subprocess.PIPE,
                               stderr=subprocess.PIPE, text=True, start_new_session=True,
                               preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL))
        stage = tmp_path / "again" / ".suite"
        deadline = time.monotonic() + 300
        while len(list(stage.rglob("interactions.json"))) < 3 and time.monotonic() < deadline:
            assert run.poll() is None, "the suite ended before it could be stopped"
            time.sleep(0.05)
        os.killpg(run.pid, signal.SIGINT)  # what Ctrl-C in a terminal does: the whole process group
        out, err = run.communicate(timeout=120)
        kept = len(list(stage.rglob("interactions.json")))
        assert run.returncode == 130, out + err
        assert err.count("\n") == 1 and err.startswith("sartco suite: interrupted (Ctrl-C): the episodes played are kept")
        assert 3 <= kept < 10

        done = command(suite_args("again"), cwd=tmp_path, env=env, timeout=600)
        assert done.returncode == 0, done.stdout + done.stderr
        log = (tmp_path / "again" / "main.log").read_text()
        # only what is missing: the episodes never played, and the one Ctrl-C stopped part way if any
        to_play = int(re.search(r"10 episodes in instances_smoke.json \(all experiments\), (\d+) to play", log)[1])
        assert 10 - kept <= to_play <= 11 - kept
        assert f"sartco suite: the report to look at: {tmp_path / 'again-tables' / 'report.html'}" in done.stdout
        assert not stage.exists()
        whole = command(suite_args("whole"), cwd=tmp_path, env=env, timeout=600)
        assert whole.returncode == 0, whole.stdout + whole.stderr
    record = json.loads((tmp_path / "whole" / benchrun.MODEL / "cobot_instruct" / "run.json").read_text())
    assert record["generation"]["max_tokens"] == 512
    compare = _compare()
    ours, theirs = compare.files(tmp_path / "again"), compare.files(tmp_path / "whole")
    assert set(ours) == set(theirs)
    places = ({(tmp_path / "again").resolve(): b"<results>"}, {(tmp_path / "whole").resolve(): b"<results>"})
    differ = {name: why for name in ours if Path(name).name in compare.RESULT_NAMES | {"interactions.json"}
              for why in [compare.compare(name, ours[name], theirs[name], places, True)] if why is not None}
    assert not differ, differ
    assert len([n for n in ours if n.endswith("transcript.html")]) == 10
    assert "<td>first-order (multi-turn)</td>" in (tmp_path / "again-tables" / "report.html").read_text()


@pytest.mark.slow
def test_a_second_suite_into_a_folder_with_runs_is_refused_before_playing_and_the_advice_works(tmp_path):
    results = tmp_path / "results-mine"
    first = command([BIN / "sartco", "suite", "-r", results, "--out", tmp_path / "tables", "-m", "rulebased",
                     "--erring", "-g", "cobot_instruct", "-i", "instances_smoke"], cwd=REPO, timeout=600)
    assert first.returncode == 0, first.stdout + first.stderr
    second = command([BIN / "sartco", "suite", "-r", results, "--out", tmp_path / "tables", "-m", "erring",
                      "--erring", "-g", "cobot_instruct", "-i", "instances_smoke"], cwd=REPO, timeout=600)
    assert second.returncode == 2 and second.stderr.count("\n") == 1, second.stderr
    assert not (results / "erring").exists()   # refused before playing
    advice = second.stderr.split("remove the folder: ")[1].rstrip().rstrip(")")
    assert advice == f"make clean-results RESULTS={results}"
    done = subprocess.run(advice, shell=True, cwd=REPO, capture_output=True, text=True)
    assert done.returncode == 0 and not results.exists(), done.stderr
