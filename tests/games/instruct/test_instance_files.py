"""cobot_instruct's clemgame.json entries and their instance files: each kind of run is its own
game, so clem eval's score per game means one thing (the leaderboard game: Table 3 template cells,
test split, nothing else)."""
import json
from pathlib import Path

REPO = Path(__file__).resolve().parents[3]
GAME = REPO / "games" / "cobot_instruct"
CELLS = ["sb_so_first_order_template", "sb_so_sequence_function_template", "sb_so_optimal_function_template",
         "rb_so_repetition_template", "rb_co_repetition_template"]


def load(name):
    return json.loads((GAME / "in" / f"{name}.json").read_text(encoding="utf-8"))["experiments"]


def test_each_entry_names_its_own_instance_file():
    entries = {e["game_name"]: e for e in json.loads((GAME / "clemgame.json").read_text())}
    assert {name: e["instances"] for name, e in entries.items()} == {
        "cobot_instruct": "instances", "cobot_instruct_published": "instances_published",
        "cobot_instruct_paper": "instances_paper", "cobot_instruct_fresh": "instances_fresh",
        "cobot_instruct_ablations": "instances_ablations", "cobot_instruct_feedback": "instances_feedback",
        "cobot_instruct_published_feedback": "instances_published_feedback",
        "cobot_instruct_train": "instances_train"}
    assert all(e["main_game"] == "cobot_instruct" and isinstance(e["benchmark"], list) for e in entries.values())
    assert [name for name, e in entries.items() if "sartco" in e["benchmark"]] == ["cobot_instruct"]


def test_leaderboard_file_holds_the_table3_template_cells_only():
    experiments = load("instances")
    assert [e["name"] for e in experiments] == CELLS
    assert all(e["split"] == "test" and e["ablation"] is None and "attempts" not in e for e in experiments)
    assert [len(e["game_instances"]) for e in experiments] == [130] * 5


def test_ablations_and_feedback_have_their_own_files():
    ablations = load("instances_ablations")
    assert len(ablations) == 85 and all(e["split"] == "val" and e["ablation"] for e in ablations)
    feedback = load("instances_feedback")
    assert [e["feedback_of"] for e in feedback] == CELLS and all(e["attempts"] == 3 for e in feedback)


def test_smoke_file_is_the_first_episodes_of_each_cell():
    full, smoke = load("instances"), load("instances_smoke")
    assert [e["name"] for e in smoke] == CELLS
    for cell, small in zip(full, smoke):
        assert small == dict(cell, game_instances=cell["game_instances"][:2])
