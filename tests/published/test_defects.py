"""sartco.published.defects: each defect rule on its own, on made-up records and real executions."""
from __future__ import annotations

from collections import Counter

import pytest

from sartco.program import execute
from sartco.published import defects

BOARD = "board = init_board(8, 8)\n"
RED_WASHER = BOARD + "put(board, 'washer', 'red', 0, 0)"
BLUE_NUT = BOARD + "put(board, 'nut', 'blue', 1, 1)"


def record(rid: str, target=None, instructions=None, file="sb_so_test.json", sample="simple/simple/2/wn/0"):
    return {"id": rid, "target": target, "instructions": instructions or {},
            "provenance": {"source": "published", "file": file, "sample": sample}}


@pytest.mark.parametrize("text, junk", [
    ("erere", True), ("rererer", True), ("   ", True), ("asdf qwer zxcv", True), ("Place it.", True),
    ("Fill the 4th column with ns objects.", False), ("Place a red washer in row 3.", False),
    ("Put bw objects on the diagonal", False),
])
def test_junk_rule(text, junk):
    assert defects.is_junk(text) is junk


@pytest.mark.parametrize("text, cleaned", [
    ("s: Place a red washer.", "Place a red washer."), ("s Place a red washer.", "Place a red washer."),
    (": Place a red washer.", "Place a red washer."), ("Place a red washer.", "Place a red washer."),
    ("screws go on top.", "screws go on top."),
])
def test_prefix_rule(text, cleaned):
    assert defects.without_stray_prefix(text) == cleaned



def test_judge_gold_keeps_the_board_every_style_builds_and_counts():
    red = execute(RED_WASHER)
    found, checked = [], Counter()
    target = defects.judge_gold("sb_so_test.json", record("r"), {"first_order": red, "optimal_function": red},
                                {"simple/simple/2/wn/0": red.cells}, found, checked)
    assert target == red.cells and found == [] and checked == {"run": 2, "built_gold": 2}


@pytest.mark.parametrize("runs, gold, kind, detail", [
    (["board = init_board(8, 8)\nput(board, 'washer', 'red', 9, 0)"], "red", "gold_error", "first_order gold code fails: "),
    ([BLUE_NUT], "red", "gold_mismatch", "first_order gold code builds another board than gold_boards"),
    ([RED_WASHER, BLUE_NUT], None, "gold_mismatch", "style1 gold code builds another board than the first style's"),
])
def test_judge_gold_leaves_out_a_sample_whose_gold_code_fails_or_differs(runs, gold, kind, detail):
    names = ["first_order", "style1"]
    executions = {names[i]: execute(code) for i, code in enumerate(runs)}
    boards = {"simple/simple/2/wn/0": execute(RED_WASHER).cells} if gold else None
    found, checked = [], Counter()
    assert defects.judge_gold("sb_so_test.json", record("r"), executions, boards, found, checked) is None
    assert [(d.kind, d.id) for d in found] == [(kind, "r")]
    assert found[0].detail.startswith(detail) and found[0].detail.endswith("sample left out")
    assert checked["run"] == len(runs)


def test_a_sample_without_a_gold_board_is_reported_and_kept():
    red = execute(RED_WASHER)
    found = []
    assert defects.judge_gold("sb_so_test.json", record("r"), {"first_order": red}, {}, found, Counter()) == red.cells
    assert [d.kind for d in found] == ["no_gold_board"]


def test_instruction_defects_name_the_variant_file_and_the_text():
    r = record("r", instructions={
        "template": {"multi_turn": ["Place a red washer in the 1st row, 1st column", "erere"]},
        "human": {"single_turn": "Place a red washer in the 1st row"},
        "gpt4": {"single_turn": "Place a red washer in the 1st row, 1st column."},
        "claude": {"single_turn": "Place a red washer in the 1st"}})
    found = defects.instruction_defects({"simple_simple_test.json": [r]})
    assert [(d.kind, d.file, d.detail) for d in found] == [
        ("junk_instruction", "sb_so_test.json", "template.multi_turn[1] 'erere'"),
        ("unterminated_instruction", "sb_so_test_hc.json", "human.single_turn ends 'Place a red washer in the 1st row'"),
        ("truncated_instruction", "sb_so_test_claude_mg.json", "claude.single_turn ends 'Place a red washer in the 1st'")]


def test_overlap_defects_in_two_files_and_twice_in_one():
    a, b = {"0:0": [["washer", "red"]]}, {"1:1": [["nut", "blue"]]}
    found = defects.overlap_defects({
        "regular_simple_train.json": [record("t1", a), record("t2", b), record("t3", b)],
        "regular_simple_test.json": [record("s1", a)]})
    assert [d.line() for d in found] == [
        "split_overlap: regular_simple_train.json: one board in regular_simple_train.json and "
        "regular_simple_test.json: t1, s1",
        "duplicate_board: regular_simple_train.json: one board 2 times: t2, t3"]
