"""A corpus of hostile programs: each ends in its expected code, and afterwards the sandbox
still works, nothing outside a temporary folder was touched and no worker process is left.

The assertions are about outcomes, never about durations: the one program that needs the hard
kill (a loop inside C code) gets a 1 s wall-time budget, everything else a generous 20 s.
"""
import os
from pathlib import Path

import pytest

from sartco.program import Limits, execute, shutdown
from sartco.world import ErrorCode

E = ErrorCode
F, T, R = E.FORBIDDEN, E.TIMEOUT, E.RESOURCE_LIMIT
GENEROUS = Limits(wall_time=20.0)
HARD_KILL = Limits(wall_time=1.0)
SMALL_MEMORY = Limits(wall_time=20.0, memory=128 * 1024 * 1024)
CANARY = "CANARY"  # replaced by the canary file's path

HOSTILE = [
    # escapes through attributes and format strings
    ("class via tuple", "().__class__", F, None),
    ("subclasses walk", "[].__class__.__base__.__subclasses__()", F, None),
    ("builtin self", "print.__self__", F, None),
    ("put globals", "put.__globals__['__builtins__']", F, None),
    ("lambda globals", "(lambda: 0).__globals__", F, None),
    ("lambda code", "f = lambda: 0\nc = f.__code__", F, None),
    ("generator frame", "g = (i for i in range(3))\nfr = g.gi_frame", F, None),
    ("generator frame in loop", "g = (i for i in [1])\nfor f in [g.gi_frame]: pass", F, None),
    ("f-string attribute", "x = 1\ns = f'{x.__class__}'", F, None),
    ("str.format walk", "s = '{0.__class__}'.format(1)", F, None),
    ("str.format index", "s = '{0[0]}'.format([1])", F, None),
    ("str.format nested width", "s = '{:{}}'.format(1, 10**9)", F, None),
    ("format() width", "s = format(1, '999999999')", F, None),
    ("str.format on a name", "fmt = '{0.__init__.__globals__}'\nfmt.format(put)", F, None),
    ("printf star width", "s = '%*d' % (10**9, 1)", F, None),
    ("printf width bomb", "s = '%999999999d' % 1", F, None),
    ("f-string width bomb", "s = f'{1:999999999}'", F, None),
    ("f-string dynamic spec", "s = f'{1:{10**9}}'", F, None),
    ("board internals", "board.stacks[0][0].append(('screw', 'red'))", F, None),
    ("attribute store", "board.rows = 100", F, None),
    ("method on a type", "f = str.lower\no = f.__objclass__", F, None),
    # Unicode names, imports, builtins
    ("full-width eval", "ｅｖａｌ('1+1')", F, None),
    ("full-width import", "__ｉｍｐｏｒｔ__('os')", F, None),
    ("full-width keyword", "ｉｍｐｏｒｔ os", E.SYNTAX_ERROR, None),
    ("open file", "f = open('/etc/passwd')", F, None),
    ("write canary", "f = open(CANARY, 'w')", F, None),
    ("import", "import os\nos.system('touch ' + CANARY)", F, None),
    ("from import", "from os import system", F, None),
    ("builtins dict", "__builtins__['eval']('1')", F, None),
    ("dunder import", "__import__('os')", F, None),
    ("getattr", "getattr(board, 'stacks')", F, None),
    ("setattr", "setattr(board, 'rows', 1)", F, None),
    ("type", "t = type(board)", F, None),
    ("object", "o = object()", F, None),
    ("eval", "eval('1')", F, None),
    ("exec", "exec('x = 1')", F, None),
    ("compile", "compile('1', '', 'exec')", F, None),
    ("globals", "g = globals()", F, None),
    ("vars", "v = vars()", F, None),
    ("locals", "v = locals()", F, None),
    ("dunder kwarg", "d = dict(__class__=1)", F, None),
    ("dunder name", "__x = 1", F, None),
    ("rebind put", "def put(*a):\n    pass", F, None),
    ("rebind init_board", "init_board = lambda rows, cols: board", F, None),
    ("rebind via parameter", "def f(put):\n    return put", F, None),
    # statements outside the subset
    ("class metaclass", "class A(metaclass=type):\n    pass", F, None),
    ("class derived from a builtin", "class S(str):\n    pass", F, None),
    ("try swallows timeout", "try:\n    while True:\n        pass\nexcept BaseException:\n    pass", T, None),
    ("finally swallows timeout", "def f():\n    try:\n        while True:\n            pass\n    finally:\n        return 1\nf()",
     T, None),
    ("map swallows timeout", "x = list(map(lambda i: i, iter(int, 1)))", T, None),
    ("try swallows refusal", "try:\n    n = (5).count(1)\nexcept Exception:\n    pass", F, None),
    ("try swallows length", "try:\n    x = [0] * 10**9\nexcept Exception:\n    pass", R, None),
    ("finally swallows length", "def f():\n    try:\n        x = 'a' * 10**9\n    finally:\n        return 1\nf()", R, None),
    # issue 21: a RecursionError swallowed by `finally: return` (or break/continue) ended ok
    ("finally return swallows recursion", "def f():\n    return f()\ndef g():\n    try:\n        f()\n    finally:\n"
     "        return\ng()", R, None),
    ("finally break swallows recursion", "def f():\n    return f()\nwhile True:\n    try:\n        f()\n    finally:\n"
     "        break", R, None),
    ("finally continue swallows recursion", "def f():\n    return f()\nfor i in range(2):\n    try:\n        f()\n"
     "    finally:\n        continue", R, None),
    ("finally return at every depth", "def f():\n    try:\n        return f()\n    finally:\n        return 1\nf()",
     R, None),
    ("exception traceback", "try:\n    1 / 0\nexcept ZeroDivisionError as e:\n    t = e.__traceback__", F, None),
    ("exception method", "try:\n    1 / 0\nexcept ZeroDivisionError as e:\n    t = e.with_traceback(None)", F, None),
    ("with", "with open(CANARY) as f:\n    pass", F, None),
    # issue 32: `with` takes the stand-ins' context managers only, and none swallows a stop
    ("with a program's context manager", "class C:\n    def __enter__(self):\n        return self\n"
     "    def __exit__(self, *a):\n        return True\nwith C():\n    pass", F, None),
    ("suppress swallows timeout", "import contextlib\nwith contextlib.suppress(BaseException):\n    while True:\n"
     "        pass\nput(board, 'washer', 'red', 0, 0)", T, None),
    ("suppress swallows length", "from contextlib import suppress\nwith suppress(Exception):\n    x = [0] * 10**9", R, None),
    ("suppress swallows refusal", "from contextlib import suppress\nwith suppress(Exception):\n    n = (5).count(1)", F, None),
    ("suppress swallows recursion", "from contextlib import suppress\ndef f():\n    return f()\n"
     "with suppress(RuntimeError):\n    f()", R, None),
    ("global", "def f():\n    global put\n    put = 1\nf()", F, None),
    ("refused builtin bound later", "def f():\n    return open(CANARY)\nf()\nopen = 1", F, None),
    ("generator function frame", "def f():\n    yield 1\nfr = f().gi_frame", F, None),
    ("async", "async def f():\n    pass", F, None),
    ("del", "del put", F, None),
    ("raise", "raise SystemExit", F, None),
    ("match reading a dunder", "match 1:\n    case int(__class__=c):\n        pass", F, None),
    ("match reading an unchecked method", "match 'a':\n    case str(ljust=f):\n        f(10 ** 8)", F, None),
    ("decorator", "@getattr\ndef g():\n    pass", F, None),
    # imports: only the stand-ins, and nothing behind them
    ("import os.path", "import os.path", F, None),
    ("import builtins", "import builtins", F, None),
    ("random state", "import random\ns = random.getstate()", F, None),
    ("relative import", "from . import world", F, None),
    ("numpy beyond the stand-in", "import numpy.linalg", F, None),
    ("numpy member", "from numpy import load", F, None),
    ("typing eval", "from typing import get_type_hints", F, None),
    ("namedtuple exec", "from collections import namedtuple\nP = namedtuple('P', ['x=__import__(\"os\")'])",
     E.VALUE_ERROR, None),
    ("module attribute store", "import math\nmath.pi = 3", F, None),
    ("module internals", "import math\nm = math.__dict__", F, None),
    ("module loader", "import math\nm = math.__loader__", F, None),
    ("partial internals", "from functools import partial\np = partial(len)\nf = p.func", F, None),
    ("stand-in module method", "import math\nd = math.sqrt.count(1)", F, None),
    # budgets: time
    ("while true", "while True:\n    pass", T, None),
    ("self-extending list", "L = [1]\nfor x in L:\n    L.append(x)", T, None),
    ("exponential lambda", "f = lambda n: n and f(n - 1) + f(n - 1)\nf(60)", T, None),
    ("comprehension product", "n = [0 for a in range(10**5) for b in range(10**5)]", T, None),
    ("loop in C code", "x = sum(sum(range(10**6)) for i in range(10**6))", T, HARD_KILL),
    # budgets: depth, length, integers, memory, source
    ("deep recursion", "def f(n):\n    return f(n + 1)\nf(0)", R, None),
    ("deep repr", "x = []\nfor i in range(100000):\n    x = [x]\ns = str(x)", R, None),
    ("list bomb", "x = [0] * 10**9", R, None),
    ("string bomb", "x = 'a' * 10**9", R, None),
    ("reversed string bomb", "x = 10**9 * 'a'", R, None),
    ("string doubling", "s = 'a'\nwhile True:\n    s = s + s", R, None),
    ("f-string doubling", "s = 'a'\nwhile True:\n    s = f'{s}{s}'", R, None),
    ("list doubling", "L = [1]\nwhile True:\n    L += L", R, None),
    ("extend doubling", "L = [1]\nwhile True:\n    L.extend(L)", R, None),
    ("starred doubling", "L = [1]\nwhile True:\n    L = [*L, *L]", R, None),
    ("item doubling", "d = {'k': 'a'}\nwhile True:\n    d['k'] *= 2", R, None),
    ("sum of lists", "L = [[0] * 10**6] * 10**6\nx = sum(L, [])", R, None),
    ("star args bomb", "print(*[0] * 10**9)", R, None),
    ("integer tower", "x = 10**10**10", R, None),
    ("integer power", "x = 2**99999999", R, None),
    ("integer shift", "x = 1 << 10**10", R, None),
    ("integer squaring", "x = 3\nwhile True:\n    x = x * x", R, None),
    ("float overflow", "x = 2.0 ** 10**9", R, None),
    ("int() of a long hex string", "x = int('f' * 10**6, 16)", R, None),
    ("int() with base 0", "x = int('0x' + 'f' * 10**6, 0)", R, None),
    ("case mapping growth", "x = ('\ufb03' * 10**6).upper()", R, None),
    ("join bomb", "x = ','.join(['a' * 1000] * 10**4)", R, None),
    ("replace bomb", "x = ('a' * 10**5).replace('a', 'a' * 1000)", R, None),
    ("replace empty bomb", "x = ('a' * 10**5).replace('', 'b' * 100)", R, None),
    ("padding bomb", "x = 'a'.ljust(10**9)", R, None),
    ("zfill bomb", "x = '1'.zfill(10**9)", R, None),
    ("str of shared lists", "x = [[0] * 1000] * 1000\ns = str(x)", R, None),
    ("repr of shared lists", "x = [[0] * 1000] * 1000\ns = repr(x)", R, None),
    ("ascii of shared lists", "x = [['\u00e9'] * 1000] * 1000\ns = ascii(x)", R, None),
    ("f-string repr of shared lists", "x = [[0] * 1000] * 1000\ns = f'{x!r}'", R, None),
    ("printf of a big list", "x = [[0] * 1000] * 1000\ns = '%s' % (x,)", R, None),
    ("format of a big list", "x = [[0] * 1000] * 1000\ns = '{}'.format(x)", R, None),
    ("factorial", "import math\nx = math.factorial(10**6)", R, None),
    ("comb", "from math import comb\nx = comb(10**6, 5 * 10**5)", R, None),
    ("prod", "import math\nx = math.prod([2**60000] * 3)", R, None),
    ("operator.mul squaring", "import operator\nx = 3\nwhile True:\n    x = operator.mul(x, x)", R, None),
    ("pow builtin", "x = pow(3, 10**9)", R, None),
    ("numpy zeros", "import numpy as np\nx = np.zeros((10**5, 10**5))", R, None),
    ("numpy arange", "import numpy as np\nx = np.arange(10**12)", R, None),
    ("huge range", "for i in range(10**12):\n    pass", R, None),
    ("huge range object", "n = len(range(10**30))", R, None),
    ("round bomb", "x = round(1, -10**9)", R, None),
    ("memory bomb", "x = [list(range(10**6)) for i in range(1000)]", R, SMALL_MEMORY),
    ("huge source", "x = 1\n" * 60_000, R, None),
    ("deep nesting", "x = " + "-" * 20_000 + "1", R, None),
    ("nested parentheses", "x = " + "(" * 1000 + ")" * 1000, E.SYNTAX_ERROR, None),
    ("null byte", "x = 1\x00", E.SYNTAX_ERROR, None),
    # a failing program keeps the board built so far
    ("timeout keeps board", "put(board, 'washer', 'red', 0, 0)\nwhile True:\n    pass", T, None),
]


def _children():
    """(pid, state, cmdline) of this process's child processes, from /proc."""
    out = []
    for entry in Path("/proc").iterdir():
        if not entry.name.isdigit():
            continue
        try:
            status = (entry / "status").read_text()
            cmdline = (entry / "cmdline").read_bytes().replace(b"\0", b" ").decode(errors="replace")
        except OSError:
            continue
        fields = dict(line.split(":", 1) for line in status.splitlines() if ":" in line)
        if int(fields.get("PPid", "0").strip()) == os.getpid():
            out.append((int(entry.name), fields.get("State", "").strip()[:1], cmdline))
    return out


@pytest.fixture(scope="module")
def canary(tmp_path_factory):
    folder = tmp_path_factory.mktemp("canary")
    path = folder / "canary.txt"
    path.write_text("untouched")
    return path


@pytest.fixture(scope="module")
def corpus(canary):
    before = (canary.stat().st_mtime_ns, canary.parent.stat().st_mtime_ns, sorted(os.listdir(canary.parent)))
    shutdown()  # start from no workers: execute() then uses exactly one
    results, live = {}, []
    for name, code, expected, limits in HOSTILE:
        results[name] = execute(code.replace("CANARY", repr(str(canary))), limits=limits or GENEROUS)
        live.append(len([c for c in _children() if "sartco.program.child.template" in c[2]]))
    after = (canary.stat().st_mtime_ns, canary.parent.stat().st_mtime_ns, sorted(os.listdir(canary.parent)))
    return results, before, after, live


def test_corpus_is_big_enough():
    assert len(HOSTILE) >= 40
    assert len({name for name, *_ in HOSTILE}) == len(HOSTILE)


@pytest.mark.parametrize("name,code,expected,limits", HOSTILE, ids=[h[0] for h in HOSTILE])
def test_hostile_program_ends_in_expected_code(corpus, name, code, expected, limits):
    ex = corpus[0][name]
    assert (ex.ok, ex.error) == (False, expected), ex.message
    assert ex.message


def test_failed_program_keeps_board_so_far(corpus):
    assert corpus[0]["timeout keeps board"].cells == {"0:0": [["washer", "red"]]}


def test_after_corpus_benign_program_builds_exact_board(corpus):
    ex = execute("board = init_board(8, 8)\nfor c in range(3):\n    put(board, 'washer', 'red', 7, c)\n"
                 "put(board, 'bridge-h', 'blue', 7, 0)")
    assert ex.ok, ex.message
    assert ex.cells == {"7:0": [["washer", "red"], ["bridge-h", "blue"]],
                        "7:1": [["washer", "red"], ["bridge-h", "blue"]],
                        "7:2": [["washer", "red"]]}
    assert ex.puts == 4


def test_after_corpus_nothing_was_touched(corpus, canary):
    _, before, after, _ = corpus
    assert before == after
    assert canary.read_text() == "untouched"


def test_after_corpus_no_process_left_over(corpus):
    _, _, _, live = corpus
    assert max(live) <= 1, "killed workers are reaped and replaced, never piled up"
    assert not [c for c in _children() if c[1] == "Z"], "no zombie children"
    shutdown()
    assert not [c for c in _children() if "sartco.program.child.template" in c[2]]
    assert execute("put(board, 'nut', 'green', 1, 1)").cells == {"1:1": [["nut", "green"]]}  # restarts
    shutdown()
