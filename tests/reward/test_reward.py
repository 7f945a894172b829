"""The reward API (sartco.reward) equals `clem score`: cobot_instruct episodes played through
clemcore's real loop by the erring player (seeded slips) and by scripted answers (no code, errors,
a hard-coded function, hostile characters, a multi-turn answer that stops), scored by the game's
scorer; then the same answers, read back from interactions.json, through `score` in one batch."""
from __future__ import annotations

import json
import math
from pathlib import Path

import pytest

from play_helpers import GAMES, fence, play
from sartco.episode import (CELL_F1, CELL_PRECISION, CELL_RECALL, ERROR_CATEGORY, ERROR_FAMILY, EXECUTION_SUCCESS,
                            FUNCTION_GENERALISATION, PROBE_CATEGORIES, PROBE_FUNCTION, PUTS)
from sartco.reward import Episodes, score

SMOKE = GAMES / "cobot_instruct" / "in" / "instances_smoke.json"
COMPARED = (EXECUTION_SUCCESS, CELL_PRECISION, CELL_RECALL, CELL_F1, ERROR_CATEGORY, ERROR_FAMILY, PUTS,
            FUNCTION_GENERALISATION, PROBE_CATEGORIES, PROBE_FUNCTION)
HARD_CODED = """def bn(board, colors, x, y):
    put(board, 'bridge-v', 'green', 4, 3)
    put(board, 'nut', 'red', 4, 3)
bn(board, ('green', 'red'), 4, 3)"""


def scripts(task: str, gold: str) -> list[list[str]]:
    """Answers `mock` gives instead of the gold (one list per episode, the last answer repeated)."""
    common = [["I would rather not write code."], [fence("put(board, 'nut')")], [fence("def f(:\n    pass")],
              [fence("x = 1")], [fence(gold + "\n# \u202e\x00 done")]]
    if task == "optimal_function":
        return common + [[fence(HARD_CODED)], [fence(gold.replace("'red'", "'blue'"))]]
    if task == "first_order":
        return common + [[fence("put(board, 'washer', 'red', 0, 0)"), "nothing more to add"]]
    return common


@pytest.fixture(scope="module")
def played(tmp_path_factory) -> list[Path]:
    """The smoke file's episodes played by erring, and scripted variants of two of them by mock;
    the episode folders, scored."""
    results = tmp_path_factory.mktemp("reward") / "results"
    experiments = json.loads(SMOKE.read_text())["experiments"]
    for experiment in experiments:
        fields = {k: v for k, v in experiment.items() if k != "game_instances"}
        episodes = experiment["game_instances"]
        play(episodes, fields, results, "erring")
        first = episodes[0]
        if first["task"] in ("optimal_function", "first_order"):
            if first["task"] == "optimal_function":
                assert first["combo_name"] == "bn" and first["target"]["4:3"] == [["bridge-v", "green"], ["nut", "red"]]
            variants = [{**first, "game_id": 100 + k, "script": s}
                        for k, s in enumerate(scripts(first["task"], first["gold_code"]))]
            play(variants, fields, results, "mock")
    return sorted(p.parent for p in results.rglob("scores.json"))


def answers_of(interactions: dict, instance: dict) -> list[str]:
    """The player's answers, in order: the transcript's `text` of each answer event (escaped by
    the game master), or for a scripted episode the raw script's answers (the last one repeated)."""
    given = [event["action"]["text"] for turn in interactions["turns"] for event in turn
             if event["action"]["type"] == "get message"]
    script = instance.get("script")
    return [script[min(k, len(script) - 1)] for k in range(len(given))] if script else given


def same(a, b) -> bool:
    if isinstance(a, float) and isinstance(b, float) and math.isnan(a) and math.isnan(b):
        return True
    return a == b


def test_rewards_equal_clem_score_on_a_results_folder(played):
    index, pairs, expected = {}, [], []
    for folder in played:
        instance = json.loads((folder / "instance.json").read_text())
        key = "/".join(folder.parts[-4:])  # model/game/experiment/episode
        index[key] = instance
        pairs.append((key, answers_of(json.loads((folder / "interactions.json").read_text()), instance)))
        expected.append(json.loads((folder / "scores.json").read_text())["episode scores"])
    rewards = score(pairs, Episodes(index))
    assert len(rewards) == len(played) == 23  # 10 erring, 7 + 6 scripted
    for reward, scores, (key, _) in zip(rewards, expected, pairs):
        assert reward.id == key
        for name in COMPARED:
            assert same(reward.scores.get(name), scores.get(name)), (key, name, reward.scores.get(name), scores.get(name))
        assert reward.category == scores[ERROR_CATEGORY] and reward.aborted == bool(scores["Aborted"])
        assert reward.es == (0 if reward.aborted else scores[EXECUTION_SUCCESS])
        assert reward.cell_f1 == (0.0 if reward.aborted else scores[CELL_F1])
        assert reward.puts == scores[PUTS]
        fg = scores.get(FUNCTION_GENERALISATION)
        assert reward.function_generalisation == (None if fg is None or math.isnan(fg) else fg)
    categories = {r.category for r in rewards}
    assert {"success", "parse_error", "type_error", "syntax_error", "mismatch_location"} <= categories
    assert len(categories) >= 7  # and the erring player's slips
    assert {r.function_generalisation for r in rewards} >= {None, 0.0, 1.0}  # the hard-coded function: 0.0


def test_pairs_are_checked_before_anything_runs():
    episodes = Episodes.from_files([SMOKE])
    key = next(iter(episodes))
    assert key == "sb_so_first_order_template/simple_simple_test_0000/first_order"
    for pairs, message in [([("nope", "x")], "pair 0: unknown episode id 'nope'"),
                           ([(key, 3)], "the completion must be a str or a list of str"),
                           ([(key, ["a"] * 9)], "9 answers for 2 turn"),
                           ([(key, "x"), "y"], "pair 1: expected (episode id, completion)")]:
        with pytest.raises(ValueError, match=message.replace("(", r"\(").replace(")", r"\)")):
            score(pairs, episodes)
