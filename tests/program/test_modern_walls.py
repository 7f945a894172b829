"""What the modern constructs of issue 43 (item 4) hand a program: nothing of the interpreter.

Each construct runs as plain exec runs it (test_honest.py, the modern corpus); here, the walls around it:
enum's machinery, metaclass and real types stay out of reach; abc runs no ABCMeta; a slot's
descriptor is not readable; a `match` class pattern reads a subject's attributes only where
`subject.name` could, and never a method the budgets check only when called; `type()` names
only classes the program could name anyway; the budgets hold inside the new stand-ins. And the
two breakages of Python 3.13 (class bodies, string seeds) stay fixed on every interpreter.
"""
import random

import pytest

from sartco.program import MODULE, PAPER, execute_many
from sartco.world import Board, put

F, R, T, L = "forbidden", "runtime_error", "type_error", "resource_limit"
ENUM = "from enum import Enum, IntEnum\nclass Color(Enum):\n    RED = 'red'\n"
HOSTILE = {
    # enum: the metaclass, enum's machinery (a real type among it), a class body through the functional API
    "an enum's metaclass": (ENUM + "m = Color.__class__", F),
    "type() of an enum": (ENUM + "m = type(Color)", F),
    "an enum's member map": (ENUM + "m = Color._member_map_", F),
    # (a name in one of the program's strings passes the check before running: the rule stops it then)
    "an enum's member type": ("from enum import IntEnum\nclass C(IntEnum):\n    A = 1\nt = C._member_type_ or '_member_type_'", R),
    "an enum's member constructor": (ENUM + "n = Color._new_member_ or '_new_member_'", R),
    "a member's sort order": (ENUM + "n = Color.RED._sort_order_ or '_sort_order_'", R),
    "the metaclass's mro": (ENUM + "n = Color.mro or 'mro'", R),
    "a dunder through the functional API": ("from enum import Enum\nE = Enum('E', [('__getattr__', 1)])", F),
    "a dunder in an enum's body": ("from enum import Enum\nclass E(Enum):\n    __init_subclass__ = 1", F),
    "an enum deriving from a stand-in": ("from enum import Enum\nimport random\nclass E(random.Random, Enum):\n    A = 1", F),
    "an unchecked str method of a str enum": (
        "from enum import Enum\nclass S(str, Enum):\n    A = 'a'\nf = S.A.expandtabs or 'expandtabs'", R),
    "a checked str method of a str enum keeps its budget": (
        "from enum import Enum\nclass S(str, Enum):\n    A = 'a'\nx = S.A.ljust(10 ** 7)", L),
    # abc
    "ABCMeta is not a metaclass to call": ("from abc import ABCMeta\nM = ABCMeta('M', (), {})", T),
    "another metaclass keyword": ("import abc\nclass A(metaclass=abc.ABC):\n    pass", F),
    "abstractmethod on a builtin": ("from abc import abstractmethod\nabstractmethod(len)", F),
    # __slots__
    "a slot's descriptor": ("class P:\n    __slots__ = ('x',)\nd = P.x", F),
    "a __weakref__ slot": ("class P:\n    __slots__ = '__weakref__'", F),
    "slots that are not names": ("class P:\n    __slots__ = 3", F),
    # match
    "a class pattern reading a dunder": ("match 1:\n    case int(__class__=c):\n        pass", F),
    "a class pattern reading an unchecked method": ("match 'a':\n    case str(ljust=f):\n        x = f(10 ** 8)", F),
    "__match_args__ naming a dunder": (
        "class P:\n    __match_args__ = ('__dict__',)\nmatch P():\n    case P(d):\n        pass", F),
    # (a name the rule hides is a pattern that does not match, as a missing attribute)
    "a class pattern on a stand-in": ("import random\nmatch random.Random(1):\n    case random.Random(gauss_next=g):\n"
                                      "        put(board, 'washer', 'red', 0, 0)", "ok"),
    # type(), typing, functools
    "type() making a class": ("C = type('C', (), {'__getattr__': len})", F),
    "type() of a function": ("t = type(put)", F),
    "type() of the board": ("t = type(board)", F),
    "a cache's wrapped function": ("import functools\n@functools.cache\ndef f(x):\n    return x\ng = f.__wrapped__", F),
    "a generic alias's origin": ("from typing import Generic, TypeVar\nT = TypeVar('T')\nclass Q(Generic[T]):\n"
                                 "    pass\no = Q[int].__origin__", F),
    "an abstract base's register": ("import collections.abc\nr = collections.abc.Iterable.register", F),
    "a class deriving from collections.abc": ("import collections.abc\nclass A(collections.abc.Sequence):\n    pass", F),
    # budgets inside the new stand-ins
    "heapq.nlargest of an endless iterator": ("import heapq, itertools\nheapq.nlargest(2, itertools.count())", "timeout"),
}
NAMES = list(HOSTILE)


@pytest.fixture(scope="module")
def outcomes():
    return dict(zip(NAMES, execute_many([code for code, _ in HOSTILE.values()], cache=False)))


@pytest.mark.parametrize("name", NAMES)
def test_modern_constructs_hand_out_nothing_of_the_interpreter(outcomes, name):
    ex = outcomes[name]
    if HOSTILE[name][1] == "ok":
        assert ex.ok and not ex.cells, ex
    else:
        assert (ex.ok, ex.error.value if ex.error else None) == (False, HOSTILE[name][1]), ex.message


def _plain(source: str) -> dict:
    board = Board(8, 8)
    exec(compile(source, "<honest>", "exec", dont_inherit=True), {"__name__": "__main__", "board": board, "put": put})
    return board.cells()


SAME = {  # constructs whose semantics a shortcut could get wrong, against plain exec
    "a property read once by a class pattern": (
        "class P:\n    reads = 0\n    @property\n    def x(self):\n        P.reads += 1\n        return 3\n"
        "match P():\n    case P(x=3):\n        put(board, 'washer', 'red', P.reads, 0)"),
    "a missing attribute makes a class pattern fail": (
        "class P:\n    pass\nmatch P():\n    case P(y=1):\n        put(board, 'nut', 'red', 0, 0)\n"
        "    case P():\n        put(board, 'washer', 'red', 1, 1)"),
    "a value pattern is read when its case is tried": (
        "def f(v):\n    match v:\n        case 0:\n            return 'red'\n        case Later.BLUE:\n            return 'blue'\n"
        "put(board, 'washer', f(0), 0, 0)\nclass Later:\n    BLUE = 1\nput(board, 'washer', f(1), 1, 1)"),
    "self-matching built-ins and subclasses": (
        "from enum import IntEnum\nclass C(IntEnum):\n    A = 3\nfor v in (True, 2, 2.0, 'x', C.A, [1], (1,)):\n"
        "    match v:\n        case bool(b):\n            put(board, 'washer', 'red', 0, int(b))\n"
        "        case C(c):\n            put(board, 'washer', 'red', 1, c.value)\n"
        "        case int(n) | float(n):\n            put(board, 'washer', 'red', 2, int(n) + 3 * isinstance(n, float))\n"
        "        case str(s):\n            put(board, 'washer', 'red', 3, len(s))\n"
        "        case list(l) | tuple(l):\n            put(board, 'washer', 'red', 4, len(l) + isinstance(l, tuple))"),
    "abstract classes as Python makes them": (
        "from abc import ABC, ABCMeta, abstractmethod\nclass A(ABC):\n    @abstractmethod\n    def f(self):\n        pass\n"
        "class B(A):\n    pass\nclass C(B):\n    def f(self):\n        return 2\nclass D(metaclass=ABCMeta):\n"
        "    @property\n    @abstractmethod\n    def g(self):\n        pass\nfor i, k in enumerate([A, B, C, D]):\n"
        "    try:\n        k()\n        put(board, 'washer', 'blue', i, 0)\n    except TypeError as e:\n"
        "        put(board, 'nut', 'red', i, len(str(e)) % 8)\nput(board, 'washer', 'green', 7, int(isinstance(C(), A)))"),
    "enum members, iteration and lookups": (
        "from enum import Enum, Flag, auto\nclass C(Enum):\n    R = 'red'\n    G = 'green'\n    B = 'red'\n"
        "class F(Flag):\n    X = auto()\n    Y = auto()\nput(board, 'washer', C.B.value, len(C), len(C.__members__))\n"
        "put(board, 'washer', C('green').value, int(C['R'] is C.B), int((F.X | F.Y).value))\n"
        "put(board, 'washer', 'blue', 4, len({C.R, C.B, C.G}))\nput(board, 'nut', 'blue', 4, len(repr(C.G)) % 8)"),
    "type() of what a program holds": (
        "class A:\n    def __repr__(self):\n        return type(self).__name__\ntry:\n    {}['k']\nexcept KeyError as e:\n"
        "    n = type(e).__name__\nput(board, 'washer', 'red', len(repr(A())), len(n) % 8)\n"
        "put(board, 'nut', 'red', 1, int(type(3) is int) + int(type('') == str) + int(type(A()) is A))"),
}


@pytest.mark.parametrize("semantics", [MODULE, PAPER])
def test_modern_constructs_match_plain_exec_where_a_shortcut_would_not(semantics):
    names = list(SAME)
    got = execute_many([SAME[n] for n in names], cache=False, semantics=semantics)
    for name, ex in zip(names, got):
        if semantics == PAPER:  # top-level classes are locals there: only check that nothing escapes
            assert ex.error is None or ex.error.value in ("name_error", "ok"), (name, ex.message)
            continue
        assert ex.ok, (name, ex.message)
        assert ex.cells == _plain(SAME[name]), name


def test_the_two_python_313_breakages_stay_fixed():
    """3.13 puts __firstlineno__ and __static_attributes__ in every class body, and imports
    sha512 at the first string seed (a confined child can import nothing): on every interpreter."""
    source = ("import random\nclass P:\n    def __init__(self):\n        self.x = 1\nrandom.seed('sartco')\n"
              "r = random.Random('bench')\nput(board, 'washer', 'red', P().x, random.randint(0, 7))\n"
              "put(board, 'nut', 'blue', 2, r.randint(0, 7))")
    random.seed("sartco")
    a = random.randint(0, 7)
    b = random.Random("bench").randint(0, 7)
    ex = execute_many([source], cache=False)[0]
    assert ex.ok, ex.message
    assert ex.cells == {f"1:{a}": [["washer", "red"]], f"2:{b}": [["nut", "blue"]]}
