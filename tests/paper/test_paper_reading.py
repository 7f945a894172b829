"""Each reading rule of the paper-protocol README ("Reading an answer")."""
import pytest

from sartco.paper.reading import read_answer

PUT = "put(board, 'washer', 'red', 7, 3)"
DEF = "def wn(board, colors, x, y):\n    put(board, 'washer', colors[0], x, y)"
USE = "wn(board, ['red'], 7, 3)"


@pytest.mark.parametrize("answer", [
    f"Output\n{PUT}",                                   # the label as in the examples
    f"Output:\n{PUT}",                                  # with a colon: the leading ":" is dropped
    f"Output: {PUT}",
    f"Output:\n```python\n{PUT}\n```",                  # fenced
    f"```\nOutput\n{PUT}\n```",                         # fence around the label
    f"Sure! Here is the code.\nOutput\n```python\n{PUT}\n```",   # prose before the label is cut
    f"  {PUT}  \n",                                     # no label: the whole answer, stripped
    f"```python\n{PUT}\n```",
])
def test_output_reads_to_the_code(answer):
    assert read_answer(answer, "multi_turn") == {"output": PUT}
    assert read_answer(answer, "regular_hai") == {"output": PUT}


def test_prose_after_the_code_stays_in_the_output():
    got = read_answer(f"Output:\n```python\n{PUT}\n```\nThis places the washer.", "regular")
    assert got == {"output": f"{PUT}\n\nThis places the washer."}


def test_the_text_after_the_first_label_is_kept_whole():
    assert read_answer(f"Output\n{PUT}\nOutput\n{PUT}", "multi_turn") == {"output": f"{PUT}\nOutput\n{PUT}"}


def test_only_one_leading_colon_is_dropped():
    assert read_answer(f"Output:: {PUT}", "multi_turn") == {"output": f": {PUT}"}


def test_function_and_usage_labels_without_colons():
    got = read_answer(f"Function\n{DEF}\n\nUsage\n{USE}\n", "single_turn")
    # the function value holds everything after "Function", the usage included ("Usage" removed)
    assert got == {"function": f"{DEF}\n\n\n{USE}", "usage": USE}


def test_function_and_usage_labels_with_colons_and_fences():
    answer = f"Function:\n```python\n{DEF}\n```\nUsage:\n```python\n{USE}\n```"
    got = read_answer(answer, "single_turn_hai")
    # "Usage:" removed and stripped, then the first line ":" (left by "Function:") dropped (no
    # strip after that: the blank line the fence left stays)
    assert got["function"] == f"\n{DEF}\n\n\n\n{USE}"
    # only "Usage" is removed from the usage text: the colon stays
    assert got["usage"] == f":\n\n{USE}"


def test_function_label_with_colon_and_no_usage_keeps_the_colon_line():
    assert read_answer(f"Function:\n{DEF}", "single_turn") == {"function": f":\n{DEF}", "usage": ""}


def test_function_inside_the_function_text_wins_over_the_usage_step():
    answer = f"Function:\n{DEF}\nUsage (Function call):\n{USE}"
    got = read_answer(answer, "single_turn_mg")
    # the text after the first "Function", every further "Function" removed; the Usage step is lost
    assert got["function"] == f":\n{DEF}\nUsage ( call):\n{USE}"
    assert got["usage"] == f"(Function call):\n{USE}"


def test_missing_labels():
    assert read_answer(f"  {DEF}\n{USE}\n", "single_turn") == {"function": f"{DEF}\n{USE}", "usage": ""}
    assert read_answer("no code at all", "multi_turn") == {"output": "no code at all"}
    assert read_answer("", "single_turn_sc") == {"function": "", "usage": ""}


def test_usage_without_function_label():
    got = read_answer(f"{DEF}\nUsage: {USE}  # Usage example", "single_turn")
    assert got["usage"] == f": {USE}  #  example"
    # the whole answer; "Usage:" is removed, so a bare "Usage" elsewhere stays
    assert got["function"] == f"{DEF}\n {USE}  # Usage example"


def test_unknown_variant():
    with pytest.raises(ValueError, match="unknown variant"):
        read_answer(PUT, "single")
