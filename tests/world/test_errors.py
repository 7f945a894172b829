"""The error vocabulary's families: every code has one, and a recorded category reads back as
its code's family ("success" for a build that equals its target)."""
import pytest

from sartco.world import (MISMATCH_CODES, PYTHON_CODES, SANDBOX_CODES, SUCCESS_CATEGORY, WORLD_CODES, ErrorCode,
                          category_family)

FAMILIES = {"python": PYTHON_CODES, "world": WORLD_CODES, "sandbox": SANDBOX_CODES, "mismatch": MISMATCH_CODES,
            "parse": {ErrorCode.PARSE_ERROR}, "harness": {ErrorCode.HARNESS_ERROR}}


@pytest.mark.parametrize("code", list(ErrorCode))
def test_every_code_has_exactly_one_family(code):
    assert [name for name, codes in FAMILIES.items() if code in codes] == [code.family]


@pytest.mark.parametrize("category, family", [
    (None, "success"), ("", "success"), (SUCCESS_CATEGORY, "success"), ("syntax_error", "python"),
    ("bridge_placement", "world"), ("timeout", "sandbox"), ("mismatch_color", "mismatch"), ("parse_error", "parse"),
    ("harness_error", "harness"),
])
def test_a_recorded_category_reads_back_as_its_family(category, family):
    assert category_family(category) == family


def test_an_unknown_category_is_an_error():
    with pytest.raises(ValueError):
        category_family("sucess")
