"""Episodes that tests in several folders play: a scripted cobot_instruct episode (its target,
gold code and experiment; tests/games/instruct/test_episodes.py, tests/games/test_harness_episodes.py)
and cobot_describe's committed instance files (tests/games/describe, tests/games/test_score_card.py)."""
import json
from pathlib import Path

from play_helpers import REPO, scripted_episode
from sartco.follower import emit
from sartco.follower.correct import pieces

# target: a red washer with a blue nut on top at row 7, column 3; a yellow bridge-h at (2, 5)-(2, 6)
TARGET = {"2:5": [["bridge-h", "yellow"]], "2:6": [["bridge-h", "yellow"]],
          "7:3": [["washer", "red"], ["nut", "blue"]]}
GOLD = ["put(board, 'washer', 'red', 7, 3)", "put(board, 'nut', 'blue', 7, 3)",
        "put(board, 'bridge-h', 'yellow', 2, 5)"]
SINGLE = {"name": "scripted_single", "board_type": "simple", "object_type": "simple", "task": "first_order",
          "source": "template", "split": "test", "ablation": None}


def instance(game_id, script=None, turns=1):
    texts = (["Place a red washer at row 8, column 4, a blue nut on it, and a yellow horizontal bridge "
              "at row 3, columns 6 and 7."] if turns == 1 else
             ["Place a red washer at row 8, column 4.", "Place a blue nut on top of it.",
              "Place a yellow horizontal bridge at row 3, columns 6 and 7."])
    return scripted_episode(game_id, TARGET, GOLD, texts, script=script, single_turn=turns == 1)


def outcome(scores):
    s = scores["episode scores"]
    return "aborted" if s["Aborted"] else "success" if s["Success"] else "lose"


DESCRIBE_IN = REPO / "games" / "cobot_describe" / "in"
FULL = [DESCRIBE_IN / "instances.json", DESCRIBE_IN / "instances_dialogue.json"]  # cobot_describe, _dialogue


def experiments_of(paths: list[Path]) -> list[dict]:
    return [e for path in paths for e in json.loads(path.read_text())["experiments"]]


def wrong_code(target: dict) -> str:
    """Every piece of the target but the last one: runs, builds another board."""
    return emit.first_order([p for _, p in pieces(target)][:-1])
