"""The built-in players' answer sources (sartco.clem.players.answers, sartco.games.describe.players): what
each answers turn by turn, and which one a player gets for a model name."""
import pytest

from play_helpers import REPO, scripted_episode
from sartco.games.describe.players import DescriberMock, DialogueFollower, builder_answers, describer_answers
from sartco.games.describe.turns import Dialogue, DialogueLog
from sartco.clem.players.answers import NO_CODE, GoldCode, InstructFollower, Scripted, instruct_answers
from sartco.clem.players.sourced import RULEBASED, fenced

TARGET = {"7:3": [["washer", "red"], ["nut", "blue"]]}
GOLD = ["put(board, 'washer', 'red', 7, 3)", "put(board, 'nut', 'blue', 7, 3)"]
STEPS = ["Place a red washer in the 8th row, 4th column.", "Place a blue nut on top of it."]


def multi_turn():
    episode = scripted_episode(0, TARGET, GOLD, STEPS, single_turn=False)
    episode["instructions"] = STEPS
    return episode


def test_scripted_repeats_its_last_answer_or_hands_over():
    assert [Scripted(["a", "b"]).answer(k) for k in range(4)] == ["a", "b", "b", "b"]
    then = Scripted(["x"])
    assert [Scripted(["a"], then=then).answer(k) for k in range(3)] == ["a", "x", "x"]


def test_gold_code_answers_each_turn_fenced():
    gold = GoldCode(GOLD)
    assert [gold.answer(k) for k in range(3)] == [fenced(GOLD[0]), fenced(GOLD[1]), fenced(GOLD[1])]
    assert GoldCode([]).answer(0) == NO_CODE


def test_follower_writes_one_turn_then_the_whole_program_after_the_last_instruction():
    follower = InstructFollower(multi_turn())
    assert follower.answer(0) == fenced(GOLD[0]) and follower.answer(1) == fenced(GOLD[1])
    assert follower.answer(2) == fenced("\n".join(GOLD))  # a repair after feedback: every instruction
    unreadable = {**multi_turn(), "instructions": ["Place something nice.", "And more."]}
    assert InstructFollower(unreadable).answer(0).startswith("```python\n# I cannot follow this instruction:")


def test_instruct_answers_are_chosen_by_the_model_name():
    episode = multi_turn()
    assert isinstance(instruct_answers(RULEBASED, episode), InstructFollower)
    assert isinstance(instruct_answers("mock", episode), GoldCode)
    assert instruct_answers("mock", {**episode, "script": ["s"]}).answer(0) == "s"
    paper = {**episode, "mock_answers": ["Output\nput(board, 'nut', 'red', 0, 0)\n"]}
    assert instruct_answers("mock", paper, paper=True).answer(0) == paper["mock_answers"][0]
    with pytest.raises(ValueError, match="paper protocol has no rule-based builder"):
        instruct_answers(RULEBASED, paper, paper=True)


def test_describe_sources_read_what_was_said():
    import json
    experiments = json.loads((REPO / "games" / "cobot_describe" / "in" / "instances_slice.json").read_text())
    episode = experiments["experiments"][0]["game_instances"][0]
    dialogue = Dialogue(DialogueLog("clarify", 2, 0))
    describer = describer_answers("mock", episode, dialogue)
    assert isinstance(describer, DescriberMock)
    assert describer.answer(0) == f"Instruction: {episode['template_instruction']}"
    dialogue.instruct(episode["template_instruction"])
    dialogue.ask("Which row?")
    assert describer.answer(1) == f"Answer: {episode['template_instruction']}"
    dialogue.instruction = episode["template_instruction"]
    assert isinstance(builder_answers("mock", episode, dialogue), DialogueFollower)
    assert builder_answers("mock", episode, dialogue).answer(0).startswith("```python\n")
    scripted = {**episode, "builder_script": ["Question: where?"]}
    assert builder_answers("mock", scripted, dialogue).answer(0) == "Question: where?"
    assert isinstance(builder_answers(RULEBASED, scripted, dialogue), DialogueFollower)  # rulebased: no script
