"""Feedback (repair) experiments of cobot_instruct through clemcore's real loop: after a failed
attempt the builder is told what the execution showed (sartco.clem.core.feedback) and may answer
again with complete code, up to the experiment's `attempts`; ES@1 / ES@N / Attempts / Attempt
Categories in scores.json; one picture per attempt; the target never reaches the builder."""
import csv
import json
import re
import sys
from pathlib import Path

import pytest

from feedback_cases import GOLD, HOSTILE, NO_CODE, PARTIAL, TARGET, WRONG, WRONG_CATEGORY, assert_no_target
from play_helpers import GAMES, clem, fence, scripted_episode, sh
from sartco.cli import main as sartco_main
from sartco.clem.core.building import build

EXPERIMENT = {"name": "scripted_feedback", "board_type": "simple", "object_type": "simple", "task": "first_order",
              "source": "template", "split": "test", "ablation": None, "attempts": 3,
              "feedback_of": "scripted"}


def instance(game_id, script=None, turns=1):
    texts = ["Build the board."] if turns == 1 else [f"Instruction {k + 1}." for k in range(len(GOLD))]
    return scripted_episode(game_id, TARGET, GOLD, texts, script=script, single_turn=turns == 1)


def scores(result):
    return result["scores"]["episode scores"]


def feedback_texts(result):
    """What the game master sent the builder after each failed attempt."""
    sent = [e["action"]["content"] for t in result["interactions"]["turns"] for e in t
            if e["from"] == "GM" and e["to"] == "Player 1" and e["action"]["type"] == "send message"]
    return [text for text in sent if "Write the complete corrected code" in text]


def board_events(result):
    return [e for t in result["interactions"]["turns"] for e in t if e["action"]["type"] == "board"]


# --- through the game loop ----------------------------------------------------------------

def test_mock_solves_at_the_first_attempt(play_episodes):
    results = play_episodes([instance(0), instance(1, turns=len(GOLD))], EXPERIMENT)
    for result in results:
        s = scores(result)
        assert (s["ES@1"], s["ES@N"], s["Attempts"], s["Max Attempts"], s["Attempt Categories"]) == \
            (1, 1, 1, 3, "success")
        assert s["Main Score"] == 100.0 and s["Exact Match"] == 1 and s["Success"] == 1
        assert len(result["interactions"]["sartco_attempts"]) == 1 and not feedback_texts(result)
        assert (result["dir"] / "boards_1.svg").is_file() and (result["dir"] / "boards.svg").is_file()


def test_fail_once_then_gold(play_episodes):
    [result] = play_episodes([instance(0, [fence(WRONG), fence("\n".join(GOLD))])], EXPERIMENT)
    s = scores(result)
    assert (s["ES@1"], s["ES@N"], s["Attempts"], s["Attempt Categories"]) == (0, 1, 2, f"{WRONG_CATEGORY},success")
    assert s["Main Score"] == 100.0 and s["Execution Success"] == 1 and s["Success"] == 1
    # every attempt in the transcript with its own board picture
    events = board_events(result)
    assert [e["action"]["category"] for e in events] == [WRONG_CATEGORY, "success"]
    assert [re.findall(r'<a href="([^"]+)"', e["action"]["content"]) for e in events] == \
        [["boards_1.svg"], ["boards_2.svg"]]  # full-size pictures, relative to the episode folder
    assert all(e["action"]["content"].count('<img src="data:image/svg+xml;base64,') == 1 for e in events)
    assert [a["category"] for a in result["interactions"]["sartco_attempts"]] == [WRONG_CATEGORY, "success"]


def test_attempt_limit(play_episodes):
    [result] = play_episodes([instance(0, [fence(PARTIAL)])], EXPERIMENT)  # always the same wrong answer
    s = scores(result)
    assert (s["Attempts"], s["Lose"], s["Aborted"], s["ES@1"], s["ES@N"], s["Main Score"]) == (3, 1, 0, 0, 0, 0.0)
    assert s["Attempt Categories"] == ",".join([build(PARTIAL, TARGET).category] * 3)
    assert s["Request Count"] == 3 and len(feedback_texts(result)) == 2
    assert len(board_events(result)) == 3
    assert all((result["dir"] / f"boards_{k}.svg").is_file() for k in (1, 2, 3))


def test_attempts_field_sets_the_limit(play_episodes):
    [result] = play_episodes([instance(0, [fence(PARTIAL)])], dict(EXPERIMENT, name="five", attempts=5))
    assert (scores(result)["Attempts"], scores(result)["Max Attempts"]) == (5, 5)


def test_each_attempt_runs_on_a_fresh_board(play_episodes):
    rest = "\n".join(GOLD[3:])  # only the distinctive cell: correct only on top of attempt 1's board
    [result] = play_episodes([instance(0, [fence(PARTIAL), fence(rest), fence(rest)])], EXPERIMENT)
    s = scores(result)
    assert s["ES@N"] == 0 and s["Attempts"] == 3 and s["Attempt Categories"].startswith("mismatch")
    assert result["interactions"]["sartco_build"]["cells"] == {k: TARGET[k] for k in ("0:0",)}


def test_parse_error_inside_the_loop_is_a_failed_attempt(play_episodes):
    results = play_episodes([
        instance(0, [NO_CODE, fence("\n".join(GOLD))]),          # no code, then gold
        instance(1, [fence(WRONG), NO_CODE]),                     # code, then no code to the end
        instance(2, [NO_CODE]),                                   # never any code
    ], EXPERIMENT)
    s = scores(results[0])
    assert (s["ES@1"], s["ES@N"], s["Attempts"], s["Attempt Categories"]) == (0, 1, 2, "parse_error,success")
    assert s["Success"] == 1 and s["Violated Request Count"] == 1 and s["Main Score"] == 100.0
    assert "No code was found" in feedback_texts(results[0])[0]
    s = scores(results[1])
    assert (s["Attempts"], s["Attempt Categories"]) == (3, f"{WRONG_CATEGORY},parse_error,parse_error")
    assert (s["Lose"], s["Aborted"], s["Main Score"], s["Error Category"]) == (1, 0, 0.0, "parse_error")
    assert (s["Exact Match"], s["CodeBLEU"], s["ES@1"], s["ES@N"]) == (0, 0.0, 0, 0)
    s = scores(results[2])
    assert (s["Aborted"], s["Attempts"], s["Main Score"], s["ES@1"]) == (1, 3, None, None)  # NaN: not played
    assert s["Attempt Categories"] == "parse_error,parse_error,parse_error"


def test_multi_turn_parse_error_ends_the_first_attempt(play_episodes):
    script = [fence(GOLD[0]), NO_CODE, fence("\n".join(GOLD))]
    [result] = play_episodes([instance(0, script, turns=len(GOLD))], EXPERIMENT)
    s = scores(result)
    assert (s["Attempts"], s["Attempt Categories"], s["ES@N"]) == (2, "parse_error,success", 1)


def test_hostile_program_inside_the_loop(play_episodes):
    marker = Path("/tmp/sartco_feedback_pwned")
    marker.unlink(missing_ok=True)
    [result] = play_episodes([instance(0, [fence(HOSTILE), fence("\n".join(GOLD))])], EXPERIMENT)
    s = scores(result)
    assert (s["ES@1"], s["ES@N"], s["Attempts"], s["Attempt Categories"]) == (0, 1, 2, "forbidden,success")
    assert "forbidden" in feedback_texts(result)[0]
    assert not marker.exists()


def test_target_never_reaches_the_builder(play_episodes):
    failing = [fence(PARTIAL), fence(WRONG), fence("put(board, 'nut', 'red', 9, 9)")]
    [result] = play_episodes([instance(0, failing)], EXPERIMENT)
    texts = feedback_texts(result)
    assert len(texts) == 2
    for text in texts:
        assert_no_target(text)
    # all the builder ever saw: the prompt, the turn, the feedback
    seen = [e["action"]["content"] for t in result["interactions"]["turns"] for e in t
            if e["to"] == "Player 1"]
    for text in seen:
        assert "('screw', 'green')" not in text and "cells differ" not in text and "P/R/F1" not in text


def test_report_repair_table(play_episodes, tmp_path):
    from argparse import Namespace

    from sartco.report import tables as report
    play_episodes([instance(0), instance(1, [fence(WRONG), fence("\n".join(GOLD))]), instance(2, [fence(PARTIAL)]),
                   instance(3, [NO_CODE])], EXPERIMENT)
    assert report.run(Namespace(results=tmp_path / "results", out=tmp_path / "scores", game=None)) == 0
    [row] = list(csv.DictReader((tmp_path / "scores" / "repair.csv").open()))
    assert (row["experiment"], row["episodes"], row["es_at_1"], row["es_at_n"], row["first_failures"],
            row["repaired"], row["repaired_share"], row["mean_attempts"]) == \
        ("scripted_feedback", "4", "25.0", "50.0", "3", "1", "33.33", "2.25")
    assert "| mock | cobot_instruct | scripted_feedback | scripted | 3 | 4 | 25.00 | 50.00 | 3 | 1 | 33.33 | 2.25 |" \
        in (tmp_path / "scores" / "repair.md").read_text()
    assert not list(csv.DictReader((tmp_path / "scores" / "table3.csv").open()))


# --- clem run / score / transcribe / eval and sartco report -----------------------------------

@pytest.mark.slow
def test_feedback_experiment_end_to_end(tmp_path):
    results, out = tmp_path / "results", tmp_path / "scores"
    experiment = "rb_co_repetition_template_feedback"
    # the game's feedback file cut to that experiment's first 10 episodes (of 130: the flow, not the
    # coverage, is checked here; tests/clem/test_instance_checks.py checks every committed file)
    data = json.loads((GAMES / "cobot_instruct" / "in" / "instances_feedback.json").read_text())
    data["experiments"] = [dict(e, game_instances=e["game_instances"][:10])
                           for e in data["experiments"] if e["name"] == experiment]
    (tmp_path / "instances_feedback.json").write_text(json.dumps(data))
    # the `clem` process for the run (it checks the instance file and writes run.json); the other
    # commands are the same code in this process
    sh(str(Path(sys.executable).parent / "clem"), "run", "-g", "cobot_instruct_feedback", "-m", "mock", "-i",
       str(tmp_path / "instances_feedback"), "-e", experiment, "-r", str(results), "-l", "512")
    clem("score", "-g", "cobot_instruct_feedback", "-r", str(results))
    clem("transcribe", "-g", "cobot_instruct_feedback", "-r", str(results))
    clem("eval", "-r", str(results))
    assert sartco_main(["report", "-r", str(results), "--out", str(out)]) == 0
    files = sorted(results.rglob("scores.json"))
    assert len(files) == 10
    for path in files:
        s = json.loads(path.read_text())["episode scores"]
        assert (s["ES@1"], s["ES@N"], s["Attempts"], s["Max Attempts"], s["Main Score"]) == (1, 1, 1, 3, 100.0)
        assert "boards_1.svg" in (path.parent / "transcript.html").read_text()
    rows = list(csv.DictReader((out / "repair.csv").open()))
    assert [(r["model"], r["experiment"], r["feedback_of"], r["attempts"], r["episodes"], r["es_at_1"], r["es_at_n"],
             r["first_failures"]) for r in rows] == \
        [("mock", experiment, "rb_co_repetition_template", "3", "10", "100.0", "100.0", "0")]
    assert not list(csv.DictReader((out / "table3.csv").open()))  # feedback experiments are not Table 3 cells
