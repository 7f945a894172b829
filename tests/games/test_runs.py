"""A run that stopped part-way is reported incomplete and `sartco resume` completes it to the
scores of an uninterrupted run; every run leaves run.json; runs of different instance files are
not merged (issue 22: completeness, resume, provenance). The smoke file: 10 episodes, 2 per
experiment, played by `mock` through the clem command line (the `clem run` process: it writes
run.json); `sartco report` and `sartco resume` in this process (play_helpers.sartco)."""
import csv
import json
import shutil
import sys
from pathlib import Path

import pytest

from play_helpers import REPO, clem, sartco, sh

BIN = Path(sys.executable).parent
GAME = "cobot_instruct"


def played(results: Path) -> Path:
    sh(str(BIN / "clem"), "run", "-g", GAME, "-m", "mock", "-i", "instances_smoke", "-r", str(results))  # run.json: `clem`
    clem("score", "-r", str(results))
    return results / "mock" / GAME


def scores_of(game_dir: Path) -> dict[str, bytes]:
    return {str(p.relative_to(game_dir)): p.read_bytes() for p in sorted(game_dir.rglob("scores.json"))}


@pytest.fixture(scope="module")
def uninterrupted(tmp_path_factory):
    return played(tmp_path_factory.mktemp("whole") / "results")


@pytest.mark.slow
def test_stopped_run_is_reported_incomplete_and_resume_completes_it(tmp_path, uninterrupted):
    game_dir = played(tmp_path / "results")
    # the state of a run stopped after 7 of 10 episodes: the last three never got a folder ...
    stopped = [("rb_co_repetition_template", 1), ("rb_so_repetition_template", 0), ("rb_so_repetition_template", 1)]
    for experiment, game_id in stopped:
        shutil.rmtree(game_dir / experiment / f"instance_{game_id:05d}")
    # ... one played episode was not scored, one scores.json is cut off
    (game_dir / "sb_so_first_order_template" / "instance_00000" / "scores.json").unlink()
    (game_dir / "sb_so_optimal_function_template" / "instance_00001" / "scores.json").write_text('{"episode')

    report = sartco("report", "-r", tmp_path / "results", "--out", tmp_path / "scores")
    assert report.returncode == 3, report.stderr
    assert "mock / cobot_instruct / rb_so_repetition_template: 0 of 2 scored; missing 0-1" in report.stderr
    assert "rb_co_repetition_template: 1 of 2 scored; missing 1" in report.stderr
    assert "sb_so_first_order_template: 1 of 2 scored; unscored 0" in report.stderr
    assert "sb_so_optimal_function_template: 1 of 2 scored; unreadable 1" in report.stderr
    rows = {r["experiment"]: r for r in csv.DictReader((tmp_path / "scores" / "completeness.csv").open())}
    assert [(rows[x]["episodes_expected"], rows[x]["episodes_scored"]) for x in sorted(rows)] == \
        [("2", "1"), ("2", "0"), ("2", "1"), ("2", "1"), ("2", "2")]
    table3 = {r["task"]: r for r in csv.DictReader((tmp_path / "scores" / "table3.csv").open())}
    assert (table3["first_order"]["episodes_expected"], table3["first_order"]["episodes_scored"]) == ("2", "1")
    assert (table3["sequence_function"]["episodes_expected"], table3["sequence_function"]["episodes_scored"]) == ("2", "2")
    md = (tmp_path / "scores" / "table3.md").read_text()
    assert md.startswith("> † Incomplete results") and "| 100.00 [100.00, 100.00]† |" in md

    resume = sartco("resume", "-r", tmp_path / "results", "-g", GAME, "-m", "mock")
    assert resume.returncode == 0, resume.stdout[-2000:] + resume.stderr[-2000:]
    assert "3 to play, 2 to score" in resume.stdout
    assert scores_of(game_dir) == scores_of(uninterrupted)  # byte-identical, every episode under its id
    again = sartco("report", "-r", tmp_path / "results", "--out", tmp_path / "scores")
    assert again.returncode == 0, again.stderr
    assert "† " not in (tmp_path / "scores" / "table3.md").read_text()

    run = json.loads((game_dir / "run.json").read_text())
    assert run["instance_file"]["path"] == "games/cobot_instruct/in/instances_smoke.json"
    assert run["clemcore_version"] and run["sartco_version"] and run["models"] == [
        {"model_name": "mock", "backend": "_player_programmed"}]
    assert [(s["resume"], s["episodes_selected"], s["episodes_played"]) for s in run["sessions"]] == \
        [(False, 10, 10), (True, 3, 3)]
    assert run["start"] <= run["end"] and run["counts"] == {"sessions": 2, "episodes_played": 13}


@pytest.mark.slow
def test_runs_of_different_instance_files_are_refused(tmp_path, uninterrupted):
    results = tmp_path / "results"
    shutil.copytree(uninterrupted.parent, results / "mock")  # played from instances_smoke
    # one more experiment into the same folder from another instance file: the game's default file
    # (instances.json) cut to that experiment's first 2 episodes, in a folder of its own (-i PATH)
    other = tmp_path / "other" / "instances.json"
    other.parent.mkdir()
    default = json.loads((REPO / "games" / GAME / "in" / "instances.json").read_text())
    default["experiments"] = [dict(e, game_instances=e["game_instances"][:2])
                              for e in default["experiments"] if e["name"] == "rb_co_repetition_template"]
    other.write_text(json.dumps(default))
    sh(str(BIN / "clem"), "run", "-g", GAME, "-m", "mock", "-i", str(other.with_suffix("")), "-e",
       "rb_co_repetition_template", "-r", str(results))
    path = results / "mock" / GAME / "run.json"
    run = json.loads(path.read_text())
    assert [s["instance_file"]["name"] for s in run["sessions"]] == ["instances_smoke", "instances"]
    report = sartco("report", "-r", results, "--out", tmp_path / "scores")
    assert report.returncode == 2
    assert "refusing to merge runs played from different instance files" in report.stderr
    assert str(other) in report.stderr and "games/cobot_instruct/in/instances_smoke.json" in report.stderr
    assert len(report.stderr.strip().splitlines()) == 1
    resume = sartco("resume", "-r", results, "-g", GAME, "-m", "mock")
    assert resume.returncode == 2 and "refusing to merge" in resume.stderr

    # the instance file changed since the first run: neither report nor resume go on
    first = json.loads((uninterrupted / "run.json").read_text())
    path.write_text(json.dumps(dict(first, instance_file=dict(first["instance_file"], sha256="f" * 64))))
    for done in (sartco("report", "-r", results, "--out", tmp_path / "scores"),
                 sartco("resume", "-r", results, "-g", GAME, "-m", "mock")):
        assert done.returncode == 2
        assert "instances_smoke.json changed since the run (sha256 ffffffffffff in run.json" in done.stderr


def test_run_json_keeps_no_secret():
    from sartco.clem.core.provenance import without_secrets
    entry = {"model_name": "m", "backend": "openai_compatible", "api_key": "sk-1",
             "model_config": {"base_url": "http://x", "Authorization": "Bearer y", "headers": [{"x-api-token": "z"}]}}
    assert without_secrets(entry) == {"model_name": "m", "backend": "openai_compatible",
                                      "model_config": {"base_url": "http://x", "headers": [{}]}}


def test_cobot_describe_is_the_one_shot_game_alone():
    """One meaning per leaderboard column: `clem run -g cobot_describe` plays the paper's one-shot
    mode only; the dialogue modes are the entry cobot_describe_dialogue. Both files follow the one
    convention of every instance file: experiments named <cell>_<task>_<source>[_<mode>]
    (sartco.dataset.experiment_name), game_id from 0 in each, the same board under the same id
    in every mode."""
    from clemcore.clemgame import GameRegistry

    registry = GameRegistry.from_directories_and_cwd_files()
    files = {}
    for game in ("cobot_describe", "cobot_describe_dialogue"):
        [spec] = [s for s in registry.get_game_specs_that_unify_with(game) if s.game_name == game]
        data = json.loads((Path(spec.game_path) / "in" / f"{spec.instances}.json").read_text())
        files[game] = data["experiments"]
    assert {e.get("mode", "oneshot") for e in files["cobot_describe"]} == {"oneshot"}
    oneshot = ["sb_so_optimal_function_describer", "rb_so_repetition_describer", "rb_co_repetition_describer"]
    modes = ("clarify", "correct", "clarify_correct")
    assert [e["name"] for e in files["cobot_describe"]] == oneshot
    assert [(e["name"], e["mode"]) for e in files["cobot_describe_dialogue"]] == \
        [(f"{name}_{mode}", mode) for mode in modes for name in oneshot]
    experiments = [e for game in files.values() for e in game]
    assert sum(len(e["game_instances"]) for e in experiments) == 1560
    boards = {}
    for e in experiments:
        assert [i["game_id"] for i in e["game_instances"]] == list(range(130)), e["name"]
        for i in e["game_instances"]:
            assert boards.setdefault((e["board_type"], e["object_type"], i["game_id"]), i["board_id"]) == i["board_id"]
