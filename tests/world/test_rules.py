"""The world's assembly rules, one row per rule and per documented deviation from the authors'
simulator (../shared/sartco-data/README.md, "Facts established from the authors' simulator").

Each row: the puts already on an empty 8x8 board, one more put, the error code we raise (None: it
is placed), and what the authors' simulator does with the same puts (tools/world_agreement.py's
model of it): the same code unless the row is one of our documented deviations."""
import importlib.util
from pathlib import Path

import pytest

from sartco.world import Board, ErrorCode, WorldError, put

REPO = Path(__file__).resolve().parents[2]
_spec = importlib.util.spec_from_file_location("world_agreement", REPO / "tools" / "world_agreement.py")
world_agreement = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(world_agreement)

SAME = "same"  # the authors' simulator raises the same code
W, N, S, BH, BV = "washer", "nut", "screw", "bridge-h", "bridge-v"

# name: (puts before, the put, our code, the authors' code or SAME)
RULES = {
    # placed
    "washer on an empty cell": ([], (W, "red", 7, 3), None, SAME),
    "washer in the first corner": ([], (W, "red", 0, 0), None, SAME),
    "washer in the last corner": ([], (W, "red", 7, 7), None, SAME),
    "nut on a washer": ([(W, "red", 7, 3)], (N, "blue", 7, 3), None, SAME),
    "washer directly on a bridge": ([(BH, "red", 2, 2)], (W, "blue", 2, 3), None, SAME),
    "washer on the second cell of a bridge-v": ([(BV, "red", 2, 2)], (W, "blue", 3, 2), None, SAME),
    "screw directly on a bridge": ([(BH, "red", 2, 2)], (S, "blue", 2, 2), None, SAME),
    "bridge-h directly on a bridge-h (bridges are exempt)": ([(BH, "red", 2, 2)], (BH, "blue", 2, 2), None, SAME),
    "bridge-v directly on a bridge-v": ([(BV, "red", 2, 2)], (BV, "blue", 2, 2), None, SAME),
    "bridge-h across the second cell of a bridge-h and another bridge-h (object bbb)": (
        [(BH, "red", 2, 2), (BH, "blue", 2, 4)], (BH, "green", 2, 3), None, SAME),
    "bridge-h across a washer and a nut": ([(W, "red", 2, 2), (N, "red", 2, 3)], (BH, "blue", 2, 2), None, SAME),
    "bridge-v across a bridge-h and a washer (bridges are exempt)": ([(BH, "red", 2, 2), (W, "blue", 3, 2)],
                                                                    (BV, "green", 2, 2), None, SAME),
    # dimensions
    "row beyond the board": ([], (W, "red", 8, 3), "dimensions_mismatch", SAME),
    "column beyond the board": ([], (W, "red", 3, 8), "dimensions_mismatch", SAME),
    "negative row (deviation: theirs wraps to the last row)": ([], (W, "red", -1, 3), "dimensions_mismatch", None),
    "negative column (deviation)": ([(W, "red", 3, 7)], (W, "blue", 3, -1), "dimensions_mismatch",
                                    "same_shape_stacking"),
    "bridge-h at a negative column (deviation)": ([], (BH, "red", 2, -1), "dimensions_mismatch", None),
    "bridge-v at a negative row (deviation)": ([], (BV, "red", -1, 2), "dimensions_mismatch", None),
    # full cells, bridges off the board or too high
    "fifth piece in a cell": ([(W, "red", 1, 1), (W, "red", 1, 2), (BH, "blue", 1, 1), (N, "red", 1, 1),
                               (S, "blue", 1, 1)], (N, "red", 1, 1), "value_error", SAME),
    "bridge-h needing a column off the board": ([], (BH, "red", 2, 7), "value_error", SAME),
    "bridge-v needing a row off the board": ([], (BV, "red", 7, 2), "value_error", SAME),
    "bridge on level 3": ([(W, "red", 2, 2), (N, "blue", 2, 2), (W, "red", 2, 3), (N, "blue", 2, 3)],
                          (BH, "green", 2, 2), "bridge_placement", SAME),
    "bridge-v on level 3": ([(W, "red", 2, 2), (N, "blue", 2, 2), (W, "red", 3, 2), (N, "blue", 3, 2)],
                            (BV, "green", 2, 2), "bridge_placement", SAME),
    "bridge-h two levels above a bridge-h is on level 3": ([(BH, "red", 2, 2), (W, "red", 2, 2), (W, "red", 2, 3)],
                                                         (BH, "blue", 2, 2), "bridge_placement", SAME),
    "bridge whose second cell is full (value_error before depth)": (
        [(W, "red", 2, 3), (W, "red", 3, 3), (BV, "blue", 2, 3), (N, "red", 2, 3), (S, "blue", 2, 3)],
        (BH, "green", 2, 2), "value_error", SAME),
    "bridge over cells of different heights": ([(W, "red", 2, 2)], (BH, "blue", 2, 2), "depth_mismatch", SAME),
    "bridge-v over cells of different heights": ([(W, "red", 2, 2)], (BV, "blue", 2, 2), "depth_mismatch", SAME),
    "bridge-v from a bridge-h's second cell to an empty cell": ([(BH, "red", 2, 2)], (BV, "blue", 2, 3),
                                                                "depth_mismatch", SAME),
    # screws
    "washer on a screw": ([(S, "red", 4, 4)], (W, "blue", 4, 4), "not_on_top_of_screw", SAME),
    "screw on a screw": ([(S, "red", 4, 4)], (S, "blue", 4, 4), "not_on_top_of_screw", SAME),
    "bridge on a screw (deviation: theirs places it)": ([(S, "red", 4, 4), (W, "red", 4, 5)],
                                                        (BH, "blue", 4, 4), "not_on_top_of_screw", None),
    "bridge whose second cell holds a screw (deviation)": ([(W, "red", 4, 4), (S, "red", 4, 5)],
                                                           (BH, "blue", 4, 4), "not_on_top_of_screw", None),
    # same shapes
    "washer directly on a washer": ([(W, "red", 5, 5)], (W, "blue", 5, 5), "same_shape_stacking", SAME),
    "nut directly on a nut": ([(N, "red", 5, 5)], (N, "blue", 5, 5), "same_shape_stacking", SAME),
    "washer two levels above a washer": ([(W, "red", 5, 5), (N, "blue", 5, 5)], (W, "green", 5, 5),
                                         "same_shape_at_alternate_levels", SAME),
    "washer two levels above a washer, across a bridge": ([(W, "red", 5, 5), (W, "red", 5, 6), (BH, "blue", 5, 5)],
                                                          (W, "green", 5, 6), "same_shape_at_alternate_levels", SAME),
    "nut two levels above a nut, across a bridge": ([(N, "red", 5, 5), (N, "red", 5, 6), (BH, "blue", 5, 5)],
                                                    (N, "green", 5, 5), "same_shape_at_alternate_levels", SAME),
    # unknown names
    "unknown shape": ([], ("bolt", "red", 1, 1), "key_error", SAME),
    "unknown colour (deviation: theirs stores its first letter)": ([], (W, "purple", 1, 1), "key_error", None),
    "unknown colour black (deviation: theirs reads it back as blue)": ([], (W, "black", 1, 1), "key_error", None),
    "unknown shape and unknown colour": ([], ("bolt", "purple", 1, 1), "key_error", SAME),
}


def _board(before):
    board = Board()
    for p in before:
        put(board, *p)
    return board


@pytest.mark.parametrize("name", list(RULES))
def test_rule(name):
    before, piece, code, _ = RULES[name]
    board = _board(before)
    cells = board.cells()
    if code is None:
        put(board, *piece)
        assert board.puts == len(before) + 1
        assert any(piece[:2] == tuple(stack[-1]) for stack in board.cells().values())
    else:
        with pytest.raises(WorldError) as raised:
            put(board, *piece)
        assert raised.value.code == ErrorCode(code)
        assert board.cells() == cells and board.puts == len(before), "a failed put leaves the board unchanged"


@pytest.mark.parametrize("name", list(RULES))
def test_the_authors_simulator_agrees_except_for_the_documented_deviations(name):
    before, piece, code, theirs = RULES[name]
    board = world_agreement.AuthorsBoard()
    for p in before:
        board.put(*p)
    try:
        board.put(*piece)
        got = None
    except world_agreement.AuthorsError as error:
        got = error.category
    assert got == (code if theirs == SAME else theirs)
    if theirs != SAME:
        assert "deviation" in name or code != got


def test_a_failed_bridge_leaves_the_board_unchanged_theirs_keeps_its_first_half():
    before = [(W, "red", 2, 2)]
    ours = _board(before)
    with pytest.raises(WorldError):
        put(ours, BH, "blue", 2, 2)
    assert ours.cells() == {"2:2": [[W, "red"]]}
    theirs = world_agreement.AuthorsBoard()
    theirs.put(*before[0])
    with pytest.raises(world_agreement.AuthorsError):
        theirs.put(BH, "blue", 2, 2)
    assert theirs.cells() == {"2:2": [[W, "red"], [BH, "blue"]]}


@pytest.mark.parametrize("bad", [("1", 3), (1.0, 3), (True, 3), (None, 3)])
def test_coordinates_must_be_integers(bad):
    with pytest.raises(WorldError) as raised:
        put(Board(), W, "red", *bad)
    assert raised.value.code == ErrorCode.TYPE_ERROR


def test_the_bounds_are_the_boards_own():
    board = Board(10, 12)
    put(board, W, "red", 9, 11)
    for x, y in ((10, 0), (0, 12)):
        with pytest.raises(WorldError) as raised:
            put(board, W, "red", x, y)
        assert raised.value.code == ErrorCode.DIMENSIONS_MISMATCH
    assert board.cells() == {"9:11": [[W, "red"]]}


def test_put_needs_a_board():
    with pytest.raises(WorldError) as raised:
        put({}, W, "red", 1, 1)
    assert raised.value.code == ErrorCode.TYPE_ERROR
