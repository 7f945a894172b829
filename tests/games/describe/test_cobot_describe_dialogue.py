"""cobot_describe as a dialogue (clarify, correct, both) through clemcore's real loop: `clem run`,
`clem score`, `clem transcribe` as subprocesses from the repository root, `sartco report` in
process; scripted describers and builders for every path of the dialogue (the dialogue's units:
tests/games/describe/test_dialogue_turns.py)."""
from __future__ import annotations

import copy
import json
import re
from pathlib import Path

import pytest

from episode_helpers import FULL, experiments_of, wrong_code
from play_helpers import REPO, clem, fence
from sartco.cli import main as sartco_main
from sartco.games.describe.dialogue import settings_of
from sartco.follower.correct import pieces
from sartco.world import COLORS

IN = REPO / "games" / "cobot_describe" / "in"
SLICES = [IN / "instances_slice.json", IN / "instances_dialogue_slice.json"]  # cobot_describe, _dialogue
MODES = ("oneshot", "clarify", "correct", "clarify_correct")
HOSTILE = "import os\nos.system('touch /tmp/sartco_dialogue_pwned')"


def no_colours(text: str) -> str:
    return re.sub(rf"\b(?:{'|'.join(COLORS)})\s+", "", text)


# name: (mode, describer script (None: mock), builder script (None: rule-based), expected)
def scenarios(base: dict) -> dict:
    wrong = fence(wrong_code(base["target"]))
    template = base["template_instruction"]
    return {
        "question answered": ("clarify", [f"Instruction: {no_colours(template)}"], None,
                              dict(outcome="success", questions=1, corrections=0, builds=1, es=[1])),
        "question limit": ("clarify", None, ["Question: which colour?", "Question: which row?", "Question: and?"],
                           dict(outcome="aborted", questions=2, corrections=0, builds=1, category="parse_error")),
        "no code": ("clarify", None, ["I would rather not write code."],
                    dict(outcome="aborted", questions=0, corrections=0, builds=1, category="parse_error")),
        "correction repairs": ("correct", None, [wrong],
                               dict(outcome="success", questions=0, corrections=1, builds=2, es=[0, 1, 1, 1])),
        "done on a wrong board": ("correct", [f"Instruction: {template}", "**Done.**"], [wrong],
                                  dict(outcome="lose", questions=0, corrections=0, builds=1, es=[0, 0, 0, 0])),
        "round limit": ("correct", None, [wrong] * 4,
                        dict(outcome="lose", questions=0, corrections=3, builds=4, es=[0, 0, 0, 0])),
        "sandbox error in a correction round": ("correct", None, [wrong, fence(HOSTILE)],
                                                dict(outcome="success", questions=0, corrections=2, builds=3,
                                                     es=[0, 0, 1, 1])),
        "no code in a correction round": ("correct", None, [wrong, "Sorry, I am lost."],
                                          dict(outcome="lose", questions=0, corrections=1, builds=2, es=[0, 0, 0, 0],
                                               category="parse_error")),
        "question after a correction": ("clarify_correct", ["Instruction: " + template,
                                                            "Correction: put everything back as I said.",
                                                            "Answer: " + template],
                                        [wrong],
                                        dict(outcome="success", questions=1, corrections=1, builds=2,
                                             es=[0, 1, 1, 1])),
    }


def scripted_instances() -> dict:
    data = {"experiments": experiments_of(SLICES)}
    used = {i["board_id"] for e in data["experiments"] for i in e["game_instances"]}
    full = experiments_of(FULL)
    base = next(i for i in full[0]["game_instances"] if i["board_id"] not in used)  # a simple board
    by_mode = {e.get("mode", "oneshot"): e for e in full if e["board_type"] == "simple"}
    experiments = {}
    for game_id, (name, (mode, describer, builder, _)) in enumerate(scenarios(base).items(), start=100):
        source = by_mode[mode]
        experiment = experiments.setdefault(mode, {**{k: v for k, v in source.items() if k != "game_instances"},
                                                   "name": f"scripted_{mode}", "game_instances": []})
        inst = copy.deepcopy(next(i for i in source["game_instances"] if i["board_id"] == base["board_id"]))
        inst["game_id"] = game_id
        if describer is not None:
            inst["describer_script"] = describer
        if builder is not None:
            inst["builder_script"] = builder
        experiment["game_instances"].append(inst)
    return {"experiments": [*data["experiments"], *experiments.values()]}, base


@pytest.fixture(scope="module")
def run(tmp_path_factory):
    """The slice (2 boards per experiment, 12 experiments) and the scripted episodes, played by
    mock, scored, transcribed and reported."""
    tmp = tmp_path_factory.mktemp("dialogue")
    instances, base = scripted_instances()
    (tmp / "episodes.json").write_text(json.dumps(instances))
    results = tmp / "results"
    clem("run", "-g", "cobot_describe", "-m", "mock", "-i", str(tmp / "episodes"), "-r", str(results))
    clem("score", "-g", "cobot_describe", "-r", str(results))
    clem("transcribe", "-g", "cobot_describe", "-r", str(results))
    assert sartco_main(["report", "-r", str(results), "--out", str(tmp / "tables")]) == 0
    played = {}
    for path in sorted(results.glob("*/cobot_describe/*/instance_*/scores.json")):
        interactions = json.loads((path.parent / "interactions.json").read_text())
        played[(path.parent.parent.name, interactions["meta"]["game_id"])] = {
            "scores": json.loads(path.read_text().replace("NaN", "null"))["episode scores"],
            "interactions": interactions, "dir": path.parent}
    return {"results": results, "tables": tmp / "tables", "played": played, "base": base}


def scripted(run, name):
    names = list(scenarios(run["base"]))
    mode = scenarios(run["base"])[name][0]
    return run["played"][(f"scripted_{mode}", 100 + names.index(name))]


def messages(episode, player: str) -> list[str]:
    """What the game master sent to a player ("Player 1" describer, "Player 2" builder)."""
    return [e["action"]["text"] for t in episode["interactions"]["turns"] for e in t
            if e["from"] == "GM" and e["to"] == player and e["action"]["type"] == "send message"]


def answers(episode, player: str) -> list[str]:
    return [e["action"]["text"] for t in episode["interactions"]["turns"] for e in t
            if e["from"] == player and e["to"] == "GM"]


def test_mock_plays_every_mode_and_wins(run):
    experiments = experiments_of(SLICES)
    assert sorted({e.get("mode", "oneshot") for e in experiments}) == sorted(MODES)
    assert len(experiments) == 12
    for experiment in experiments:
        settings = settings_of(experiment)
        for inst in experiment["game_instances"]:
            e = run["played"][(experiment["name"], inst["game_id"])]
            s = e["scores"]
            assert (s["Main Score"], s["Success"], s["ES@1"], s["ES@N"], s["Cell F1@N"]) == (100.0, 1, 1, 1, 1.0)
            assert (s["Questions Asked"], s["Corrections Sent"], s["First Success Round"]) == (0, 0, 0)
            assert [s[f"ES Round {k}"] for k in range(settings.corrections + 1)] == [1] * (settings.corrections + 1)
            assert f"ES Round {settings.corrections + 1}" not in s
            said = answers(e, "Player 1")
            assert said[-1] == ("Done" if settings.corrections else said[0])  # the mock describer approves


@pytest.mark.parametrize("name", ["question answered", "question limit", "no code", "correction repairs",
                                  "done on a wrong board", "round limit", "sandbox error in a correction round",
                                  "no code in a correction round", "question after a correction"])
def test_scripted_dialogues(run, name):
    want = scenarios(run["base"])[name][3]
    e = scripted(run, name)
    s = e["scores"]
    got = "aborted" if s["Aborted"] else "success" if s["Success"] else "lose"
    assert got == want["outcome"]
    assert (s["Questions Asked"], s["Corrections Sent"]) == (want["questions"], want["corrections"])
    builds = e["interactions"]["sartco_attempts"]
    assert len(builds) == want["builds"]
    assert e["interactions"]["sartco_build"] == builds[-1]  # the last build is the one scored
    if "category" in want:
        assert s["Error Category"] == want["category"]
    if want["outcome"] == "aborted":
        assert s["Main Score"] is None and s["ES@1"] is None and s["First Success Round"] is None
        return
    assert s["Main Score"] == 100.0 * want["es"][want["builds"] - 1]
    assert [s[f"ES Round {k}"] for k in range(4 if "correct" in e["dir"].parent.name else 1)] == want["es"]
    assert s["ES@1"] == want["es"][0] and s["ES@N"] == builds[-1]["es"]
    first = want["es"].index(1) if 1 in want["es"] else None
    assert s["First Success Round"] == first


def test_question_is_answered_from_the_target(run):
    e = scripted(run, "question answered")
    question = answers(e, "Player 2")[0]
    assert question.startswith("Question: I cannot read this: a washer without a colour") or \
        question.startswith("Question: I cannot read this: a ")
    asked = messages(e, "Player 1")[1]
    assert asked.startswith("The builder asks: I cannot read this") and '"Answer:"' in asked
    told = messages(e, "Player 2")[1]
    assert told.startswith("The describer answers: " + run["base"]["template_instruction"])
    log = e["interactions"]["sartco_dialogue"]
    words = sum(len(ev["text"].split()) for ev in log["events"] if ev["kind"] in ("instruction", "answer"))
    assert e["scores"]["Describer Words"] == words > e["scores"]["Instruction Words"]


def test_question_limit_is_an_answer_without_code(run):
    e = scripted(run, "question limit")
    assert "past the limit of 2" in e["interactions"]["sartco_build"]["message"]
    assert e["interactions"]["sartco_build"]["message"].startswith("Builder:")
    assert len(messages(e, "Player 1")) == 3  # the instruction prompt and two questions


def test_correction_names_pieces_and_repairs(run):
    e = scripted(run, "correction repairs")
    review = messages(e, "Player 1")[1]
    assert review.startswith("The builder's code ran; this is the board it built") and "contains" in review
    correction = answers(e, "Player 1")[1]
    last = [p for _, p in pieces(run["base"]["target"])][-1]
    assert correction.startswith("Correction: Place a ") and correction.count("Place") == 1
    assert f"{last.color} " in correction
    told = messages(e, "Player 2")[1]
    assert told.startswith("The describer looked at the board your code built and asks for a correction: Place a")
    assert answers(e, "Player 1")[-1] == "Done"
    categories = [b["category"] for b in e["interactions"]["sartco_attempts"]]
    assert categories[0].startswith("mismatch_") and categories[1] == "success"


def test_done_on_a_wrong_board_is_scored_as_it_stands(run):
    e = scripted(run, "done on a wrong board")
    assert e["scores"]["Error Category"].startswith("mismatch_") and e["scores"]["Cell F1@N"] < 1.0
    assert [ev["kind"] for ev in e["interactions"]["sartco_dialogue"]["events"]] == ["instruction", "done"]


def test_round_limit_ends_after_the_last_rebuild(run):
    e = scripted(run, "round limit")
    assert len(messages(e, "Player 1")) == 4  # instruction prompt + 3 reviews; the 4th build is not reviewed
    assert "1 more correction)" in messages(e, "Player 1")[-1]


def test_sandbox_error_inside_a_correction_round(run, tmp_path):
    e = scripted(run, "sandbox error in a correction round")
    categories = [b["category"] for b in e["interactions"]["sartco_attempts"]]
    assert categories[1] == "forbidden" and categories[2] == "success"
    assert not Path("/tmp/sartco_dialogue_pwned").exists()
    review = messages(e, "Player 1")[2]
    assert review.startswith("The builder's code stopped with an error (forbidden)")
    for text in messages(e, "Player 1")[1:]:  # the describer never sees code (its prompt explains put)
        assert "os.system" not in text and "put(board" not in text


def test_builder_never_sees_the_target(run):
    for name in scenarios(run["base"]):
        for text in messages(scripted(run, name), "Player 2"):
            assert "contains" not in text and "⬜️" not in text


def test_transcript_shows_every_turn_and_board(run):
    e = scripted(run, "sandbox error in a correction round")
    html = (e["dir"] / "transcript.html").read_text()
    for k in (1, 2, 3):
        assert f"boards_{k}.svg" in html
    assert "The builder asks" not in html  # no question in this episode
    assert "Correction: " in html and "forbidden" in html and "asks for a correction" in html
    q = scripted(run, "question answered")
    html = (q["dir"] / "transcript.html").read_text()
    assert "Question: I cannot read this" in html and "The describer answers" in html


def test_report_has_the_dialogue_table_and_plot(run):
    md = (run["tables"] / "dialogue.md").read_text()
    assert "![ES after round k](dialogue_rounds.svg)" in md
    rows = {r.split(" | ")[2]: r for r in md.splitlines() if r.startswith("| mock")}
    assert "sb_so_optimal_function_describer_clarify_correct" in rows and "scripted_correct" in rows
    svg = (run["tables"] / "dialogue_rounds.svg").read_text()
    assert svg.startswith("<svg") and "mock — correct</text>" in svg and "<polyline" in svg
    table3 = (run["tables"] / "table3.md").read_text()
    assert ": ES\n" in table3 and "| mock |" in table3 and "clarify" not in table3  # the oneshot experiments only
    import csv
    with (run["tables"] / "dialogue.csv").open() as f:
        by_experiment = {r["experiment"]: r for r in csv.DictReader(f)}
    assert by_experiment["scripted_correct"]["episodes"] == "5"
    assert float(by_experiment["sb_so_optimal_function_describer_correct"]["es_at_n"]) == 100.0
