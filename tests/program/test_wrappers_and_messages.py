"""Issue 43, items 2 and 3: no stand-in that takes objects or names from a program hands it a
type, a foreign class dict, a descriptor or a module's globals (functools.wraps and
update_wrapper copy plain Python's defaults, and only from the program's own objects); every
message is one line to str.splitlines(), and a message whose __str__ raises (even a
BaseException) still keeps the pieces put before it."""
import pytest
from oracle_helpers import plain_exec

from sartco.program import execute_many
from sartco.text import one_line
from sartco.world import ErrorCode as E

PIECE = "put(board, 'washer', 'red', 0, 0)\n"
PIECE_CELLS = {"0:0": [["washer", "red"]]}

# each program ends `raise ValueError(repr(x))` where x is what it reached: on 188cc2a the
# message named a real type, a descriptor or a stand-in's staticmethod, or the world's globals
# became the program's names
REACHED = {
    "wraps(put) merging __globals__": "import functools\ndef f():\n    pass\n"
        "functools.wraps(put)(f, assigned=(), updated=('__globals__',))\nx = Board",
    "wraps(random.seed) merging __globals__": "import functools, random\ndef f():\n    pass\n"
        "functools.wraps(random.seed)(f, updated=('__globals__',))\nx = SHARED",
    "wraps(int) copying the sandbox int's class dict": "import functools\nNAMES = 'real convert'\n"
        "def f():\n    pass\nfunctools.wraps(int)(f)\nx = f.real",
    "wraps(str): the stand-in's staticmethod": "import functools\nNAMES = 'convert'\ndef f():\n    pass\n"
        "functools.wraps(str)(f)\nx = f.convert",
    "attrgetter after wraps(str)": "import functools, operator\ndef f():\n    pass\n"
        "functools.wraps(str)(f)\nx = operator.attrgetter('real')(f)",
    "methodcaller after wraps(int)": "import functools, operator\ndef f():\n    pass\n"
        "functools.wraps(int)(f)\nx = operator.methodcaller('convert', '7')(f)",
    "wraps(BaseException): a descriptor": "import functools\nNAMES = 'args'\ndef f():\n    pass\n"
        "functools.wraps(BaseException)(f)\nx = f.args",
    "wraps(Counter): its methods": "import functools, collections\nNAMES = 'most_common'\n"
        "def f():\n    pass\nfunctools.wraps(collections.Counter)(f)\nx = f.most_common",
    "wraps(random.Random): its methods": "import functools, random\nNAMES = 'seed'\ndef f():\n    pass\n"
        "functools.wraps(random.Random)(f)\nx = f.seed",
    "wraps(a program class): its dict's descriptors": "import functools\nNAMES = 'm'\n"
        "class P:\n    def m(self):\n        pass\ndef f():\n    pass\nfunctools.wraps(P)(f)\nx = f.m",
    "update_wrapper onto the world's put": "import functools\ndef f():\n    pass\n"
        "functools.update_wrapper(put, f)\nx = put",
}


@pytest.mark.parametrize("name", list(REACHED))
def test_no_wrapper_hands_out_internals(name):
    ex = execute_many([PIECE + REACHED[name] + "\nraise ValueError(repr(x))"], cache=False)[0]
    assert ex.error != E.VALUE_ERROR, ex  # the program never got to show what it reached
    assert ex.error in (E.TYPE_ERROR, E.RUNTIME_ERROR, E.FORBIDDEN, E.NAME_ERROR), ex
    assert ex.cells == PIECE_CELLS


HONEST = {  # (program, the cells plain exec builds)
    "@wraps(f) keeps the name and the function's attributes": (
        "from functools import wraps\ndef f():\n    pass\nf.calls = 3\ndef deco(g):\n    @wraps(g)\n"
        "    def inner(*a):\n        return g(*a)\n    return inner\nh = deco(f)\n"
        "put(board, 'washer', 'red', h.calls, len(h.__name__))", {"3:1": [["washer", "red"]]}),
    "update_wrapper in a class-based decorator": (
        "import functools\nclass Count:\n    def __init__(self, f):\n        functools.update_wrapper(self, f)\n"
        "        self.f = f\n        self.n = 0\n    def __call__(self, *a):\n        self.n += 1\n"
        "        return self.f(*a)\n@Count\ndef place(x):\n    put(board, 'nut', 'blue', x, x)\n"
        "place(2)\nplace(3)\nput(board, 'washer', 'red', place.n, 0)",
        {"2:0": [["washer", "red"]], "2:2": [["nut", "blue"]], "3:3": [["nut", "blue"]]}),
    "wraps of a stand-in keeps its name": (
        "import functools, math\ndef f(x):\n    return int(math.sqrt(x))\nfunctools.wraps(math.sqrt)(f)\n"
        "put(board, 'washer', 'red', len(f.__name__), f(9))", {"4:3": [["washer", "red"]]}),
}


@pytest.mark.parametrize("name", list(HONEST))
def test_honest_wrappers_run_as_plain_exec(name):
    source, cells = HONEST[name]
    assert plain_exec(source) == cells
    ex = execute_many([source], cache=False)[0]
    assert ex.ok and ex.cells == cells, ex


BREAKS = "\n\r\v\f\x1c\x1d\x1e\x85\u2028\u2029"  # every line break of str.splitlines()


def test_one_line_leaves_no_line_break():
    text = "".join(f"a{c}" for c in BREAKS) + "\r\nz\t"
    assert len(text.splitlines()) > 10
    assert len(one_line(text).splitlines()) == 1
    assert one_line(one_line(text)) == one_line(text)
    assert "\\u2028" in one_line(text) and "\\u2029" in one_line(text)


def test_messages_are_one_line():
    programs = [PIECE + f"raise ValueError('a' + chr({ord(c)}) + 'b')" for c in BREAKS]
    programs.append(PIECE + "import typing, functools\ndef f():\n    pass\n"
                    "functools.wraps(typing.TypeVar('T\\u2028x'))(f)\nraise ValueError(f.__name__)")
    programs.append(PIECE + "d = {}\nd['k\\u2029'] = 1\nd['j']")
    for ex in execute_many(programs, cache=False):
        assert not ex.ok and ex.cells == PIECE_CELLS, ex
        assert len(ex.message.splitlines()) == 1 and ex.message.isprintable(), ex


@pytest.mark.parametrize("raised", ["BaseException('x')", "E()", "ValueError('x')", "B()"])
def test_a_message_whose_str_raises_keeps_the_pieces(raised):
    source = (f"class B(BaseException):\n    pass\nclass E(Exception):\n    def __str__(self):\n"
              f"        raise {raised}\n{PIECE}raise E()")
    ex = execute_many([source], cache=False)[0]
    assert (ex.error, ex.message, ex.cells, ex.puts) == (E.RUNTIME_ERROR, "line 7: E", PIECE_CELLS, 1), ex
