"""The json stand-in (the authors' namespace bound `json`; `import json` works too): plain data
as json does it, nothing handed to program functions from inside the encoder, and output
counted against the length budget before it is made."""
import json

import pytest

from sartco.program import PAPER, execute
from sartco.world import ErrorCode

E = ErrorCode


@pytest.mark.parametrize("value", ['[1, "a", null, true, 2.5]', '{"b": [1, {"c": "d"}], "a": 1}', '"x"'])
def test_dumps_and_loads_as_json_does(value):
    program = (f"import json\nv = json.loads({value!r})\ns = json.dumps(v, sort_keys=True, indent=2)\n"
               f"assert s == {json.dumps(json.loads(value), sort_keys=True, indent=2)!r}, s\n"
               "put(board, 'washer', 'red', 0, len(s) % 8)")
    ex = execute(program)
    assert ex.ok, ex.message


def test_output_is_counted_before_it_is_made():
    """1,000 x 1,000 x 1,000 shared items would be gigabytes of text: refused at once."""
    ex = execute("a = [1] * 1000\nb = [a] * 1000\nc = [b] * 1000\njson.dumps(c)", semantics=PAPER)
    assert ex.error == E.RESOURCE_LIMIT and "longer than the limit" in ex.message


@pytest.mark.parametrize("program, code, text", [
    ("a = []\na.append(a)\njson.dumps(a)", E.VALUE_ERROR, "Circular reference detected"),
    ("json.dumps(board)", E.TYPE_ERROR, "Object of type Board is not JSON serializable"),
    ("json.dumps(board, default=lambda o: 1)", E.TYPE_ERROR, "unexpected keyword argument 'default'"),
    ("json.loads('[1]', object_hook=print)", E.TYPE_ERROR, "unexpected keyword argument 'object_hook'"),
    ("json.loads('[1,')", E.VALUE_ERROR, "JSONDecodeError"),
])
def test_what_json_refuses_is_a_clear_verdict(program, code, text):
    ex = execute(program, semantics=PAPER)
    assert ex.error == code and text in ex.message, ex.message
