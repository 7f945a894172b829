"""The honest constructs of issue 21 (item 5) and issue 32 (item 6) run as plain `exec` runs them.

Each program is one construct models write: classes (methods, properties, static and class
methods, inheritance, dunder methods, `__rmul__ = __mul__`), dataclasses (frozen ones in a set,
unsafe_hash, a plain one unhashable, slots and kw_only, fields()), namedtuples, generators
(StopIteration.value), the main guard, seeded random, `from __future__ import annotations`,
functools.wraps, attributes on the program's own functions, contextlib.suppress,
chain.from_iterable, unbound methods of built-in types, and numpy arrays used for coordinates
(ndenumerate, nonzero). The oracle is plain
`exec` of the same text as a script (`__name__ == "__main__"`) with the real modules (numpy,
random) and a reference `put` that takes numpy's integers as the authors' simulator did (it
indexed a numpy board with them); the sandbox must give ok and exactly the same cells.
"""
import pytest
from oracle_helpers import plain_exec

from sartco.program import execute_many
from sartco.world import Board, put

CONSTRUCTS = {
    "class with methods": (
        "class Stacker:\n    def __init__(self, board, x, y):\n        self.board = board\n        self.x, self.y = x, y\n"
        "        self.count = 0\n    def add(self, shape, color):\n        put(self.board, shape, color, self.x, self.y)\n"
        "        self.count += 1\n        return self\ns = Stacker(board, 2, 3)\ns.add('washer', 'red').add('nut', 'blue')\n"
        "put(board, 'screw', 'green', s.count, s.count)"),
    "property, staticmethod, classmethod": (
        "class Cell:\n    made = 0\n    def __init__(self, x, y):\n        self._x = x\n        self.y = y\n        Cell.made += 1\n"
        "    @property\n    def x(self):\n        return self._x\n    @x.setter\n    def x(self, value):\n        self._x = value % 8\n"
        "    @staticmethod\n    def color(i):\n        return ['red', 'blue'][i % 2]\n    @classmethod\n    def origin(cls):\n"
        "        return cls(0, 0)\nc = Cell.origin()\nc.x = 9\nput(board, 'washer', Cell.color(c.x), c.x, c.y)\n"
        "put(board, 'nut', 'yellow', Cell.made, Cell(5, 5).y)"),
    "inheritance and super": (
        "class Piece:\n    def __init__(self, shape, color):\n        self.shape, self.color = shape, color\n"
        "    def place(self, b, x, y):\n        put(b, self.shape, self.color, x, y)\nclass Washer(Piece):\n"
        "    def __init__(self, color):\n        super().__init__('washer', color)\nclass Nut(Piece):\n"
        "    def place(self, b, x, y):\n        super().place(b, x, y + 1)\nfor i, p in enumerate([Washer('red'), Nut('nut', 'blue')]):\n"
        "    p.place(board, i, i)\nput(board, 'screw', 'red', 6, int(isinstance(Washer('x'), Piece)))"),
    "object base, class constants, del of an attribute": (
        "class Layout(object):\n    ROWS = 8\n    COLORS = ('red', 'blue')\n    def __init__(self):\n        self.temp = 1\n"
        "        self.placed = []\nlay = Layout()\ndel lay.temp\ntry:\n    t = lay.temp\nexcept AttributeError:\n"
        "    t = 3\nfor i, c in enumerate(Layout.COLORS):\n    put(board, 'washer', c, lay.ROWS - 1, i + t)\n    lay.placed.append(i)\n"
        "put(board, 'nut', 'green', len(lay.placed), 0)"),
    "class name in repr": (
        "class Piece:\n    def __init__(self, shape):\n        self.shape = shape\n    def __repr__(self):\n"
        "        return f'{self.__class__.__name__}({self.shape!r})'\n    def twin(self):\n        return self.__class__(self.shape)\n"
        "p = Piece('nut').twin()\nput(board, p.shape, 'red', len(repr(p)) % 8, len(Piece.__qualname__))"),
    "private names": (
        "class Grid:\n    __size = 8\n    def __init__(self):\n        self.__cells = []\n    def __check(self, x):\n"
        "        return 0 <= x < self.__size\n    def add(self, x, y):\n        if self.__check(x):\n            self.__cells.append((x, y))\n"
        "    def cells(self):\n        return [c for c in self.__cells]\ng = Grid()\ng.add(2, 2)\ng.add(9, 1)\nfor x, y in g.cells():\n"
        "    put(board, 'washer', 'red', x, y)\nput(board, 'nut', 'blue', 3, len(g._Grid__cells))"),
    "dunder methods": (
        "class Pos:\n    def __init__(self, x, y):\n        self.x, self.y = x, y\n    def __add__(self, other):\n"
        "        return Pos(self.x + other.x, self.y + other.y)\n    def __eq__(self, other):\n        return (self.x, self.y) == (other.x, other.y)\n"
        "    def __hash__(self):\n        return hash((self.x, self.y))\n    def __iter__(self):\n        yield self.x\n        yield self.y\n"
        "    def __repr__(self):\n        return f'Pos({self.x}, {self.y})'\n    def __lt__(self, other):\n        return (self.x, self.y) < (other.x, other.y)\n"
        "cells = {Pos(1, 1), Pos(1, 1), Pos(0, 2) + Pos(1, 0)}\nfor p in sorted(cells):\n    put(board, 'washer', 'red', *p)\n"
        "put(board, 'nut', 'blue', len(repr(Pos(1, 2))) - 6, 0)"),
    "container class": (
        "class Row:\n    def __init__(self, colors):\n        self.colors = list(colors)\n    def __len__(self):\n        return len(self.colors)\n"
        "    def __getitem__(self, i):\n        return self.colors[i]\n    def __contains__(self, c):\n        return c in self.colors\n"
        "r = Row(['red', 'green', 'blue'])\nfor y in range(len(r)):\n    put(board, 'washer', r[y], 4, y)\nif 'green' in r:\n"
        "    put(board, 'nut', r[-1], 4, 0)"),
    "exception class": (
        "class Full(ValueError):\n    pass\ndef place(x, y):\n    if x > 6:\n        raise Full(f'row {x}')\n    put(board, 'washer', 'red', x, y)\n"
        "for x in range(9):\n    try:\n        place(x, 1)\n    except Full as e:\n        put(board, 'nut', 'blue', 0, len(e.args))\n        break"),
    "dataclass": (
        "from dataclasses import dataclass, field\nfrom typing import List\n@dataclass\nclass Part:\n    shape: str\n    color: str\n"
        "    cells: List[tuple] = field(default_factory=list)\n    level: int = 0\np = Part('washer', 'yellow', [(1, 2), (2, 1)])\n"
        "q = Part('washer', 'yellow', [(1, 2), (2, 1)])\nfor x, y in p.cells:\n    put(board, p.shape, p.color, x, y)\n"
        "if p == q:\n    put(board, 'screw', 'red', 7, len(repr(p)) % 8)"),
    "frozen ordered dataclass": (
        "from dataclasses import dataclass\n@dataclass(frozen=True, order=True)\nclass P:\n    x: int\n    y: int\n"
        "    def moved(self, dx):\n        return P(self.x + dx, self.y)\npts = sorted([P(3, 1), P(1, 2), P(1, 1)])\n"
        "for p in pts + [pts[0].moved(4)]:\n    put(board, 'nut', 'green', p.x, p.y)\ntry:\n    pts[0].x = 5\nexcept AttributeError:\n"
        "    put(board, 'washer', 'red', 0, 0)"),
    "future annotations": (
        "from __future__ import annotations\nfrom dataclasses import dataclass\n@dataclass\nclass Node:\n    x: int\n    nxt: Node | None = None\n"
        "def walk(n: Node) -> list[int]:\n    out = []\n    while n is not None:\n        out.append(n.x)\n        n = n.nxt\n    return out\n"
        "for i, x in enumerate(walk(Node(1, Node(3, Node(5))))):\n    put(board, 'washer', 'blue', x, i)"),
    "namedtuple": (
        "from collections import namedtuple\nPiece = namedtuple('Piece', ['shape', 'color', 'x', 'y'])\nP2 = namedtuple('P2', 'x y', defaults=[0])\n"
        "ps = [Piece('washer', 'red', 1, 1), Piece(shape='nut', color='blue', x=1, y=1)]\nfor p in ps:\n    put(board, *p)\n"
        "q = ps[0]._replace(x=5)\nput(board, q.shape, q.color, q.x, q.y)\nput(board, 'screw', 'green', *P2(6))\n"
        "put(board, 'washer', 'yellow', len(q._asdict()), len(repr(q)) % 8)"),
    "typing NamedTuple": (
        "from typing import NamedTuple\nclass Spot(NamedTuple):\n    x: int\n    y: int = 4\n    def right(self):\n"
        "        return Spot(self.x, self.y + 1)\ns = Spot(2)\nput(board, 'washer', 'red', *s)\nput(board, 'nut', 'blue', *s.right())\n"
        "put(board, 'screw', 'green', s[0] + 3, len(str(s)) % 8)"),
    "generators": (
        "def diagonal(n):\n    for i in range(n):\n        yield i, i\ndef both(n):\n    yield from diagonal(n)\n    yield from ((i, 7 - i) for i in range(n))\n"
        "for x, y in both(3):\n    put(board, 'washer', 'red', x, y)\ng = diagonal(5)\nnext(g)\nput(board, 'nut', 'blue', *next(g))"),
    "generator with return and send": (
        "def counter():\n    total = 0\n    while True:\n        got = yield total\n        if got is None:\n            return\n        total += got\n"
        "c = counter()\nnext(c)\nc.send(2)\nx = c.send(3)\nput(board, 'washer', 'green', x, x)"),
    "main guard": (
        "def build(b):\n    put(b, 'washer', 'red', 3, 3)\n    return b\ndef main():\n    global board\n    board = build(board)\n"
        "if __name__ == '__main__':\n    main()"),
    "seeded random module": (
        "import random\nrandom.seed(42)\ncolors = ['red', 'blue', 'green', 'yellow']\nrandom.shuffle(colors)\n"
        "for i, c in enumerate(colors):\n    put(board, 'washer', c, i, random.randint(0, 7))\n"
        "put(board, 'nut', random.choice(colors), 5, int(random.random() * 8))\nfor x, y in random.sample([(6, i) for i in range(8)], 3):\n"
        "    put(board, 'screw', 'red', x, y)\nput(board, 'washer', 'blue', 7, random.randrange(0, 8, 2))"),
    "seeded random instances": (
        "from random import Random\nr = Random(7)\ns = Random('sartco')\nfor i in range(3):\n    put(board, 'washer', r.choice(['red', 'blue']), i, r.randint(0, 7))\n"
        "put(board, 'nut', 'green', 5, int(s.uniform(0, 8)))\nput(board, 'screw', 'yellow', *r.choices(range(8), k=2))"),
    "functools.total_ordering": (
        "from functools import total_ordering\n@total_ordering\nclass V:\n    def __init__(self, n):\n        self.n = n\n"
        "    def __eq__(self, o):\n        return self.n == o.n\n    def __lt__(self, o):\n        return self.n < o.n\n"
        "vs = [V(3), V(1), V(2)]\nfor i, v in enumerate(sorted(vs, reverse=True)):\n    if v >= V(2):\n        put(board, 'nut', 'red', i, v.n)"),
    "functools.wraps": (
        "from functools import wraps\ndef logged(f):\n    @wraps(f)\n    def inner(*args):\n        return f(*args)\n    return inner\n"
        "@logged\ndef place(x, y):\n    put(board, 'washer', 'red', x, y)\nplace(1, 2)"),
    "chain.from_iterable, unbound methods": (
        "import itertools\nrows = [[(0, 0), (0, 1)], [(1, 0)]]\nfor x, y in itertools.chain.from_iterable(rows):\n"
        "    put(board, 'washer', 'red', x, y)\nnames = list(map(str.lower, ['BLUE', 'Green']))\nfor i, c in enumerate(names):\n"
        "    put(board, 'nut', c, 3, i)\nseen = dict.fromkeys(['red', 'red', 'yellow'])\nfor i, c in enumerate(seen):\n"
        "    put(board, 'screw', c, 5, i)\nwords = list(map(str.upper, ['a'])) + list(map(str.strip, [' x ']))\n"
        "put(board, 'washer', 'blue', len(words), len(''.join(words)))"),
    "numpy scaling and arithmetic": (
        "import numpy as np\ncells = np.array([0, 1, 2]) * 2\nfor y in cells:\n    put(board, 'washer', 'red', 1, y)\n"
        "shifted = np.array([[1, 1], [2, 2]]) + np.array([1, 3])\nfor x, y in shifted:\n    put(board, 'nut', 'blue', x, y)\n"
        "a = (np.arange(8) + 3) // 2 % 4\nput(board, 'screw', 'green', a[5], a[-1])\nput(board, 'washer', 'yellow', *(2 * np.array((3, 3)) - 1))"),
    "numpy grid": (
        "import numpy as np\ngrid = np.zeros((8, 8), dtype=int)\ngrid[2, 3] = 1\ngrid[5, :] = 2\ngrid[0:2, 6] = 3\n"
        "rows, cols = grid.shape\nfor x, y in np.ndindex(rows, cols):\n    if grid[x, y] == 1:\n        put(board, 'washer', 'red', x, y)\n"
        "    elif grid[x][y] == 3:\n        put(board, 'nut', 'blue', x, y)\nput(board, 'screw', 'green', grid.ndim, int(grid.sum()) % 8)\n"
        "put(board, 'washer', 'yellow', len(grid) - 1, grid.max())"),
    "numpy where, shapes, views": (
        "import numpy as np\nm = np.arange(16).reshape(4, 4)\nxs, ys = np.where(m % 5 == 0)\nfor x, y in zip(xs, ys):\n"
        "    put(board, 'washer', 'red', x, y)\nt = m.T\nput(board, 'nut', 'blue', t[1, 0] % 8, t[0, 1])\nflat = m.flatten().tolist()\n"
        "put(board, 'screw', 'green', flat[-1] % 8, len(flat) % 8)\nsel = np.where(m > 12, m - 10, 0)\nput(board, 'washer', 'yellow', sel.max(), np.sum(sel) % 8)\n"
        "put(board, 'nut', 'red', *(m[1:3, 2] % 8))\nput(board, 'washer', 'blue', int(m[m > 13][0]) % 8, np.min(m) + 6)"),
    "numpy views": (
        "import numpy as np\ngrid = np.zeros((8, 8), dtype=int)\ngrid[2][3] = 1\nrow = grid[4]\nrow[1:3] = 5\ngrid.T[0, 6] = 7\n"
        "grid[grid == 5] = 2\ncol = grid[:, 1]\ncol[7] = 9\nfor x, y in zip(*np.where(grid > 0)):\n"
        "    put(board, 'washer', 'red', x, y)\nvals = [int(v) for v in grid.flatten() if v]\n"
        "put(board, 'nut', 'blue', 6, len(vals))\nput(board, 'nut', 'yellow', 5, sum(vals) % 8)\n"
        "flat = grid.reshape(-1)\nflat[63] = 1\nput(board, 'screw', 'green', 7, int(grid[7, 7]))"),
    "numpy meshgrid, argwhere, unique, concatenate": (
        "import numpy as np\nX, Y = np.meshgrid(np.arange(3), np.arange(2))\nfor x, y in zip(X.flatten(), Y.flatten()):\n"
        "    put(board, 'washer', 'red', x, y)\nI, J = np.meshgrid([5, 6], [1, 2, 3], indexing='ij')\nfor x, y in zip(I.ravel(), J.ravel()):\n"
        "    put(board, 'nut', 'blue', x, y)\nm = np.zeros_like(np.ones((8, 8), dtype=int))\nm[7, 5] = 1\nfor x, y in np.argwhere(m):\n"
        "    put(board, 'screw', 'green', x, y)\nu = np.unique([4, 1, 4, 2])\nc = np.concatenate([u, np.array([7])])\n"
        "for y in c:\n    put(board, 'washer', 'yellow', 3, y)"),
    "numpy linspace and ones": (
        "import numpy as np\nys = np.linspace(0, 7, 4).astype(int)\nfor y in ys:\n    put(board, 'washer', 'green', 6, y)\n"
        "o = np.ones(3, dtype=int) * 4\nput(board, 'nut', 'red', o[0], int(o.sum()) % 8)\nprint(np.array([1, 2]) == np.array([1, 3]))"),
    # issue 32, item 6
    "frozen dataclass in a set": (
        "from dataclasses import dataclass\n@dataclass(frozen=True)\nclass P:\n    x: int\n    y: int\n"
        "seen = {P(1, 2), P(1, 2), P(3, 4)}\nfor p in sorted(seen, key=lambda p: (p.x, p.y)):\n"
        "    put(board, 'washer', 'red', p.x, p.y)\nput(board, 'nut', 'blue', len(seen), int(P(3, 4) in seen))"),
    "dataclass unsafe_hash": (
        "from dataclasses import dataclass\n@dataclass(unsafe_hash=True)\nclass P:\n    x: int\n    y: int\n"
        "colors = {P(1, 2): 'red', P(5, 5): 'blue'}\ncolors[P(1, 2)] = 'green'\nfor p, c in colors.items():\n"
        "    put(board, 'washer', c, p.x, p.y)\nput(board, 'nut', 'red', len(colors), int(hash(P(0, 1)) == hash(P(0, 1))))"),
    "plain dataclass is unhashable": (
        "from dataclasses import dataclass\n@dataclass\nclass P:\n    x: int\n@dataclass(eq=False)\nclass Q:\n    x: int\n"
        "try:\n    s = {P(1)}\nexcept TypeError as e:\n    put(board, 'washer', 'red', 0, len(str(e)) % 8)\n"
        "put(board, 'nut', 'blue', 1, len({Q(1), Q(1)}))\nput(board, 'screw', 'green', 2, int(P.__hash__ is None))"),
    "dataclass slots and kw_only": (
        "from dataclasses import dataclass, field\n@dataclass(slots=True, kw_only=True)\nclass P:\n    x: int\n    y: int = 3\n"
        "    tags: list = field(default_factory=list)\np = P(x=2)\np.tags.append('red')\nput(board, 'washer', p.tags[0], p.x, p.y)\n"
        "try:\n    P(1, 2)\nexcept TypeError:\n    put(board, 'nut', 'blue', 0, 0)\ntry:\n    p.z = 1\nexcept AttributeError:\n"
        "    put(board, 'nut', 'green', 0, 1)\nput(board, 'screw', 'red', 0, 2 + int(P(x=1) == P(x=1)))"),
    "dataclasses.fields": (
        "import dataclasses\nfrom dataclasses import dataclass, field, fields\n@dataclass\nclass Piece:\n    shape: str\n"
        "    color: str = 'red'\n    cells: list = field(default_factory=list)\np = Piece('washer')\n"
        "for i, f in enumerate(fields(p)):\n    put(board, p.shape, p.color, i, len(f.name))\n"
        "names = [f.name for f in fields(Piece) if f.default is dataclasses.MISSING]\n"
        "put(board, 'nut', 'blue', 4, len(names))\nput(board, 'nut', 'green', 5, int(fields(Piece)[1].default == 'red'))"),
    "__rmul__ = __mul__ in a class body": (
        "class V:\n    def __init__(self, x, y):\n        self.x, self.y = x, y\n    def __mul__(self, k):\n"
        "        return V(self.x * k, self.y * k)\n    __rmul__ = __mul__\n    def __add__(self, o):\n"
        "        return V(self.x + o.x, self.y + o.y)\n    __radd__ = __add__\n    __hash__ = None\n"
        "for v in [2 * V(1, 2), V(3, 1) * 2, V(1, 1) + V(0, 2)]:\n    put(board, 'washer', 'red', v.x, v.y)"),
    "StopIteration.value": (
        "def walk(n):\n    for i in range(n):\n        yield i\n    return n * 2\nit = walk(2)\nwhile True:\n    try:\n"
        "        y = next(it)\n    except StopIteration as stop:\n        put(board, 'nut', 'blue', stop.value, len(stop.args))\n"
        "        break\n    put(board, 'washer', 'red', 0, y)"),
    "np.ndenumerate and np.nonzero": (
        "import numpy as np\ngrid = np.zeros((8, 8), dtype=int)\ngrid[1, 2] = 1\ngrid[6, 0] = 2\n"
        "for (x, y), v in np.ndenumerate(grid):\n    if v:\n        put(board, 'washer', ['red', 'blue'][v - 1], x, y)\n"
        "xs, ys = np.nonzero(grid)\nfor x, y in zip(xs, ys):\n    put(board, 'nut', 'green', x, y)\n"
        "for i in np.nonzero([0, 3, 0, 4])[0]:\n    put(board, 'screw', 'yellow', 5, i)\n"
        "for i, v in np.ndenumerate([7, 6]):\n    put(board, 'washer', 'yellow', v, i[0])"),
    "attributes on the program's functions": (
        "from functools import wraps\ndef counted(f):\n    @wraps(f)\n    def wrapper(*args):\n        wrapper.calls += 1\n"
        "        return f(*args)\n    wrapper.calls = 0\n    return wrapper\n@counted\ndef place(x, y):\n"
        "    put(board, 'washer', 'red', x, y)\nplace(1, 1)\nplace(2, 2)\nput(board, 'nut', 'blue', place.calls, 0)\n"
        "step = lambda: 0\nstep.size = 3\ndel step.size\ntry:\n    s = step.size\nexcept AttributeError:\n"
        "    put(board, 'screw', 'green', 5, len(place.__name__))"),
    "contextlib.suppress and nullcontext": (
        "import contextlib\nfrom contextlib import nullcontext, suppress\nplaced = {}\nwith contextlib.suppress(KeyError, IndexError):\n"
        "    put(board, 'washer', 'red', 0, 0)\n    placed['x']\n    put(board, 'washer', 'red', 1, 0)\n"
        "with suppress(ValueError) as nothing, nullcontext(board) as b:\n    put(b, 'nut', 'blue', 2, int(nothing is None))\n"
        "try:\n    with suppress(KeyError):\n        [][1]\nexcept IndexError:\n    put(board, 'screw', 'green', 3, 3)"),
}
NAMES = list(CONSTRUCTS)


@pytest.fixture(scope="module")
def sandboxed():
    return dict(zip(NAMES, execute_many(list(CONSTRUCTS.values()), cache=False)))


@pytest.mark.parametrize("name", NAMES)
def test_construct_builds_what_plain_exec_builds(sandboxed, name):
    expected = plain_exec(CONSTRUCTS[name])
    assert expected, "every program places something"
    ex = sandboxed[name]
    assert ex.ok, f"{ex.error}: {ex.message}"
    assert ex.cells == expected


UNSEEDED = ("import random\nfor i in range(4):\n    put(board, 'washer', random.choice(['red', 'blue']), i, random.randint(0, 7))\n"
            "r = random.Random()\nput(board, 'nut', 'green', 7, r.randint(0, 7))")


def test_unseeded_random_is_seeded_with_zero_in_every_worker():
    """Our choice: unseeded random is deterministic, CPython's sequence for seed 0."""
    runs = [execute_many([UNSEEDED] * 3, cache=False, workers=2) for _ in range(2)]
    seeded = UNSEEDED.replace("import random\n", "import random\nrandom.seed(0)\n").replace("Random()", "Random(0)")
    expected = plain_exec(seeded)
    assert all(ex.ok and ex.cells == expected for run in runs for ex in run)


ORDER_SENSITIVE = ("class Spot:\n    def __init__(self, y):\n        self.y = y\nspots = {Spot(y) for y in range(8)}\n"
                   "for x, s in enumerate(spots):\n    put(board, 'washer', 'red', x, s.y)")


def test_sets_of_program_objects_iterate_alike_in_every_worker():
    """Objects without __hash__ hash by the order they were first hashed, not by address."""
    runs = [ex.cells for _ in range(3) for ex in execute_many([ORDER_SENSITIVE] * 4, cache=False, workers=2)]
    assert runs[0] == {f"{x}:{x}": [["washer", "red"]] for x in range(8)}
    assert all(cells == runs[0] for cells in runs)


def test_namespace_names_the_module():
    """One function makes every program's globals; the paper protocol passes another name."""
    from sartco.program.child.runtime import namespace
    board = Board(8, 8)
    assert namespace(board, None)["__name__"] == "__main__"
    ns = namespace(board, None, name="scorer")
    assert (ns["__name__"], ns["board"], ns["put"]) == ("scorer", board, put)


def test_random_state_does_not_leak_between_programs():
    first = "import random\nrandom.seed(3)\nx = random.random()\nput(board, 'washer', 'red', 0, 0)"
    second = "import random\nput(board, 'washer', 'red', random.randint(0, 7), 0)"
    runs = execute_many([first, second, second], cache=False, workers=1)
    assert runs[1].cells == runs[2].cells == plain_exec("import random\nrandom.seed(0)\n" + second.split("\n", 1)[1])


@pytest.mark.parametrize("source,words", [
    ("import numpy as np\nx = np.fft.fft([1, 2])", "numpy's fft is not available in the sandbox"),
    ("import numpy.random", "numpy's random is not available in the sandbox"),
    ("import random\ns = random.getstate()", "random's getstate is not available in the sandbox"),
    ("class A(str):\n    pass", "may derive only from the program's own classes"),
    ("class A:\n    def __getattr__(self, n):\n        return 1", "names starting with two underscores"),
])
def test_what_stays_refused_says_what_and_why(source, words):
    ex = execute_many([source], cache=False)[0]
    assert ex.error is not None and ex.error.value == "forbidden" and words in ex.message, ex.message
