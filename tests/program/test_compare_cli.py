"""compare(): ES, the mismatch categories and P/R/F1; judge(): an execution against its target;
`sartco execute`: the JSON-lines contract."""
import json
import subprocess
import sys

import pytest

from sartco.program import Comparison, compare, execute, judge
from sartco.world import ErrorCode

E = ErrorCode
W, N, S = ["washer", "red"], ["nut", "blue"], ["screw", "green"]
TARGET = {"1:1": [W, N], "2:2": [S]}


@pytest.mark.parametrize("built,category", [
    ({"1:1": [W, N], "2:2": [S]}, None),
    ({"2:2": [S]}, E.MISMATCH_LOCATION),                      # target cell missing
    ({"1:1": [W], "2:2": [S]}, E.MISMATCH_COUNT),             # shorter stack
    ({"1:1": [W, S], "2:2": [S]}, E.MISMATCH_SHAPE),          # another shape
    ({"1:1": [N, W], "2:2": [S]}, E.MISMATCH_ORDER),          # same shapes, other order
    ({"1:1": [W, ["nut", "red"]], "2:2": [S]}, E.MISMATCH_COLOR),
    ({"1:1": [W, N], "2:2": [S], "0:0": [S]}, E.MISMATCH_LOCATION),  # extra built cell
    ({"1:1": [N, W], "2:2": [["washer", "red"]]}, E.MISMATCH_ORDER),  # first cell in row-major order decides
    ({"1:1": [W, N], "2:2": [S], "3:3": []}, None),           # empty cells do not count
])
def test_categories(built, category):
    cmp = compare(built, TARGET)
    assert cmp.category == category
    assert cmp.es == (category is None)


def test_row_major_scan_decides_between_two_differences():
    target = {"0:5": [W], "1:0": [W, N]}
    built = {"1:0": [W], "0:5": [N]}       # 0:5 comes first in row-major order
    assert compare(built, target).category == E.MISMATCH_SHAPE
    assert compare(built, {"10:0": [W], "9:1": [W]}).category == E.MISMATCH_LOCATION


def test_precision_recall_f1():
    built = {"1:1": [W, S], "3:3": [S]}   # entries: (1,1,0,W) hit, (1,1,1,S) miss, (3,3,0,S) miss
    cmp = compare(built, TARGET)          # target entries: (1,1,0,W), (1,1,1,N), (2,2,0,S)
    assert cmp == Comparison(0, E.MISMATCH_SHAPE, 1 / 3, 1 / 3, pytest.approx(1 / 3))
    assert compare(TARGET, TARGET) == Comparison(1, None, 1.0, 1.0, 1.0)
    assert compare({}, {}) == Comparison(1, None, 1.0, 1.0, 1.0)             # empty/empty = 1.0
    assert compare({}, TARGET) == Comparison(0, E.MISMATCH_LOCATION, 0.0, 0.0, 0.0)
    assert compare(TARGET, {}) == Comparison(0, E.MISMATCH_LOCATION, 0.0, 0.0, 0.0)
    half = compare({"1:1": [W]}, {"1:1": [W, N]})
    assert (half.precision, half.recall, half.f1) == (1.0, 0.5, pytest.approx(2 / 3))


def test_bridge_counts_in_both_cells():
    built = execute("put(board, 'bridge-h', 'red', 0, 0)").cells
    assert built == {"0:0": [["bridge-h", "red"]], "0:1": [["bridge-h", "red"]]}
    cmp = compare(built, {"0:0": [["bridge-h", "red"]]})
    assert (cmp.category, cmp.precision, cmp.recall) == (E.MISMATCH_LOCATION, 0.5, 1.0)


def test_judge_a_program_that_failed_part_way_has_es_0_and_its_error():
    ex = execute("put(board, 'washer', 'red', 1, 1)\nput(board, 'nut', 'blue', 1, 1)\nput(board, 'screw', 'green', 2, 2)\n"
                 "put(board, 'nut', 'red', 2, 2)")
    assert (ex.ok, ex.error, ex.cells) == (False, E.NOT_ON_TOP_OF_SCREW, TARGET)  # the target, then a failed put
    assert compare(ex.cells, TARGET).es == 1
    assert judge(ex.ok, ex.error, ex.cells, TARGET) == Comparison(0, E.NOT_ON_TOP_OF_SCREW, 1.0, 1.0, 1.0)
    partial = execute("put(board, 'washer', 'red', 1, 1)\nx = 1 / 0")
    assert judge(partial.ok, partial.error, partial.cells, TARGET) == Comparison(
        0, E.ZERO_DIVISION, 1.0, 1 / 3, pytest.approx(0.5))


@pytest.mark.parametrize("built", [TARGET, {"1:1": [W]}, {}])
def test_judge_a_program_that_ran_is_compare(built):
    assert judge(True, None, built, TARGET) == compare(built, TARGET)


def _run_cli(lines: list[str], *args) -> list[dict]:
    proc = subprocess.run([sys.executable, "-m", "sartco", "execute", *args], input="\n".join(lines) + "\n",
                          capture_output=True, text=True, timeout=120)
    assert proc.returncode == 0, proc.stderr
    return [json.loads(line) for line in proc.stdout.splitlines()]


def test_cli_contract():
    good = "board = init_board(8, 8)\nput(board, 'washer', 'red', 1, 1)\nput(board, 'nut', 'blue', 1, 1)"
    lines = [
        json.dumps({"id": "a", "code": good, "target": {"1:1": [W, N]}}),
        json.dumps({"id": "b", "code": good}),
        "{not json",
        "",
        json.dumps({"id": "c", "code": "put(board, 'washer', 'red', 1, 1)\nput(board, 'washer', 'red', 1, 1)",
                    "target": {"1:1": [W, N]}}),
        json.dumps({"id": "d", "code": "import os"}),
        json.dumps(["a list"]),
        json.dumps({"id": "e", "code": 42}),
        json.dumps({"id": "f", "code": good, "target": {"x": 1}}),
        json.dumps({"id": "g", "code": "put(board, 'screw', 'red', 0, 0)", "target": {"1:1": [W, N]}}),
    ]
    out = _run_cli(lines)
    assert [o["id"] for o in out] == ["a", "b", None, "c", "d", None, "e", "f", "g"]
    a, b, bad, c, d, not_obj, e, f, g = out
    assert a == {"id": "a", "ok": True, "error": None, "message": "", "cells": {"1:1": [W, N]},
                 "es": 1, "category": None, "precision": 1.0, "recall": 1.0, "f1": 1.0}
    assert b == {"id": "b", "ok": True, "error": None, "message": "", "cells": {"1:1": [W, N]}}
    for o in (bad, not_obj, e, f):
        assert (o["ok"], o["error"], o["cells"]) == (False, "parse_error", {})
        assert o["message"].startswith("input line ") and "es" not in o
    assert "line 3" in bad["message"]
    assert (c["ok"], c["error"], c["es"], c["category"]) == (False, "same_shape_stacking", 0, "same_shape_stacking")
    assert c["cells"] == {"1:1": [W]} and c["precision"] == 1.0 and c["recall"] == 0.5
    assert (d["ok"], d["error"]) == (False, "forbidden")
    assert (g["ok"], g["es"], g["category"]) == (True, 0, "mismatch_location")


def test_cli_board_size_and_user_errors():
    out = _run_cli([json.dumps({"id": "x", "code": "put(board, 'washer', 'red', 9, 9)"})], "--rows", "10", "--cols", "10")
    assert out[0]["cells"] == {"9:9": [W]}
    out = _run_cli([json.dumps({"id": "x", "code": "put(board, 'washer', 'red', 9, 9)"})])
    assert out[0]["error"] == "dimensions_mismatch"
    proc = subprocess.run([sys.executable, "-m", "sartco", "execute", "--rows", "0"], input="",
                          capture_output=True, text=True, timeout=60)
    assert proc.returncode == 2 and "Traceback" not in proc.stderr and "--rows" in proc.stderr


def test_cli_hard_timeout_is_answered_in_order():
    slow = "x = sum(sum(range(10**6)) for i in range(10**6))"
    lines = [json.dumps({"id": "slow", "code": slow, "target": {"1:1": [W]}}),
             json.dumps({"id": "after", "code": "put(board, 'washer', 'red', 1, 1)", "target": {"1:1": [W]}})]
    slow_out, after = _run_cli(lines, "--wall-time", "1", "--workers", "1")
    assert (slow_out["id"], slow_out["ok"], slow_out["error"], slow_out["es"], slow_out["category"]) == \
        ("slow", False, "timeout", 0, "timeout")
    assert (slow_out["precision"], slow_out["recall"]) == (0.0, 0.0)
    assert (after["id"], after["ok"], after["es"]) == ("after", True, 1)
