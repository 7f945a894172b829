"""Function probes in played episodes: the scores in scores.json of cobot_instruct and
cobot_describe episodes played through clemcore's real loop (sartco.clem.core.probes)."""
import json

from play_helpers import GAMES, fence

HARD_CODED = """def bn(board, colors, x, y):
    put(board, 'bridge-v', 'green', 4, 3)
    put(board, 'nut', 'red', 4, 3)
bn(board, ('green', 'red'), 4, 3)"""


def experiment_of(game: str, task: str, name: str = "", file: str = "instances.json"):
    data = json.loads((GAMES / game / "in" / file).read_text())
    for e in data["experiments"]:
        if e["game_instances"][0]["task"] == task and name in e["name"]:
            return {k: v for k, v in e.items() if k != "game_instances"}, e["game_instances"]
    raise AssertionError(task)


def test_instruct_scores_name_function_generalisation(play_episodes):
    experiment, episodes = experiment_of("cobot_instruct", "optimal_function")
    ep = episodes[0]
    assert ep["combo_name"] == "bn" and ep["target"]["4:3"] == [["bridge-v", "green"], ["nut", "red"]]
    hard = {**ep, "game_id": 1, "script": [fence(HARD_CODED)]}
    gold, hard_result = play_episodes([ep, hard], experiment)
    s = gold["scores"]["episode scores"]
    assert (s["Execution Success"], s["Function Generalisation"], s["Probe Function"]) == (1, 1.0, "model")
    assert s["Probe Categories"] == ",".join(["success"] * 8)
    h = hard_result["scores"]["episode scores"]
    assert (h["Execution Success"], h["Main Score"], h["Function Generalisation"]) == (1, 100.0, 0.0)
    assert len(hard_result["interactions"]["sartco_probes"]["probes"]) == 8


def test_first_order_and_sequence_episodes_have_no_probe_scores(play_episodes):
    for task in ("first_order", "sequence_function"):
        experiment, episodes = experiment_of("cobot_instruct", task)
        [result] = play_episodes(episodes[:1], experiment)
        assert "Function Generalisation" not in result["scores"]["episode scores"], task
        assert "sartco_probes" not in result["interactions"]


def test_an_aborted_function_episode_scores_nan(play_episodes):
    experiment, episodes = experiment_of("cobot_instruct", "repetition")
    [result] = play_episodes([{**episodes[0], "script": ["no code here"]}], experiment)
    s = result["scores"]["episode scores"]
    assert s["Aborted"] == 1 and s["Function Generalisation"] is None  # NaN in scores.json


def test_describe_episodes_are_probed(play_episodes):
    experiment, episodes = experiment_of("cobot_describe", "optimal_function")
    [result] = play_episodes(episodes[:1], experiment, game="cobot_describe")
    s = result["scores"]["episode scores"]
    assert (s["Execution Success"], s["Function Generalisation"]) == (1, 1.0)
