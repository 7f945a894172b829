"""The one message a builder gets after a failed attempt (sartco.clem.core.feedback): execution facts
only, never the target; line numbers of the builder's own code; the experiment's attempts."""
import pytest

from feedback_cases import HOSTILE, PARTIAL, TARGET, WRONG, assert_no_target
from sartco.clem.core.building import build
from sartco.clem.core.feedback import feedback_for, feedback_message, max_attempts
from sartco.world.render import grid_text


def test_feedback_reports_execution_facts_only():
    partial = build(PARTIAL, TARGET)
    assert partial.category.startswith("mismatch")
    text = feedback_for(partial, attempts_left=2)
    assert "differs from the target" in text and grid_text(partial.cells) in text and "2 attempts left" in text
    assert_no_target(text)
    failed = build("put(board, 'washer', 'red', 7, 3)\nput(board, 'bridge-h', 'red', 2, 7)", TARGET)
    text = feedback_for(failed, attempts_left=1)
    assert failed.message.startswith("line 3: ")  # of the executed program: init_board is line 1
    assert f"{failed.error}: line 2: {failed.message[len('line 3: '):]}" in text and grid_text(failed.cells) in text
    assert "1 attempt left" in text
    assert_no_target(text)


def test_feedback_does_not_depend_on_the_target():
    other = {"4:4": [["washer", "blue"]]}
    for code in (PARTIAL, WRONG, "put(board, 'nut', 'red', 9, 9)", HOSTILE):
        assert feedback_for(build(code, TARGET)) == feedback_for(build(code, other))


def test_feedback_counts_lines_in_the_builders_code():
    text = feedback_for(build("put(board, 'washer', 'red', 7, 3)\n" + HOSTILE, TARGET))
    assert "forbidden: line 2:" in text  # line 3 of the executed program (after init_board)
    given = "def f(board):\n    put(board, 'nut', 'red', 9, 9)"
    text = feedback_for(build("f(board)", TARGET, given_code=given))
    assert "line 2 of the given code" in text


def test_feedback_for_no_code_and_the_attempts_field():
    text = feedback_message(error="parse_error", message="no code found in the answer", cells={})
    assert "No code was found" in text and "⬜️" not in text
    assert max_attempts({}) == 1 and max_attempts({"attempts": 3}) == 3
    for bad in ({"attempts": 0}, {"attempts": "3"}, {"attempts": True}, {"attempts": -1}):
        with pytest.raises(ValueError, match="must be an integer"):
            max_attempts(dict(bad, name="bad"))
