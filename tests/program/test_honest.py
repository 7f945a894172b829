"""The sandbox's contract: a program that plain `exec` with `board`, `put` and `init_board` runs
correctly, and that reaches nothing outside the task's world, builds the same board here.

Each program below is ordinary Python of the kinds models write (imports of harmless modules,
exceptions, annotations, set literals, str/list/dict/set methods, formatting, map/filter,
del, global/nonlocal, `_` names, decorators, ...). The oracle is plain `exec` in this test
process with the real builtins and the real modules (numpy included) and sartco.world's `put`;
the sandbox must give the same verdict (ok) and exactly the same cells.
"""
import pytest

from sartco.program import execute_many
from sartco.world import Board, put

HONEST = [
    # imports
    "import math\nfor i in range(3):\n    put(board, 'washer', 'red', int(math.sqrt(49)), i)",
    "import math\nput(board, 'nut', 'blue', math.floor(7.9), math.ceil(2.1))",
    "from math import pi, cos, sin\nx = round(3 + 3 * cos(pi))\ny = round(3 + 3 * sin(pi / 2))\nput(board, 'screw', 'green', x, y)",
    "from itertools import product\nfor x, y in product(range(2), range(3)):\n    put(board, 'washer', 'yellow', x, y)",
    "import itertools\nfor x, y in itertools.combinations(range(4), 2):\n    put(board, 'nut', 'red', x, y)",
    "from itertools import chain, islice\nfor y in islice(chain([1, 2], [5, 6]), 3):\n    put(board, 'washer', 'blue', 0, y)",
    "from itertools import permutations\ncells = list(permutations(range(3), 2))\nfor x, y in cells[:4]:\n    put(board, 'screw', 'red', x, y)",
    "from itertools import zip_longest\nfor x, y in zip_longest([1, 2, 3], [4, 5], fillvalue=0):\n    put(board, 'nut', 'green', x, y)",
    "from itertools import accumulate\nfor y in accumulate([1, 1, 2]):\n    put(board, 'washer', 'green', 5, y)",
    "from functools import reduce\ntotal = reduce(lambda a, b: a + b, [1, 2, 3])\nput(board, 'nut', 'yellow', total, total)",
    "from functools import partial\nred_washer = partial(put, board, 'washer', 'red')\nred_washer(1, 1)\nred_washer(2, 2)",
    "from functools import lru_cache\n@lru_cache(maxsize=None)\ndef col(i):\n    return (i * 3) % 8\nfor i in range(4):\n    put(board, 'nut', 'blue', i, col(i))",
    "import functools\n@functools.cache\ndef fib(n):\n    return n if n < 2 else fib(n - 1) + fib(n - 2)\nput(board, 'washer', 'red', fib(5), fib(4))",
    "from typing import List, Tuple\ndef place(board, cells: List[Tuple[int, int]]) -> None:\n    for x, y in cells:\n        put(board, 'washer', 'red', x, y)\nplace(board, [(0, 0), (1, 1)])",
    "from typing import Dict, Optional\ndef build(board, colors: Dict[str, str], row: Optional[int] = None):\n    r = 7 if row is None else row\n    put(board, 'washer', colors['base'], r, 0)\n    put(board, 'nut', colors['top'], r, 0)\n    return board\nboard = build(board, {'base': 'red', 'top': 'blue'})",
    "import typing\ndef f(x: typing.Any) -> typing.Union[int, None]:\n    return x\nput(board, 'screw', 'yellow', f(3), f(4))",
    "import numpy as np\ndef place_object(board: np.ndarray, x: int, y: int) -> np.ndarray:\n    put(board, 'washer', 'red', x, y)\n    put(board, 'nut', 'blue', x, y)\n    return board\nboard = place_object(board, 7, 3)",
    "import numpy as np\nput(board, 'washer', 'green', int(np.sqrt(16)), int(np.floor(2.5)))",
    "import numpy as np\nfrom typing import List\ndef row(board: np.ndarray, colors: List[str], x: int) -> None:\n    for y, c in enumerate(colors):\n        put(board, 'washer', c, x, y)\nrow(board, ['red', 'blue'], 2)",
    "from collections import defaultdict\nby_row = defaultdict(list)\nfor x, y in [(1, 1), (1, 2), (3, 3)]:\n    by_row[x].append(y)\nfor x, ys in by_row.items():\n    for y in ys:\n        put(board, 'nut', 'red', x, y)",
    "from collections import Counter\nc = Counter(['red', 'red', 'blue'])\nfor i, (color, n) in enumerate(c.most_common()):\n    put(board, 'washer', color, i, n)",
    "from collections import deque\nq = deque([(0, 0), (0, 1)])\nq.appendleft((5, 5))\nwhile q:\n    x, y = q.popleft()\n    put(board, 'screw', 'blue', x, y)",
    "import copy\ncells = [[0, 1], [2, 3]]\nmore = copy.deepcopy(cells)\nmore[0][0] = 4\nmore[1][1] = 5\nfor x, y in cells + more:\n    put(board, 'washer', 'yellow', x, y)",
    "import string\nletters = string.ascii_uppercase[:3]\nfor i, ch in enumerate(letters):\n    put(board, 'nut', 'green', i, ord(ch) - ord('A') + 2)",
    "import operator\ncells = sorted([(3, 1), (1, 2), (2, 0)], key=operator.itemgetter(1))\nfor x, y in cells:\n    put(board, 'washer', 'red', x, y)",
    "from math import *\nput(board, 'washer', 'blue', floor(sqrt(9)), gcd(12, 8))",
    "import math as m, itertools as it\nfor x, y in it.product(range(m.isqrt(4)), repeat=2):\n    put(board, 'nut', 'yellow', x, y)",
    # underscore names
    "for _ in range(1):\n    put(board, 'washer', 'red', 0, 0)",
    "def _helper(b, x, y):\n    put(b, 'nut', 'blue', x, y)\n_helper(board, 3, 3)",
    "_cells = [(1, 2), (2, 1)]\nfor _x, _y in _cells:\n    put(board, 'screw', 'green', _x, _y)",
    "_, y = (9, 4)\nput(board, 'washer', 'yellow', 4, y)",
    # exceptions
    "try:\n    put(board, 'washer', 'red', 9, 9)\nexcept Exception:\n    put(board, 'washer', 'red', 7, 7)",
    "try:\n    put(board, 'washer', 'purple', 0, 0)\nexcept Exception as e:\n    msg = str(e)\n    put(board, 'washer', 'red', 0, 0)",
    "def safe_put(b, *args):\n    try:\n        put(b, *args)\n        return True\n    except Exception:\n        return False\nsafe_put(board, 'screw', 'red', 1, 1)\nsafe_put(board, 'nut', 'red', 1, 1)\nsafe_put(board, 'nut', 'blue', 2, 2)",
    "def check(x):\n    if not 0 <= x < 8:\n        raise ValueError(f'bad coordinate {x}')\n    return x\ntry:\n    check(10)\nexcept ValueError:\n    put(board, 'nut', 'green', check(4), check(5))",
    "try:\n    d = {}\n    d['missing']\nexcept KeyError:\n    put(board, 'washer', 'blue', 2, 3)\nfinally:\n    put(board, 'nut', 'red', 2, 3)",
    "try:\n    x = 1 / 0\nexcept ZeroDivisionError:\n    x = 0\nelse:\n    x = 5\nput(board, 'washer', 'green', x, x)",
    "try:\n    v = int('abc')\nexcept (ValueError, TypeError):\n    v = 6\nput(board, 'screw', 'yellow', v, 1)",
    "items = [1, 2]\ntry:\n    items[5]\nexcept IndexError:\n    pass\nput(board, 'washer', 'red', len(items), 0)",
    "def f():\n    raise RuntimeError('stop')\ntry:\n    f()\nexcept RuntimeError as err:\n    put(board, 'nut', 'yellow', 6, len(str(err)))",
    "x = 3\nassert 0 <= x < 8, 'x out of range'\nput(board, 'washer', 'red', x, x)",
    "def place(b, x, y):\n    assert isinstance(x, int) and isinstance(y, int)\n    put(b, 'washer', 'blue', x, y)\nplace(board, 1, 6)",
    "try:\n    raise KeyError('k')\nexcept LookupError:\n    put(board, 'screw', 'green', 5, 5)",
    "it = iter([3, 4])\nnext(it)\ntry:\n    next(it)\n    next(it)\nexcept StopIteration:\n    put(board, 'washer', 'yellow', 3, 4)",
    # annotated assignments
    "x: int = 2\ny: int = 5\nput(board, 'washer', 'red', x, y)",
    "colors: list[str] = ['red', 'blue']\nposition: tuple[int, int] = (6, 1)\nfor c in colors:\n    put(board, 'washer' if c == 'red' else 'nut', c, *position)",
    "count: int\ncount = 3\nfor i in range(count):\n    put(board, 'nut', 'green', i, 7)",
    "def make(board: 'Board', shape: str = 'washer') -> 'Board':\n    put(board, shape, 'red', 0, 5)\n    return board\nboard = make(board)",
    # set literals and set methods
    "cells = {(0, 0), (1, 1), (0, 0)}\nfor x, y in sorted(cells):\n    put(board, 'washer', 'red', x, y)",
    "used = set()\nused.add((2, 2))\nused.update({(3, 3), (4, 4)})\nused.discard((4, 4))\nfor x, y in sorted(used):\n    put(board, 'nut', 'blue', x, y)",
    "a = {1, 2, 3}\nb = {2, 3, 4}\nfor y in sorted(a & b | {7}):\n    put(board, 'screw', 'red', 0, y)\nfor y in sorted(a.union(b) - a.intersection(b)):\n    put(board, 'washer', 'green', 1, y)",
    "rows = {r for r in range(4) if r % 2 == 0}\nfor r in sorted(rows):\n    put(board, 'washer', 'yellow', r, 3)",
    "s = frozenset({5, 6})\nif s.issubset({5, 6, 7}):\n    for y in sorted(s):\n        put(board, 'nut', 'red', 7, y)",
    # str methods
    "spec = 'washer:red:7:3'\nshape, color, x, y = spec.split(':')\nput(board, shape, color, int(x), int(y))",
    "names = ['Washer', ' NUT ']\nput(board, names[0].lower(), 'red', 0, 0)\nput(board, names[1].strip().lower(), 'blue', 0, 0)",
    "s = 'bridge_h'\nput(board, s.replace('_', '-'), 'yellow', 2, 5)",
    "shape = 'washer'\nif shape.startswith('wash') and shape.endswith('er'):\n    put(board, shape, 'green', 3, 3)",
    "color = ' '.join(['red'])\nput(board, 'washer', color, 1, 1)",
    "line = 'red,blue,green'\nfor i, c in enumerate(line.split(',')):\n    put(board, 'nut', c.upper().lower(), i, i + 1)",
    "label = 'WASHER'\nput(board, label.casefold(), 'blue', 4, 0)\nput(board, 'nut', 'RED'.title().lower(), 4, 0)",
    "text = 'row 7 col 3'\nparts = text.partition(' col ')\nput(board, 'screw', 'yellow', int(parts[0].removeprefix('row ')), int(parts[2]))",
    "name = 'nut'\nif name.isalpha() and '5'.isdigit() and name.find('u') == 1:\n    put(board, name, 'red', 5, int('5'))",
    "key = 'r3'\nput(board, 'washer', 'green', int(key[1:].zfill(2)), len(key.center(5)) - 4)",
    # list and dict methods
    "cells = [(3, 1), (1, 2), (2, 0)]\ncells.sort()\ncells.reverse()\nfor x, y in cells:\n    put(board, 'washer', 'red', x, y)",
    "todo = [(0, 0), (0, 1), (0, 2)]\ntodo.remove((0, 1))\nfirst = todo.copy()\ntodo.clear()\nfor x, y in first:\n    put(board, 'nut', 'blue', x, y)",
    "plan = {'washer': 'red'}\nplan.update({'nut': 'blue'})\nplan.setdefault('screw', 'green')\nfor i, (shape, color) in enumerate(plan.items()):\n    put(board, shape, color, i, i)",
    "d = dict(a=1, b=2)\nx = d.pop('a')\ny = d.get('c', 4)\nput(board, 'washer', 'yellow', x, y)",
    "stack = []\nstack.append(('washer', 'red'))\nstack.insert(0, ('nut', 'blue'))\nfor shape, color in reversed(stack):\n    put(board, shape, color, 6, 6)",
    "cols = list(range(5))\ncols.extend([6, 7])\nfor y in cols[::3]:\n    put(board, 'washer', 'green', 2, y)",
    # formatting
    "label = '{}-{}'.format('washer', 'red')\nshape, color = label.split('-')\nput(board, shape, color, 0, 7)",
    "s = '{shape}|{color}|{x:d}'.format(shape='nut', color='blue', x=4)\nshape, color, x = s.split('|')\nput(board, shape, color, int(x), 4)",
    "s = '%s %s %d' % ('washer', 'red', 3)\nshape, color, x = s.split()\nput(board, shape, color, int(x), 2)",
    "s = '%(shape)s' % {'shape': 'screw'}\nput(board, s, 'yellow', 1, 1)",
    "code = f'{3:02d}'\nw = 4\npadded = f'{code:>{w}}'\nput(board, 'washer', 'red', int(code), len(padded))",
    "x = 2.5\nput(board, 'nut', 'green', int(f'{x:.0f}'), int(format(4.2, '.0f')))",
    "shape = 'washer'\nmsg = f'{shape!r} at {(1, 2)}'\nput(board, shape, 'blue', len(msg) % 8, 2)",
    "n = 5\nput(board, 'washer', 'red', int(f'{n:b}', 2), int('{:o}'.format(6), 8))",
    "print(f'placing {1}')\nput(board, 'washer', 'red', 1, 1)\nprint('done', 'ok', sep='-')",
    # builtins
    "coords = list(map(int, ['1', '2', '3']))\nfor c in coords:\n    put(board, 'washer', 'yellow', c, c)",
    "ys = list(filter(lambda y: y % 2 == 0, range(8)))\nfor y in ys:\n    put(board, 'nut', 'red', 0, y)",
    "xs = [float(v) for v in ['1.0', '2.0']]\nfor x in xs:\n    put(board, 'screw', 'blue', int(x), 5)",
    "sizes = {'a': 2, 'b': 3}\nif all(isinstance(v, int) for v in sizes.values()):\n    put(board, 'washer', 'green', max(sizes.values()), min(sizes.values()))",
    "x, y = divmod(19, 8)\nput(board, 'nut', 'yellow', x, y)\nput(board, 'screw', 'red', pow(2, 2), abs(-1))",
    "cells = [(i, chr(ord('a') + i)) for i in range(3)]\nfor i, ch in cells:\n    put(board, 'washer', 'red', i, ord(ch) - 97 + 4)",
    "sum = 0\nfor v in [1, 2]:\n    sum += v\nmax = 5\nput(board, 'washer', 'blue', sum, max)",
    "list = [3, 4]\ntype = 'nut'\nobject = 'washer'\nput(board, object, 'red', list[0], list[1])\nput(board, type, 'blue', list[0], list[1])",
    "id = 2\ninput = 'red'\nput(board, 'screw', input, id, id)",
    # del, global, nonlocal
    "cells = [(0, 0), (1, 1), (2, 2)]\ndel cells[1]\nd = {'x': 1}\ndel d['x']\nfor x, y in cells:\n    put(board, 'washer', 'red', x, y)",
    "tmp = 5\ndel tmp\nput(board, 'nut', 'green', 5, 5)",
    "count = 0\ndef place(x, y):\n    global count\n    put(board, 'washer', 'blue', x, y)\n    count += 1\nplace(0, 1)\nplace(1, 0)\nput(board, 'nut', 'red', count, count)",
    "def make_counter():\n    n = 0\n    def step():\n        nonlocal n\n        n += 1\n        return n\n    return step\nnext_col = make_counter()\nfor _ in range(3):\n    put(board, 'washer', 'yellow', 3, next_col())",
    "def build():\n    global board\n    board = init_board(8, 8)\n    put(board, 'screw', 'red', 7, 7)\nbuild()",
    # decorators, lambdas, comprehensions, while, walrus
    "def twice(f):\n    def g(*args):\n        f(*args)\n        f(args[0] + 1, args[1])\n    return g\n@twice\ndef place(x, y):\n    put(board, 'nut', 'blue', x, y)\nplace(2, 2)",
    "i = 0\nwhile (j := i * 2) < 6:\n    put(board, 'washer', 'red', i, j)\n    i += 1",
    "grid = {(x, y): 'red' if (x + y) % 2 else 'blue' for x in range(2) for y in range(2)}\nfor (x, y), c in grid.items():\n    put(board, 'washer', c, x, y)",
    "board = init_board(8, 8)\nplace = lambda x, y, c='red': put(board, 'washer', c, x, y)\nplace(4, 4)\nplace(4, 5, c='green')",
    "def bridge(b, x, y, color='yellow', *, vertical=False):\n    put(b, 'bridge-v' if vertical else 'bridge-h', color, x, y)\nput(board, 'washer', 'red', 0, 0)\nput(board, 'washer', 'red', 0, 1)\nbridge(board, 0, 0)\nbridge(board, 3, 3, vertical=True)",
    "def build(board, *pieces, **opts):\n    for shape, color in pieces:\n        put(board, shape, color, opts['x'], opts['y'])\nbuild(board, ('washer', 'red'), ('nut', 'blue'), x=5, y=2)",
    "cells = [(x, y) for x in range(8) for y in range(8) if x == y][:3]\nfor x, y in cells:\n    put(board, 'screw', 'green', x, y)",
    "stack = [('washer', 'red'), ('nut', 'blue'), ('screw', 'yellow')]\nfor shape, color in stack:\n    put(board, shape, color, 3, 4)",
    "big = [0] * 1000\nfor i, v in enumerate(big[:3]):\n    put(board, 'washer', 'red', i, v)",
    "for i in range(8):\n    if i % 2:\n        continue\n    if i > 5:\n        break\n    put(board, 'nut', 'yellow', i, 7 - i)\nelse:\n    pass",
]


def _plain_exec(source: str) -> dict:
    """The oracle: plain exec with the real builtins and modules and sartco.world."""
    last = [Board(8, 8)]

    def init_board(rows=8, cols=8):
        last[0] = Board(rows, cols)
        return last[0]

    env = {"board": last[0], "put": put, "init_board": init_board}
    exec(compile(source, "<honest>", "exec"), env)
    result = env.get("board")
    return (result if type(result) is Board else last[0]).cells()


def test_corpus_is_big_enough():
    assert len(HONEST) >= 80
    assert len(set(HONEST)) == len(HONEST)


@pytest.fixture(scope="module")
def sandboxed():
    return execute_many(HONEST, cache=False)


@pytest.mark.parametrize("k", range(len(HONEST)))
def test_honest_program_builds_what_plain_exec_builds(sandboxed, k):
    expected = _plain_exec(HONEST[k])
    assert expected, "every program of the corpus places something"
    ex = sandboxed[k]
    assert ex.ok, f"{ex.error}: {ex.message}\n{HONEST[k]}"
    assert ex.cells == expected
