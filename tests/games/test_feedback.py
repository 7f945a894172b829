"""Feedback (repair) experiments of cobot_instruct through clemcore's real loop: after a failed
attempt the builder is told what the execution showed (sartco.clem.feedback) and may answer
again with complete code, up to the experiment's `attempts`; ES@1 / ES@N / Attempts / Attempt
Categories in scores.json; one picture per attempt; the target never reaches the builder."""
import csv
import json
import re
import subprocess
import sys
from pathlib import Path

import pytest

from sartco.clem.building import build
from sartco.clem.feedback import feedback_for, feedback_message, max_attempts
from sartco.world.render import grid_text

REPO = Path(__file__).resolve().parents[2]

# a red washer with a blue nut at (7, 3), a yellow bridge-h at (2, 5)-(2, 6), and a distinctive
# cell the wrong answers never build: a green screw at (0, 0) (nothing else is green or a screw)
TARGET = {"0:0": [["screw", "green"]], "2:5": [["bridge-h", "yellow"]],
          "2:6": [["bridge-h", "yellow"]], "7:3": [["washer", "red"], ["nut", "blue"]]}
GOLD = ["put(board, 'washer', 'red', 7, 3)", "put(board, 'nut', 'blue', 7, 3)",
        "put(board, 'bridge-h', 'yellow', 2, 5)", "put(board, 'screw', 'green', 0, 0)"]
PARTIAL = "\n".join(GOLD[:3])                    # builds everything but the distinctive cell
WRONG = "\n".join(GOLD[:3]).replace("'red'", "'blue'") + "\nput(board, 'washer', 'red', 0, 1)"  # runs, differs
WRONG_CATEGORY = build(WRONG, TARGET).category
NO_CODE = "I would first place the washer, then the nut."
HOSTILE = "import os\nos.system('touch /tmp/sartco_feedback_pwned')"
EXPERIMENT = {"name": "scripted_feedback", "board_type": "simple", "object_type": "simple", "task": "first_order",
              "source": "template", "split": "test", "ablation": None, "attempts": 3,
              "feedback_of": "scripted"}


def fence(code):
    return f"Here is the code:\n```python\n{code}\n```"


def instance(game_id, script=None, turns=1):
    code = "\n".join(GOLD)
    inst = {"game_id": game_id, "board_id": f"scripted_{game_id}", "rows": 8, "cols": 8, "task": "first_order",
            "prompt": "Write Python code with put(board, shape, color, x, y).",
            "turns": ["Build the board."] if turns == 1 else [f"Instruction {k + 1}." for k in range(len(GOLD))],
            "instructions": [], "given_code": "", "target": TARGET, "gold_code": code,
            "gold_turns": [code] if turns == 1 else list(GOLD)}
    if script is not None:
        inst["script"] = script
    return inst


def scores(result):
    return result["scores"]["episode scores"]


def feedback_texts(result):
    """What the game master sent the builder after each failed attempt."""
    sent = [e["action"]["content"] for t in result["interactions"]["turns"] for e in t
            if e["from"] == "GM" and e["to"] == "Player 1" and e["action"]["type"] == "send message"]
    return [text for text in sent if "Write the complete corrected code" in text]


def board_events(result):
    return [e for t in result["interactions"]["turns"] for e in t if e["action"]["type"] == "board"]


# --- the feedback message on its own ------------------------------------------------------

def assert_no_target(text):
    assert "green" not in text and "screw" not in text and "0:0" not in text
    for leak in ("P/R/F1", "precision", "recall", "F1", "cells differ", "mismatch", "target board:"):
        assert leak.lower() not in text.lower(), leak
    assert not re.search(r"\d+ cells?", text)


def test_feedback_reports_execution_facts_only():
    partial = build(PARTIAL, TARGET)
    assert partial.category.startswith("mismatch")
    text = feedback_for(partial, attempts_left=2)
    assert "differs from the target" in text and grid_text(partial.cells) in text and "2 attempts left" in text
    assert_no_target(text)
    failed = build("put(board, 'washer', 'red', 7, 3)\nput(board, 'bridge-h', 'red', 2, 7)", TARGET)
    text = feedback_for(failed, attempts_left=1)
    assert failed.message.startswith("line 3: ")  # of the executed program: init_board is line 1
    assert f"{failed.error}: line 2: {failed.message[len('line 3: '):]}" in text and grid_text(failed.cells) in text
    assert "1 attempt left" in text
    assert_no_target(text)


def test_feedback_does_not_depend_on_the_target():
    other = {"4:4": [["washer", "blue"]]}
    for code in (PARTIAL, WRONG, "put(board, 'nut', 'red', 9, 9)", HOSTILE):
        assert feedback_for(build(code, TARGET)) == feedback_for(build(code, other))


def test_feedback_counts_lines_in_the_builders_code():
    text = feedback_for(build("put(board, 'washer', 'red', 7, 3)\n" + HOSTILE, TARGET))
    assert "forbidden: line 2:" in text  # line 3 of the executed program (after init_board)
    given = "def f(board):\n    put(board, 'nut', 'red', 9, 9)"
    text = feedback_for(build("f(board)", TARGET, given_code=given))
    assert "line 2 of the given code" in text


def test_feedback_for_no_code_and_the_attempts_field():
    text = feedback_message(error="parse_error", message="no code found in the answer", cells={})
    assert "No code was found" in text and "⬜️" not in text
    assert max_attempts({}) == 1 and max_attempts({"attempts": 3}) == 3
    for bad in ({"attempts": 0}, {"attempts": "3"}, {"attempts": True}, {"attempts": -1}):
        with pytest.raises(ValueError, match="must be an integer"):
            max_attempts(dict(bad, name="bad"))


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
    assert [re.findall(r'<img src="([^"]+)"', e["action"]["content"]) for e in events] == \
        [["boards_1.svg"], ["boards_2.svg"]]  # relative to the episode folder
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

def sh(*args):
    done = subprocess.run(args, cwd=REPO, capture_output=True, text=True, timeout=600)
    assert done.returncode == 0, f"{' '.join(args)} failed:\n{done.stdout[-2000:]}\n{done.stderr[-2000:]}"
    return done


@pytest.mark.slow
def test_feedback_experiment_end_to_end(tmp_path):
    results, out = tmp_path / "results", tmp_path / "scores"
    experiment = "rb_co_repetition_template_feedback"
    clem, sartco = (str(Path(sys.executable).parent / name) for name in ("clem", "sartco"))
    sh(clem, "run", "-g", "cobot_instruct_feedback", "-m", "mock", "-e", experiment, "-r", str(results), "-l", "512")
    sh(clem, "score", "-g", "cobot_instruct_feedback", "-r", str(results))
    sh(clem, "transcribe", "-g", "cobot_instruct_feedback", "-r", str(results))
    sh(clem, "eval", "-r", str(results))
    sh(sartco, "report", "-r", str(results), "--out", str(out))
    files = sorted(results.rglob("scores.json"))
    assert len(files) == 130
    for path in files[:10]:
        s = json.loads(path.read_text())["episode scores"]
        assert (s["ES@1"], s["ES@N"], s["Attempts"], s["Max Attempts"], s["Main Score"]) == (1, 1, 1, 3, 100.0)
        assert "boards_1.svg" in (path.parent / "transcript.html").read_text()
    rows = list(csv.DictReader((out / "repair.csv").open()))
    assert [(r["model"], r["experiment"], r["feedback_of"], r["attempts"], r["episodes"], r["es_at_1"], r["es_at_n"],
             r["first_failures"]) for r in rows] == \
        [("mock", experiment, "rb_co_repetition_template", "3", "130", "100.0", "100.0", "0")]
    assert not list(csv.DictReader((out / "table3.csv").open()))  # feedback experiments are not Table 3 cells
