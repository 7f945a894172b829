"""The boards and answers of the feedback (repair) tests, unit (tests/clem/test_feedback_message.py)
and through the game loop (tests/games/instruct/test_feedback.py)."""
import re

from sartco.clem.core.building import build

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


def assert_no_target(text):
    assert "green" not in text and "screw" not in text and "0:0" not in text
    for leak in ("P/R/F1", "precision", "recall", "F1", "cells differ", "mismatch", "target board:"):
        assert leak.lower() not in text.lower(), leak
    assert not re.search(r"\d+ cells?", text)
