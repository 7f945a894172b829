"""cobot_describe's dialogue on its own (sartco.games.describe.dialogue, sartco.games.describe.players): the
labels of the new turns, the state machine of whose turn it is, the mock describer's corrections on every test board, the rule-based
builder reading corrections."""
from __future__ import annotations

import json

import pytest

from play_helpers import REPO
from sartco.clem.core.errors import ParseError
from sartco.games.describe.dialogue import parse_builder_answer, parse_review, settings_of
from sartco.games.describe.players import correction_text
from sartco.games.describe.turns import BuilderTurn, Dialogue, DialogueLog, Said, State
from sartco.follower import emit
from sartco.follower.correct import apply_correction, pieces
from sartco.program import execute_many

FULL = REPO / "games" / "cobot_describe" / "in" / "instances.json"


def test_parsers():
    clarify = settings_of({"name": "x", "mode": "clarify"})
    assert (clarify.questions, clarify.corrections) == (2, 0)
    assert parse_builder_answer("**Question:** which row?", clarify, 0) == BuilderTurn.question("which row?")
    with pytest.raises(ParseError, match="past the limit"):
        parse_builder_answer("Question: which row?", clarify, 2)
    oneshot = settings_of({"name": "x"})
    with pytest.raises(ParseError):  # no questions in oneshot: a question is an answer without code
        parse_builder_answer("Question: which row?", oneshot, 0)
    # a label inside a code fence is part of the code: a comment is not a question
    code = "```python\n# Question: which row? the first\nput(board, 'nut', 'red', 0, 0)\n```"
    assert parse_builder_answer(code, clarify, 0) == BuilderTurn.code(
        "# Question: which row? the first\nput(board, 'nut', 'red', 0, 0)")
    assert parse_review("Done.") is None and parse_review("**Done**") is None
    assert parse_review("Correction: Place a red nut in the 1st row, 1st column.").startswith("Place a red nut")
    for bad in ("", "Looks good to me", "Correction:"):
        with pytest.raises(ParseError):
            parse_review(bad)
    for bad in ({"mode": "chat"}, {"mode": "correct", "corrections": -1}, {"mode": "clarify", "questions": "2"}):
        with pytest.raises(ValueError, match="experiment 'x': field"):
            settings_of({"name": "x", **bad})


def test_mock_corrections_repair_faulty_builds_on_every_test_board():
    """On every oneshot test board: a build missing one piece, one with a piece's colour changed,
    one shifted a column to the left and an empty one; the mock describer's correction, applied
    by the rule-based builder, builds the target every time."""
    full = json.loads(FULL.read_text())["experiments"]
    targets = [i["target"] for e in full if "mode" not in e for i in e["game_instances"]]
    assert len(targets) == 390
    faulty = []
    for n, target in enumerate(targets):
        ps = [p for _, p in pieces(target)]
        k = n % len(ps)
        recoloured = [type(p)(p.shape, "red" if p.color != "red" else "blue", p.x, p.y) if i == k else p
                      for i, p in enumerate(ps)]
        shifted = [type(p)(p.shape, p.color, p.x, max(0, p.y - 1)) for p in ps]
        for steps in (ps[:k] + ps[k + 1:], recoloured, shifted, []):
            faulty.append((target, "board = init_board(8, 8)\n" + emit.first_order(steps)))
    built = execute_many([code for _, code in faulty], 8, 8)
    repaired = []
    for (target, _), ex in zip(faulty, built):
        text = correction_text(ex.cells, target)
        assert (text == "") == (ex.cells == target)  # a shift off the edge may leave the board as it was
        steps = apply_correction([p for _, p in pieces(ex.cells)], text) if text else [p for _, p in pieces(target)]
        repaired.append("board = init_board(8, 8)\n" + emit.first_order(steps))
    results = execute_many(repaired, 8, 8)
    failed = [i for i, ((target, _), ex) in enumerate(zip(faulty, results)) if not (ex.ok and ex.cells == target)]
    assert failed == [] and len(results) == 4 * 390
    assert correction_text(targets[0], targets[0]) == ""


def test_rule_based_builder_reads_corrections():
    from sartco.follower import FollowError, Placement
    steps = [Placement("washer", "red", 7, 3), Placement("nut", "blue", 7, 3)]
    text = "Remove the blue nut in the 8th row, 4th column. Place a green screw in the 8th row, 4th column."
    assert apply_correction(steps, text) == [steps[0], Placement("screw", "green", 7, 3)]
    for unreadable in ("That looks wrong.", "Place a nut in the 1st row, 1st column."):  # nothing / no colour
        with pytest.raises(FollowError):
            apply_correction(steps, unreadable)


def record(error: str | None = None):
    """A build record as the dialogue sees it (it reads only whether the answer held code)."""
    from sartco.clem.core.building import build, parse_failure
    target = {"0:0": [["nut", "red"]]}
    return parse_failure(target, "no code") if error else build("put(board, 'nut', 'red', 0, 0)", target)


def test_the_dialogue_moves_only_along_its_transitions():
    d = Dialogue(DialogueLog("clarify_correct", 1, 1))
    assert d.state is State.INSTRUCTION
    with pytest.raises(RuntimeError, match="no move from instruction to"):
        d.ask("Which row?")   # the builder cannot ask before the instruction
    d.instruct("Put a red nut in the corner.")
    d.ask("Which corner?")
    assert d.state is State.ANSWER and (d.left(Said.QUESTION), d.left(Said.CORRECTION)) == (0, 1)
    with pytest.raises(ValueError, match="only questions and corrections are limited"):
        d.left(Said.ANSWER)   # no budget of answers: never counted as corrections
    with pytest.raises(RuntimeError):
        d.build(record())     # the describer owes an answer first
    d.answer("The top left one.")
    d.build(record())         # a correction is left: the describer reviews
    assert (d.state, d.answers) == (State.REVIEW, [])
    d.correct("Remove the red nut in the 1st row, 1st column.")
    assert (d.state, d.correction) == (State.BUILD, "Remove the red nut in the 1st row, 1st column.")
    d.build(record())         # no correction left: over
    assert d.state is State.OVER and d.correction is None
    with pytest.raises(RuntimeError):
        d.done()
    # the log's kinds as interactions.json holds them: the Said values, written as their strings
    assert json.loads(json.dumps(d.log.to_json()))["events"] == [
        {"kind": "instruction", "text": "Put a red nut in the corner.", "build": 0},
        {"kind": "question", "text": "Which corner?", "build": 0}, {"kind": "answer", "text": "The top left one.", "build": 0},
        {"kind": "correction", "text": "Remove the red nut in the 1st row, 1st column.", "build": 1}]
    assert (d.log.count(Said.QUESTION), d.log.count(Said.CORRECTION), d.log.describer_words) == (1, 1, 7 + 4 + 10)


def test_a_build_without_code_is_not_reviewed_and_an_unreadable_describer_ends_or_skips_the_build():
    d = Dialogue(DialogueLog("correct", 0, 3))
    d.instruct("Put a red nut in the corner.")
    d.build(record(error="parse_error"))
    assert d.state is State.OVER   # corrections left, but nothing was built to review
    d = Dialogue(DialogueLog("correct", 0, 3))
    d.fail("no instruction")       # no board stands: the builder's turn is an empty build
    assert d.state is State.BUILD and d.log.events[-1]["kind"] == "no_instruction"
    d.build(record(error="parse_error"))
    d = Dialogue(DialogueLog("correct", 0, 3))
    d.instruct("Put a red nut in the corner.")
    d.build(record())
    d.fail("neither Done nor a correction")   # the board stands
    assert d.state is State.OVER and d.log.events[-1]["kind"] == "no_review"
