"""The rule-based follower: 100% ES on the published template instructions, tricky wordings, failures."""
from __future__ import annotations

import importlib.util
from pathlib import Path

import pytest

from sartco.follower import FollowError, follow, follow_turn, read_placements
from sartco.program import execute
from sartco.world import parse_key

REPO = Path(__file__).resolve().parents[2]
DATA = REPO.parent / "shared" / "sartco-data"
PUBLISHED = sorted((DATA / "published").glob("*.json")) if (DATA / "published").is_dir() else []


def _eval_tool():
    spec = importlib.util.spec_from_file_location("eval_follower", REPO / "tools" / "eval_follower.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def build(code: str, context: str = "") -> dict:
    """Run follower code the way the games do (through sartco.program): the given function, a
    fresh board, the code; it must run without error."""
    ex = execute(context + "\nboard = init_board(8, 8)\n" + code)
    assert ex.ok, f"{ex.error}: {ex.message}"
    return ex.cells


# --- the published template instructions -------------------------------------------------------------
@pytest.mark.skipif(not PUBLISHED, reason=f"published data not found in {DATA}")
@pytest.mark.parametrize("path", PUBLISHED, ids=lambda p: p.stem)
def test_template_instructions_build_every_gold_board(path):
    results = _eval_tool().evaluate(DATA, [path.stem])
    template = {variant: r for (_, variant), r in results.items() if r["source"] == "template"}
    assert template, "no template instructions in this file"
    for variant, r in template.items():
        failures = [f"{sid} [{kind}] {msg[:100]} :: {' || '.join(texts)[:200]}"
                    for sid, kind, msg, texts in r["failures"][:5]]
        assert r["es"] == r["n"], f"{variant}: ES {r['es']}/{r['n']}\n" + "\n".join(failures)


# --- simple boards: wordings --------------------------------------------------------------------------
@pytest.mark.parametrize("text, expected", [
    ("Place a red washer in the 8th row, 4th column.", ("washer", "red", 7, 3)),
    ("place a Blue NUT in the eighth row and fourth column", ("nut", "blue", 7, 3)),
    ("Put a green screw in row 2, column 5", ("screw", "green", 1, 4)),
    ("put a green screw at Row(2), Col(5)", ("screw", "green", 1, 4)),
    ("Place a yellow washer in the top row, leftmost column.", ("washer", "yellow", 0, 0)),
    ("Place a yellow washer in the bottom row, rightmost column.", ("washer", "yellow", 7, 7)),
    ("Place a red washer in the last row, 1st column.", ("washer", "red", 7, 0)),
    ("In the 3rd row, 2nd column, place a red nut.", ("nut", "red", 2, 1)),
    ("Place a red washer in column 4 of row 8", ("washer", "red", 7, 3)),
    ("Place a yellow bridge vertically in the 2nd row, 3rd column.", ("bridge-v", "yellow", 1, 2)),
    ("place a red horizontal bridge in the 1st row, 7th column", ("bridge-h", "red", 0, 6)),
    ("Place a red bridge-h in the 1st row, 7th column", ("bridge-h", "red", 0, 6)),
])
def test_one_placement(text, expected):
    (step,) = read_placements([text])
    assert (step.shape, step.color, step.x, step.y) == expected


def test_on_top_of_it_reuses_the_previous_cell():
    steps = read_placements(["Place a red washer in the 8th row, 4th column, then put a blue nut on top of it."])
    assert [(s.shape, s.color, s.x, s.y) for s in steps] == [("washer", "red", 7, 3), ("nut", "blue", 7, 3)]


def test_multi_turn_instructions_give_one_put_per_turn():
    turns = ["These are the step-by-step instructions to build wn. place a red washer in the 8th row, 4th column",
             "place a blue nut in the 8th row, 4th column"]
    assert follow(turns, "first_order") == ("put(board, 'washer', 'red', 7, 3)\n"
                                            "put(board, 'nut', 'blue', 7, 3)")
    assert follow_turn(turns[1], history=turns[:1]) == "put(board, 'nut', 'blue', 7, 3)"
    assert follow_turn("place a green screw on top of it", history=turns) == "put(board, 'screw', 'green', 7, 3)"


TEXT = ("These are the instructions to build bnw. Place a red bridge horizontally in the 1st row, 7th column. "
        "Place a blue nut in the 1st row, 8th column. Place a green washer in the 1st row, 7th column.")


def test_the_three_simple_styles_build_the_same_board():
    boards = [build(follow([TEXT], task)) for task in ("first_order", "sequence_function", "optimal_function")]
    assert boards[0] == boards[1] == boards[2] == {
        "0:6": [["bridge-h", "red"], ["washer", "green"]], "0:7": [["bridge-h", "red"], ["nut", "blue"]]}


def test_function_styles_use_the_object_name():
    assert follow([TEXT], "optimal_function").splitlines()[0] == "def bnw(board, colors, x, y):"
    assert follow([TEXT], "optimal_function").splitlines()[-1] == "bnw(board, ('red', 'blue', 'green'), 0, 6)"
    assert follow([TEXT], "sequence_function").splitlines()[-1] == (
        "bnw(board, ['red', 'blue', 'green'], [0, 0, 0], [6, 7, 6])")
    # no name given: the shapes' letters
    assert follow(["Place a red nut in row 1, column 1."], "sequence_function").startswith("def n(board")


# --- regular boards ----------------------------------------------------------------------------------
BW_H = """def bw(board, colors, x, y):
    shapes = ['bridge-h', 'washer']
    for shape, color, dx, dy in zip(shapes, colors, [0, 0], [0, 0]):
        put(board, shape, color, x + dx, y + dy)"""
NS = BW_H.replace("bw", "ns").replace("'bridge-h', 'washer'", "'nut', 'screw'")
# an L of three cells in a 2x2 box; (1, 1) is free, so diagonal neighbours do not overlap
BNB = """def bnb(board, colors, x, y):
    shapes = ['bridge-h', 'nut', 'bridge-v']
    for shape, color, dx, dy in zip(shapes, colors, [0, 1, 0], [0, 0, 0]):
        put(board, shape, color, x + dx, y + dy)"""


def anchors(code: str, context: str) -> set[tuple[int, int]]:
    """The cells where the code calls the object function: run (through sartco.program) with a
    stand-in function of the same name that puts one washer at its anchor."""
    name = context.split("(")[0].split()[-1]
    probe = f"def {name}(board, colors, x, y):\n    put(board, 'washer', colors[0], x, y)\n"
    return {parse_key(key) for key in build(code, probe)}


@pytest.mark.parametrize("text, context, expected", [
    ("Place a 'bw' object in the first, fourth, and seventh columns of the first row. Then, repeat this pattern "
     "of placement in the remaining rows. Use only these colors: ['red', 'yellow'] for the 'bw' object.",
     BW_H, {(r, c) for r in range(8) for c in (0, 3, 6)}),
    ("place a 'ns' object in the 1st and 5th columns of the 1st row; then repeat this placement pattern in the "
     "5th row. Use only these colors: ['red', 'blue'] for the 'ns' object.",
     NS, {(0, 0), (0, 4), (4, 0), (4, 4)}),
    ("Place a 'ns' object in the first, fourth, and seventh rows of the first column. Then, repeat this placement "
     "pattern in the remaining columns. Use only these colors: ['red', 'blue'] for the 'ns' object.",
     NS, {(r, c) for r in (0, 3, 6) for c in range(8)}),
    ("Place a 'bw' object in the 1st, 4th and 7th columns of the 1st row, then repeat in all remaining rows. "
     "Colors: red, yellow.", BW_H, {(r, c) for r in range(8) for c in (0, 3, 6)}),
    ("Place a 'ns' object in the 1st and 5th columns of the 1st row, then repeat this in the 3rd and 5th rows. "
     "Colors: red, yellow.", NS, {(r, c) for r in (0, 2, 4) for c in (0, 4)}),
    ("PLACE A 'NS' OBJECT AT ALL THE CORNERS OF THE GRID. USE ONLY THESE COLORS: ['RED', 'BLUE'] FOR THE 'NS' OBJECT.",
     NS, {(0, 0), (0, 7), (7, 0), (7, 7)}),
    ("Place a 'bw' object at all the corners of the grid. Use only these colors: ['red', 'blue'] for the 'bw' object.",
     BW_H, {(0, 0), (0, 6), (7, 0), (7, 6)}),  # the object is 1x2: it must fit in the corner
    ("Starting from the top-left corner, fill the grid with 'ns' objects diagonally. Use only these colors: "
     "['red', 'blue'] for the 'ns' object.", NS, {(i, i) for i in range(8)}),
    ("Start from the top-left corner and diagonally place 'bnb' objects, each taking a 2x2 space. Continue until "
     "there's insufficient space at the grid's end for a full object. Use only these colors: ['red', 'blue', "
     "'green'] for the 'bnb' object.", BNB, {(i, i) for i in range(7)}),
    ("Start from the top-left corner and diagonally place 'bw' objects, each taking a 1x2 space. Continue until "
     "there's insufficient space at the grid's end for a full object. Use only these colors: ['red', 'blue'] "
     "for the 'bw' object.", BW_H, {(i, i) for i in range(7)}),
    ("Starting from the top-left corner, place the 'bw' object in alternating columns of the first row, each "
     "occupying a 1x2 space. Continue until there's insufficient space at the grid's end for a full object. Then, "
     "repeat this pattern in alternating rows. Use only these colors: ['red', 'blue'] for the 'bw' object.",
     BW_H, {(r, c) for r in (0, 2, 4, 6) for c in (0, 3, 6)}),
    ("Fill the first column with the 'bw' object, each occupying a 1x2 space. Continue until there's "
     "insufficient space at the grid's end for a full object. Then repeat this action in every alternate column. "
     "Use only these colors: ['red', 'blue'] for the 'bw' object.", BW_H, {(r, c) for r in range(8) for c in (0, 3, 6)}),
    ("Fill the fourth column with the 'ns' object, each occupying a 1x1 space. Use only these colors: "
     "['red', 'blue'] for the 'ns' object.", NS, {(r, 3) for r in range(8)}),
])
def test_regular_arrangements(text, context, expected):
    code = follow([text], "repetition", context=context)
    assert anchors(code, context) == expected
    build(code, context)  # and it runs under the world's rules


def test_repetition_colours_and_name_without_context():
    code = follow(["Place a 'ns' object at all the corners of the grid. Use only these colors: red and blue."],
                  "repetition")
    assert "ns(board, colors=['red', 'blue']" in code


# --- failures: one documented exception, a clear message ---------------------------------------------
@pytest.mark.parametrize("instructions, task, context, fragment", [
    (["hello there"], "first_order", "", "no placement"),
    ([""], "optimal_function", "", "no placement"),
    (["Place a red bridge in the 1st row, 2nd column."], "first_order", "", "orientation"),
    (["Place a washer in the 1st row, 2nd column."], "first_order", "", "colour"),
    (["Place a washer and a red nut in row 8, column 4."], "first_order", "", "washer without a colour"),
    (["Place a red washer somewhere nice."], "first_order", "", "row and column"),
    (["Place a red washer in the 9th row, 2nd column."], "first_order", "", "outside"),
    (["Place a red washer in the 1st row, 2nd column."], "fourth_order", "", "unknown task"),
    ([42], "first_order", "", "list of strings"),
    (["Make something pretty with 'ns' objects. Use only these colors: ['red']"], "repetition", NS, "arrangement"),
    (["Place a 'ns' object at all the corners of the grid."], "repetition", NS, "colours"),
    (["Place a 'ns' object in the 1st and 5th columns of the 1st row. Then repeat it wherever you like. "
      "Colors: red, blue"], "repetition", NS, "where to repeat"),
    (["Place objects at all the corners of the grid. Use only these colors: ['red']"], "repetition", "", "name"),
])
def test_unreadable_instructions_raise_follow_error(instructions, task, context, fragment):
    with pytest.raises(FollowError, match=fragment):
        follow(instructions, task, context=context)


def test_follow_error_is_a_value_error():
    assert issubclass(FollowError, ValueError)
