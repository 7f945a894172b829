"""cobot_describe end to end: `clem run` / `clem score` as subprocesses from the repository root
into a temporary results folder; the describer -> import-instructions -> cobot_instruct round
trip; scripted describer answers; bad results folders."""
from __future__ import annotations

import copy
import json
import math
import re
import shutil
from pathlib import Path

import pytest

from play_helpers import clem
from sartco.cli import main as sartco_main
from sartco.games.instruct.instancegenerator import InstructFile, described

REPO = Path(__file__).resolve().parents[3]
SLICE = REPO / "games" / "cobot_describe" / "in" / "instances_slice.json"
FULL = REPO / "games" / "cobot_describe" / "in" / "instances.json"

# name: (describer answer, outcome, error category)
SCRIPTED = {
    "no label": ("Place a green bridge vertically in the 5th row, 4th column.", "aborted", "parse_error"),
    "empty label": ("Instruction:\n\n", "aborted", "parse_error"),
    "junk": ("Instruction: erere", "lose", "mismatch_location"),  # the follower builds nothing
    "moved object": (None, "lose", "mismatch_location"),  # a valid instruction, one row further up
}


def episodes(results: Path, experiment: str) -> list[dict]:
    out = []
    for path in sorted(results.glob(f"*/cobot_describe/{experiment}/instance_*/scores.json")):
        scores = json.loads(path.read_text())["episode scores"]
        interactions = json.loads((path.parent / "interactions.json").read_text())
        out.append({"scores": scores, "interactions": interactions, "dir": path.parent})
    return out


def scripted_instances() -> dict:
    slice_experiments = json.loads(SLICE.read_text())["experiments"]
    used = {i["board_id"] for e in slice_experiments for i in e["game_instances"]}
    full = json.loads(FULL.read_text())["experiments"][0]["game_instances"]
    base = next(i for i in full if i["board_id"] not in used)  # a simple board outside the slice
    scripted = {**{k: v for k, v in slice_experiments[0].items() if k != "game_instances"},
                "name": "scripted", "game_instances": []}
    for game_id, (name, (answer, _, _)) in enumerate(SCRIPTED.items(), start=100):
        inst = copy.deepcopy(base)
        inst["game_id"] = game_id
        if answer is None:  # the template instruction with every row one higher
            answer = "Instruction: " + re.sub(r"(\d)(st|nd|rd|th) row", lambda m: f"{int(m[1]) - 1}th row",
                                              inst["template_instruction"])
            assert answer != "Instruction: " + inst["template_instruction"]
        inst["describer_script"] = [answer]
        scripted["game_instances"].append(inst)
    return {"experiments": [*slice_experiments, scripted]}


@pytest.fixture(scope="module")
def describe_run(tmp_path_factory):
    """The slice (2 boards per experiment) and the scripted episodes, played by mock and scored."""
    tmp = tmp_path_factory.mktemp("cobot_describe")
    (tmp / "episodes.json").write_text(json.dumps(scripted_instances()))
    results = tmp / "results"
    clem("run", "-g", "cobot_describe", "-m", "mock", "-i", str(tmp / "episodes"), "-r", str(results))
    clem("score", "-g", "cobot_describe", "-r", str(results))
    return results


def test_mock_builds_every_board(describe_run):
    names = [e["name"] for e in json.loads(SLICE.read_text())["experiments"] if "mode" not in e]  # oneshot
    assert names == ["sb_so_optimal_function_describer", "rb_so_repetition_describer", "rb_co_repetition_describer"]
    for name in names:
        played = episodes(describe_run, name)
        assert len(played) == 2, name
        for e in played:
            s = e["scores"]
            assert (s["Main Score"], s["Success"], s["Aborted"], s["Error Category"]) == (100.0, 1, 0, "success"), e["dir"]
            assert s["Cell F1"] == 1.0 and s["Describer Answered"] == 1 and s["Object Named"] == 1
            text = e["interactions"]["sartco_instruction"]["text"]
            assert s["Instruction Words"] == len(text.split()) and s["Instruction Characters"] == len(text)
            # players: the describer's and builder's roles are both recorded
            roles = {p["game_role"] for p in e["interactions"]["players"].values()}
            assert {"Describer", "Builder"} <= roles


def test_describer_prompt_asks_for_instructions_not_code():
    prompt = json.loads(SLICE.read_text())["experiments"][0]["game_instances"][0]["describer_prompt"]
    first = prompt.split("\n", 1)[0]
    assert first.startswith("You are a helpful assistant that writes instructions for a programmer")
    assert "writes Python code" not in first


def test_builder_sees_instruction_not_target(describe_run):
    """The builder's prompt holds the describer's words (no slot left, no target grid)."""
    e = episodes(describe_run, "sb_so_optimal_function_describer")[0]
    requests = json.loads((e["dir"] / "player_2.requests.json").read_text())
    prompt = json.dumps(requests)
    text = e["interactions"]["sartco_instruction"]["text"]
    assert json.dumps(text)[1:-1] in prompt
    assert "<<DESCRIBER_INSTRUCTION>>" not in prompt and "contains" not in prompt  # no grid explanation


@pytest.mark.parametrize("name", list(SCRIPTED))
def test_scripted_describer_answers(describe_run, name):
    _, outcome, category = SCRIPTED[name]
    played = {e["interactions"]["meta"]["game_id"]: e for e in episodes(describe_run, "scripted")}
    e = played[100 + list(SCRIPTED).index(name)]
    s = e["scores"]
    got = "aborted" if s["Aborted"] else "success" if s["Success"] else "lose"
    assert (got, s["Error Category"]) == (outcome, category)
    if outcome == "aborted":
        assert s["Main Score"] is None or math.isnan(s["Main Score"])
        assert s["Describer Answered"] == 0
        assert "Describer" in e["interactions"]["sartco_build"]["message"]
        # the transcript says what happened: no instruction, nothing built (not "no code found")
        board = [ev["action"]["content"] for t in e["interactions"]["turns"] for ev in t
                 if ev["action"]["type"] == "board"]
        assert len(board) == 1 and "Describer: no instruction found" in board[0]
        assert "(none: nothing was built)" in board[0] and "no code found" not in board[0]
    else:
        assert s["Main Score"] == 0.0 and s["Describer Answered"] == 1
    if name == "junk":
        assert e["interactions"]["sartco_build"]["builder_code"].startswith("# I cannot follow these instructions")


def test_round_trip_into_cobot_instruct(describe_run, tmp_path, play_episodes):
    """describer results -> sartco import-instructions -> cobot_instruct episodes -> mock and
    rule-based builders build every board from the imported instructions."""
    results = tmp_path / "results"  # the describers' runs without the scripted experiment
    shutil.copytree(describe_run, results, ignore=shutil.ignore_patterns("scripted"))
    out = tmp_path / "dataset"
    assert sartco_main(["import-instructions", "-r", str(results), "--out", str(out)]) == 0
    manifest = json.loads((out / "manifest.json").read_text())
    assert manifest["source"] == "describer" and manifest["config"]["base"] == [{"version": "v1", "seed": 42}]
    assert manifest["config"]["instruction_sources"] == {"mock": 6} and manifest["defects"] == []
    assert manifest["files"] == {"simple_simple_test.json": 2, "regular_simple_test.json": 2,
                                 "regular_complex_test.json": 2}
    generator = InstructFile(REPO / "games" / "cobot_instruct", described)  # `sartco instances instruct-describers`
    generator.on_generate(seed=42, dataset_dir=REPO / "instances" / "v1", n_examples=5, describers_dir=out)
    experiments = generator.instances["experiments"]
    assert [e["name"] for e in experiments] == ["sb_so_optimal_function_mock", "rb_so_repetition_mock",
                                                "rb_co_repetition_mock"]
    assert generator.instances["dataset"]["source"] == "describer"
    instances = [{**inst, "game_id": i} for e in experiments for i, inst in enumerate(e["game_instances"])]
    assert len(instances) == 6 and all(inst["source"] == "mock" for inst in instances)
    experiment = {"name": "describer_mock_instructions", "task": "mixed", "source": "mock", "split": "test"}
    for model in ("mock", "rulebased"):
        results = play_episodes(instances, experiment, model=model)
        assert [r["scores"]["episode scores"]["Main Score"] for r in results] == [100.0] * len(instances), model


def test_import_rejects_bad_results_folders(tmp_path, capsys):
    missing = tmp_path / "missing"
    assert sartco_main(["import-instructions", "-r", str(missing), "--out", str(tmp_path / "o")]) == 2
    assert "not a folder" in capsys.readouterr().err
    empty = tmp_path / "empty"
    (empty / "mock" / "other_game" / "e" / "instance_00000").mkdir(parents=True)
    (empty / "mock" / "other_game" / "e" / "instance_00000" / "interactions.json").write_text("{}")
    assert sartco_main(["import-instructions", "-r", str(empty), "--out", str(tmp_path / "o")]) == 2
    err = capsys.readouterr().err
    assert "no cobot_describe episodes" in err and err.count("\n") == 1
    broken = tmp_path / "broken" / "mock" / "cobot_describe" / "e" / "instance_00000"
    broken.mkdir(parents=True)
    (broken / "interactions.json").write_text("{not json")
    assert sartco_main(["import-instructions", "-r", str(tmp_path / "broken"), "--out", str(tmp_path / "o")]) == 2
    assert "no describer instructions in 1 cobot_describe episodes (1 unreadable)" in capsys.readouterr().err
    assert not (tmp_path / "o").exists()


def test_import_reports_what_it_leaves_out(describe_run, tmp_path, capsys):
    out = tmp_path / "dataset"
    assert sartco_main(["import-instructions", "-r", str(describe_run), "--out", str(out), "--version", "x"]) == 0
    manifest = json.loads((out / "manifest.json").read_text())
    assert manifest["version"] == "x" and manifest["files"]["simple_simple_test.json"] == 3
    kinds = sorted((d["kind"], d["episode"].split("/")[-1]) for d in manifest["defects"])
    assert kinds == [("duplicate", "instance_00103"), ("no_instruction", "instance_00100"),
                     ("no_instruction", "instance_00101")]
    junk = [r for r in json.loads((out / "simple_simple_test.json").read_text())
            if r["instructions"]["mock"]["single_turn"] == "erere"]
    assert len(junk) == 1 and junk[0]["provenance"]["source"] == "describer"
    assert "left out: 3 episodes, 1 duplicate, 2 no_instruction" in capsys.readouterr().out
