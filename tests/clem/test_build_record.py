"""The library's `build()` and `parse_failure()` make strict UTF-8 JSON records of any text
(issue 32, item 3): a lone surrogate, a control character or a bidi override in the code is
escaped once at the entry (sartco.text.escape, as the game master escapes every answer), so
the record, what ran and what a transcript shows are the same text. Before, the record of a
source with `# \\ud800` could not be written (clemcore's store_json: UnicodeEncodeError)."""
import json

import pytest

from sartco.clem.core.building import build, parse_failure
from sartco.text import escape

GOLD = "put(board, 'washer', 'red', 0, 0)"
TARGET = {"0:0": [["washer", "red"]]}
ODD = ["\ud800", "\udfff\ud800", "\x00", "\x1b[31m", "\u202e", "\x07"]


def written(record) -> dict:
    """The record as clemcore's store_json writes it (ensure_ascii=False, UTF-8), read back strictly."""
    text = json.dumps(record.to_json(), ensure_ascii=False, indent=2)
    return json.loads(text.encode("utf-8").decode("utf-8", errors="strict"))


@pytest.mark.parametrize("odd", ODD)
def test_a_comment_with_odd_characters_is_recorded_and_runs_as_the_gold(odd):
    code = f"{GOLD}\n# {odd} in a comment"
    data = written(build(code, TARGET, turn_codes=[GOLD, f"# {odd}"]))
    assert (data["ok"], data["es"]) == (True, 1)
    assert data["builder_code"] == escape(code) != code and escape(odd) in data["program"]
    assert data["turn_codes"] == [GOLD, escape(f"# {odd}")]


def test_an_odd_colour_is_the_programs_error_with_its_message_escaped():
    data = written(build("put(board, 'nut', '\ud800', 0, 0)", TARGET))
    assert (data["ok"], data["error"]) == (False, "key_error") and "\\ud800" in data["message"]
    assert data["builder_code"] == "put(board, 'nut', '\\ud800', 0, 0)"


def test_a_parse_failure_with_odd_text_is_recorded():
    data = written(parse_failure(TARGET, "no code in \udfff\x00", turn_codes=["x = '\ud800'"]))
    assert data["message"] == "no code in \\udfff\\x00"
    assert data["turn_codes"] == ["x = '\\ud800'"] and data["builder_code"] == "x = '\\ud800'"


def test_an_escaped_answer_is_recorded_as_it_came():
    """What the game hands build() is escaped already: its record does not change."""
    code = escape(f"{GOLD}\n# \ud800 \u202e")
    assert build(code, TARGET) == build(f"{GOLD}\n# \ud800 \u202e", TARGET)
    assert build(code, TARGET).builder_code == code
