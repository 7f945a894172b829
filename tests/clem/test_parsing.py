"""parse_code on answers as models really write them."""
import pytest

from sartco.clem.core.errors import ParseError
from sartco.clem.core.parsing import parse_code
from sartco.world import ErrorCode

PUT = "put(board, 'washer', 'red', 7, 3)"
FUNCTION = ("def wn(board, colors, x, y):\n"
            "    shapes = ['washer', 'nut']\n"
            "    for shape, color, dx, dy in zip(shapes, colors, [0, 0], [0, 0]):\n"
            "            put(board, shape, color, x + dx, y + dy)")
USAGE = "wn(board, ('red', 'blue'), 7, 3)"
LOOP = "for row in range(8):\n    for col in [0, 3, 6]:\n        bw(board, colors=['red', 'yellow'],x=row, y=col)"

CASES = {
    "bare put": (PUT, PUT),
    "output label": (f"Output: {PUT}", PUT),
    "bold output label": (f"**Output:**\n{PUT}", PUT),
    "fenced python": (f"```python\n{PUT}\n```", PUT),
    "fenced no language": (f"```\n{PUT}\n```", PUT),
    "prose around fence": (f"Sure! Here is the code:\n\n```python\n{PUT}\n```\n\nThis places the red washer.", PUT),
    "prose around bare code": (f"To build it, we place a washer.\n{PUT}\nThat is all.", PUT),
    "unclosed fence (token limit)": (f"```python\n{FUNCTION}\n{USAGE}", f"{FUNCTION}\n{USAGE}"),
    "function and usage labels": (f"Function:\n{FUNCTION}\nUsage:\n{USAGE}", f"{FUNCTION}\n{USAGE}"),
    "two fenced blocks": (f"The function:\n```python\n{FUNCTION}\n```\nUse it like this:\n```python\n{USAGE}\n```",
                          f"{FUNCTION}\n{USAGE}"),
    "repeated instruction tail": (f"Output: {PUT}\nInstruction: place a blue nut on top of it\n"
                                  "Output: put(board, 'nut', 'blue', 7, 3)\nInstruction: place", PUT),
    "tail after fenced code": (f"```python\n{LOOP}\n```\n\nInstruction: Fill every row\nOutput:\n```python\nfoo()\n```", LOOP),
    "echoed instruction first": (f"Instruction: place a red washer in the 8th row\nOutput: {PUT}", PUT),
    "inline backticks": (f"`{PUT}`", PUT),
    "indented loop in prose": (f"Here you go:\n{LOOP}\nEach row gets three objects.", LOOP),
    "windows line ends": (f"Output:\r\n{FUNCTION}\r\n{USAGE}\r\n".replace("\n", "\r\n").replace("\r\r", "\r"),
                          f"{FUNCTION}\n{USAGE}"),
    "board init kept": (f"board = init_board(8, 8)\n{PUT}", f"board = init_board(8, 8)\n{PUT}"),
    "multi-line call": ("put(board,\n    'washer', 'red',\n    7, 3)", "put(board,\n    'washer', 'red',\n    7, 3)"),
    "comment inside code": (f"# the washer\n{PUT}", f"# the washer\n{PUT}"),
}


@pytest.mark.parametrize("answer, expected", CASES.values(), ids=CASES.keys())
def test_finds_the_code(answer, expected):
    assert parse_code(answer) == expected


@pytest.mark.parametrize("answer", [
    "", "   \n  ", "I am not sure how to build this.",
    "Place a red washer in the 8th row, 4th column. Then place a blue nut on top of it.",
    "Instruction: place a red washer\n",
    "Sorry, I cannot help with that request.",
])
def test_no_code_is_a_parse_error(answer):
    with pytest.raises(ParseError) as info:
        parse_code(answer)
    assert info.value.code is ErrorCode.PARSE_ERROR


def test_parse_error_is_clemcores():
    from clemcore.clemgame.errors import ParseError as ClemParseError
    assert issubclass(ParseError, ClemParseError)


def test_broken_code_is_not_a_parse_error():
    # found but not compilable: executed and lost as syntax_error, not aborted
    assert parse_code("```python\nput(board, 'washer', 'red', 7, 3\n```") == "put(board, 'washer', 'red', 7, 3"


# Answer styles real models use (issue 16: a local OpenAI-compatible stub server answering like
# chat models do): each is read as the code inside it deserves.
GRID = "Row 8, Col 4: red washer, blue nut\nRow 3, Col 6: yellow bridge-h"
CALL = "wn(board, ('red', 'blue'), 7, 3)"
STYLES = {
    # only the Python blocks are code; an explanation or the expected board in another block is not
    "python block + text block": (f"```python\n{PUT}\n```\nThe board afterwards:\n```text\n{GRID}\n```", PUT),
    "python block + json block": (f"```python\n{PUT}\n```\n```json\n{{\"7:3\": [[\"washer\", \"red\"]]}}\n```", PUT),
    "text block first": (f"Expected:\n```text\n{GRID}\n```\nCode:\n```python\n{PUT}\n```", PUT),
    "untagged code + untagged grid": (f"```\n{PUT}\n```\nResult:\n```\n{GRID}\n```", PUT),
    "py tag, capitalised": (f"```Python\n{FUNCTION}\n```\n```py\n{USAGE}\n```", f"{FUNCTION}\n{USAGE}"),
    "the same block repeated as the final answer": (f"```python\n{PUT}\n```\nFinal answer:\n```python\n{PUT}\n```", PUT),
    "untagged broken code is still code": ("```\nput(board, 'washer', 'red', 7, 3\n```",
                                           "put(board, 'washer', 'red', 7, 3"),
    # the usage line written outside the fence, beside its fenced function
    "usage label after the fence": (f"Function:\n```python\n{FUNCTION}\n```\nUsage: {USAGE}", f"{FUNCTION}\n{USAGE}"),
    "usage on its own line after the fence": (f"```python\n{FUNCTION}\n```\n**Usage:**\n{USAGE}\n",
                                              f"{FUNCTION}\n{USAGE}"),
    "inline usage after the fence": (f"```python\n{FUNCTION}\n```\nThen call it as `{USAGE}`.", f"{FUNCTION}\n{USAGE}"),
    "bare usage after the fence": (f"```python\n{FUNCTION}\n```\n\n{USAGE}", f"{FUNCTION}\n{USAGE}"),
    "usage before the fence goes after it": (f"Usage: {USAGE}\n```python\n{FUNCTION}\n```", f"{FUNCTION}\n{USAGE}"),
    "usage inside and repeated outside: once": (f"```python\n{FUNCTION}\n{USAGE}\n```\nUsage: `{USAGE}`",
                                                f"{FUNCTION}\n{USAGE}"),
    "signature in prose is not a usage": (f"```python\n{FUNCTION}\n```\nThe function `wn(board, colors, x, y)` "
                                          f"places a washer and a nut.\nUsage: `{USAGE}`", f"{FUNCTION}\n{USAGE}"),
    "outside call of another function is prose": (f"```python\n{FUNCTION}\n```\nYou could also `{PUT}`.", FUNCTION),
    # inline code when there is no block
    "bold label + inline code": (f"**Output:** `{PUT}`", PUT),
    "inline code in a sentence": (f"Place it with `{PUT}` and then `{CALL}`.", f"{PUT}\n{CALL}"),
    "inline code per bullet": (f"- `{PUT}`\n- `put(board, 'nut', 'blue', 7, 3)`",
                               f"{PUT}\nput(board, 'nut', 'blue', 7, 3)"),
}


@pytest.mark.parametrize("answer, expected", STYLES.values(), ids=STYLES.keys())
def test_answer_styles(answer, expected):
    assert parse_code(answer) == expected


@pytest.mark.parametrize("answer", [
    f"```text\n{GRID}\n```",                        # another language's block is never code
    "```json\n{\"puts\": 3}\n```\nThat is the plan.",
    f"```\n{GRID}\n```",                            # an untagged block with nothing like Python
    "Use the `put` function for each piece.",       # an inline name is not a statement
])
def test_blocks_without_python_are_no_code(answer):
    with pytest.raises(ParseError):
        parse_code(answer)


# Comments inside a fence are code comments; labels are read outside fences or on a line of prose
# (issue 21: a `# Usage:` comment dropped the function above it, a correct answer scored name_error;
# `# Code: build bn` turned "build bn" into code).
BN = "def bn(board, colors, x, y):\n    put(board, 'bridge-v', colors[0], x, y)\n    put(board, 'nut', colors[1], x, y)"
BN_CALL = "bn(board, ['green', 'red'], 4, 3)"
COMMENTS = {
    "usage comment in the fence": (f"```python\n{BN}\n\n# Usage:\n{BN_CALL}\n```", f"{BN}\n\n# Usage:\n{BN_CALL}"),
    "code comment in the fence": (f"```python\n{BN}\n# Code: build bn\n{BN_CALL}\n```", f"{BN}\n# Code: build bn\n{BN_CALL}"),
    "heading-like comment in the fence": (f"```python\n### Function:\n{BN}\n{BN_CALL}\n```", f"### Function:\n{BN}\n{BN_CALL}"),
    "usage comment after unfenced code": (f"{BN}\n# Usage:\n{BN_CALL}", f"{BN}\n# Usage:\n{BN_CALL}"),
    "prose label first in a fence still a label": (f"```\nOutput:\n{PUT}\n```", PUT),
    "prose label with prose rest in a fence": (f"```python\nCode: build bn\n{BN_CALL}\n```", BN_CALL),
    # outside fences a heading before code is a label; after code it reads as the comment it may be (same program)
    "markdown heading labels outside fences": (f"### Function:\n{BN}\n### Usage:\n{BN_CALL}",
                                               f"{BN}\n### Usage:\n{BN_CALL}"),
    "markdown heading labels between prose": (f"### Function:\n{BN}\n\nThen:\n### Usage:\n{BN_CALL}",
                                              f"{BN}\n{BN_CALL}"),
}


@pytest.mark.parametrize("answer, expected", COMMENTS.values(), ids=COMMENTS.keys())
def test_comments_in_code_are_not_labels(answer, expected):
    assert parse_code(answer) == expected


def test_a_usage_comment_keeps_a_correct_answer_correct():
    from sartco.program import execute
    code = parse_code(f"```python\n{BN}\n\n# Usage:\n{BN_CALL}\n```")
    result = execute(code)
    assert result.ok and result.puts == 2, result.message
