"""Each scoring rule of the paper-protocol README ("Scoring"), on real published episodes."""
import pytest

import sartco.paper.scoring as scoring
from sartco.paper.reading import read_answer
from sartco.paper.scoring import DialogueScore, TurnScore, score_dialogue, score_turn

PUT = "put(board, 'washer', 'red', 7, 3)"
DEF = ("def wn(board, colors, x, y):\n    shapes = ['washer', 'nut']\n"
       "    for shape, color, dx, dy in zip(shapes, colors, [0, 0], [0, 0]):\n"
       "            put(board, shape, color, x + dx, y + dy)")
USE = "wn(board, ('red', 'blue'), 7, 3)"
SINGLE_GOLD = {"function": DEF + "\n" + USE, "usage": USE}


def one(episodes, file, variant, n_turns=None):
    return next(e for e in episodes if e.file == file and e.variant == variant
                and (n_turns is None or len(e.gold) == n_turns))


# ----------------------------------------------------------------------------- exact match

def test_em_compares_stripped_non_empty_lines():
    assert score_turn({"output": f"\n   {PUT}   \n\n"}, {"output": PUT}, "multi_turn").em
    assert not score_turn({"output": PUT.replace("7", "6")}, {"output": PUT}, "multi_turn").em


def test_em_cuts_prediction_lines_at_their_first_colon():
    assert score_turn({"output": f"# the washer: {PUT}"}, {"output": PUT}, "multi_turn").em
    # so a def or for line can never match: EM is 0 on every function and repetition answer
    assert not score_turn(dict(SINGLE_GOLD), SINGLE_GOLD, "single_turn").em
    loop = "for row in range(8):\n    wn(board, ['red', 'blue'], row, 0)"
    assert not score_turn({"output": loop}, {"output": loop}, "regular", given_function=DEF).em


def test_em_every_compared_key_must_match():
    gold = {"function": USE + "\n" + USE, "usage": USE}   # a gold without colons, so that EM can match
    assert score_turn({"function": USE + "\n" + USE, "usage": USE}, gold, "single_turn").em
    assert not score_turn({"function": USE + "\n" + USE, "usage": ""}, gold, "single_turn").em


# ----------------------------------------------------------------------------- CodeBLEU pass

def test_cb_passes_identical_code_and_fails_unrelated_or_empty_code():
    assert score_turn(dict(SINGLE_GOLD), SINGLE_GOLD, "single_turn").cb
    assert not score_turn({"function": "x = 1", "usage": USE}, SINGLE_GOLD, "single_turn").cb
    assert not score_turn({"function": SINGLE_GOLD["function"], "usage": ""}, SINGLE_GOLD, "single_turn").cb


@pytest.mark.parametrize("score,passes", [(0.5, False), (0.5004, False), (0.5006, True), (0.9, True), (0.25, False)])
def test_cb_is_a_pass_rate_above_one_half_after_rounding_to_three_decimals(monkeypatch, score, passes):
    seen = []
    monkeypatch.setattr(scoring, "code_bleu", lambda pred, gold: seen.append((pred, gold)) or score)
    assert score_turn({"output": PUT}, {"output": PUT}, "multi_turn").cb is passes
    assert seen == [(PUT, PUT)]


def test_cb_uses_the_projects_codebleu_with_the_papers_weights():
    from codebleu import calc_codebleu
    pred = "put(board, 'nut', 'red', 7, 3)"
    theirs = calc_codebleu([PUT], [pred], lang="python", weights=(0.25, 0.25, 0.25, 0.25))["codebleu"]
    assert scoring.code_bleu(pred, PUT) == pytest.approx(theirs, abs=1e-9)


# ----------------------------------------------------------------------------- execution success

def test_es_runs_each_turn_alone_and_compares_with_the_gold_programs_board():
    nut = "put(board, 'nut', 'blue', 7, 3)"   # the second turn of a washer+nut stack
    assert score_turn({"output": nut}, {"output": nut}, "multi_turn") == TurnScore(True, True, True, None)


def test_es_wrong_coordinates_and_raising_programs():
    wrong = score_turn({"output": PUT.replace("7, 3", "6, 3")}, {"output": PUT}, "multi_turn")
    assert (wrong.es, wrong.category) == (False, "mismatch_location")
    off = score_turn({"output": PUT.replace("7, 3", "9, 3")}, {"output": PUT}, "multi_turn")
    assert (off.es, off.category) == (False, "dimensions_mismatch")
    name = score_turn({"output": "place(board)"}, {"output": PUT}, "multi_turn")
    assert (name.es, name.category) == (False, "name_error")


@pytest.mark.parametrize("suffix,ok", [(";", True), (".", True), (",", True), ("\n", True), ("..", False), (".;", False)])
def test_es_drops_one_trailing_separator(suffix, ok):
    assert score_turn({"output": PUT + suffix}, {"output": PUT}, "multi_turn").es is ok


def test_es_refuses_any_program_containing_while():
    loop = f"i = 0\nwhile i < 1:\n    {PUT}\n    i += 1"
    got = score_turn({"output": loop}, {"output": PUT}, "multi_turn")
    assert got == TurnScore(False, got.cb, False, "forbidden", "While loop not supported")
    # the text, not the statement: a comment is enough
    assert score_turn({"output": PUT + "  # meanwhile"}, {"output": PUT}, "multi_turn").message == "While loop not supported"


def test_es_regular_puts_the_gold_function_in_front():
    out = "for row in range(8):\n    wn(board, ('red', 'blue'), row, 0)"
    assert score_turn({"output": out}, {"output": out}, "regular", given_function=DEF).es
    alone = score_turn({"output": out}, {"output": out}, "regular")
    assert (alone.es, alone.category) == (False, "name_error")


def test_es_single_turn_runs_the_function_text_not_the_usage():
    # the usage key is never executed: a function answer without its call builds nothing
    got = score_turn({"function": DEF, "usage": USE}, SINGLE_GOLD, "single_turn")
    assert (got.es, got.category) == (False, "mismatch_location")
    assert score_turn({"function": DEF + "\n" + USE, "usage": ""}, SINGLE_GOLD, "single_turn").es


def test_keys_the_prediction_lacks_are_not_compared():
    got = score_turn({"function": DEF + "\n" + USE}, SINGLE_GOLD, "single_turn")
    assert (got.cb, got.es) == (True, True)
    usage_only = score_turn({"usage": USE}, SINGLE_GOLD, "single_turn")   # nothing to execute
    assert (usage_only.em, usage_only.cb, usage_only.es) == (True, True, False)
    nothing = score_turn({"code": PUT}, {"output": PUT}, "multi_turn")
    assert nothing == TurnScore(False, False, False, "parse_error", "the prediction has none of the keys output")


# ----------------------------------------------------------------------------- dialogues

def test_empty_answer_fails_all_three(episodes):
    e = one(episodes, "sb_so_test", "single_turn")
    for answer in ("", "   \n"):
        s = score_dialogue([answer], e)
        assert (s.em, s.cb, s.es) == (0, 0, 0)
        assert s.turns[0] == TurnScore(False, False, False, "parse_error", "empty answer")


def test_multi_turn_with_one_wrong_turn(episodes):
    e = one(episodes, "sb_so_test", "multi_turn", n_turns=4)
    answers = list(e.mock_answers)
    answers[2] = answers[2].replace(")\n", " + 1)\n")   # the third put one column off
    s = score_dialogue(answers, e)
    assert s.es == pytest.approx(1 - 1 / 4) and s.em == pytest.approx(1 - 1 / 4)
    assert [t.es for t in s.turns] == [True, True, False, True]


def test_mock_answers_score_like_the_papers_gold(episodes):
    for variant, em in (("multi_turn", 1.0), ("single_turn_sc", 0.0), ("regular_hai", 0.0)):
        e = one(episodes, "sb_so_test" if variant.startswith(("multi", "single")) else "rb_cho_test_hc", variant)
        assert score_dialogue(e.mock_answers, e) == DialogueScore(em, 1.0, 1.0, [TurnScore(em == 1.0, True, True, None)] * len(e.gold))
        assert score_dialogue(e.mock_answers, e.to_json()).es == 1.0


def test_answers_in_other_forms_read_and_score(episodes):
    e = one(episodes, "rb_so_test_hc", "regular_hai")
    code = e.gold[0]["output"]
    for answer in (f"Output:\n```python\n{code}\n```", f"Here you go.\nOutput\n{code}", f"```python\n{code}\n```"):
        assert score_dialogue([answer], e).es == 1.0, answer
    assert score_dialogue([f"Output:\n{code}\nHope this helps!"], e).turns[0].category == "syntax_error"


def test_missing_answers_fail_and_extra_answers_are_refused(episodes):
    e = one(episodes, "sb_so_test", "multi_turn", n_turns=2)
    s = score_dialogue(e.mock_answers[:1], e)
    assert (s.es, s.turns[1].category) == (0.5, "parse_error")
    with pytest.raises(ValueError, match="3 responses for 2 turn"):
        score_dialogue(e.mock_answers + ["x"], e)
    with pytest.raises(ValueError, match="list of strings"):
        score_dialogue([None], e)


def test_read_then_score_agree_with_score_dialogue(episodes):
    e = one(episodes, "sb_so_test_gpt4_mg", "single_turn_mg")
    answer = e.mock_answers[0]
    assert score_dialogue([answer], e).turns[0] == score_turn(read_answer(answer, e.variant), e.gold[0], e.variant)


def test_es_fails_when_the_gold_program_itself_raises():
    # README: the turn succeeds if the built board equals the gold board; a gold that raises
    # builds none (the authors' scorer fails such a turn), so neither nothing nor a partial board
    # equal to what the gold built before it raised succeeds
    off_board = "put(board, 'nut', 'red', 9, 9)"
    for prediction, gold in (("x = 1", off_board), (PUT, PUT + "\n" + off_board)):
        got = score_turn({"output": prediction}, {"output": gold}, "multi_turn")
        assert (got.es, got.category) == (False, "dimensions_mismatch"), prediction
        assert got.message.startswith("the gold program failed")
