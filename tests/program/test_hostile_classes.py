"""Hostile programs against the surface that classes, generators, records, random and numpy
arrays opened (issue 21, item 5): each ends in the expected verdict, never `ok` with anything
reached, and the board holds only what `put` placed."""
import pytest

from sartco.program import Limits, execute_many
from sartco.world import ErrorCode as E

F, T, R, X = E.FORBIDDEN, E.TIMEOUT, E.RESOURCE_LIMIT, E.RUNTIME_ERROR
SOME_PIECE = "put(board, 'washer', 'red', 0, 0)\n"

HOSTILE = {
    # class machinery that changes how Python treats an object
    "__init_subclass__": ("class A:\n    def __init_subclass__(cls):\n        pass", F),
    "metaclass keyword": ("class A(metaclass=type):\n    pass", F),
    "metaclass from a program class": ("class M:\n    pass\nclass A(metaclass=M):\n    pass", F),
    "__getattribute__": ("class A:\n    def __getattribute__(self, n):\n        return 1", F),
    "__getattr__": ("class A:\n    def __getattr__(self, n):\n        return 1", F),
    "__setattr__": ("class A:\n    def __setattr__(self, n, v):\n        pass", F),
    "__del__": ("class A:\n    def __del__(self):\n        put(board, 'screw', 'red', 1, 1)\na = A()\ndel a", F),
    "descriptor __get__": ("class D:\n    def __get__(self, obj, owner):\n        return 1", F),
    "descriptor __set_name__": ("class D:\n    def __set_name__(self, owner, name):\n        pass", F),
    "__reduce__": ("class A:\n    def __reduce__(self):\n        return (print, ())", F),
    "__deepcopy__": ("class A:\n    def __deepcopy__(self, memo):\n        return memo", F),
    "__index__": ("class I:\n    def __index__(self):\n        return 0\nput(board, 'washer', 'red', I(), 0)", F),
    "__class_getitem__": ("class A:\n    def __class_getitem__(cls, k):\n        return k", F),
    "__new__": ("class A:\n    def __new__(cls):\n        return board", F),
    "a __dict__ slot": ("class A:\n    __slots__ = ('__dict__',)", F),
    "dunder assigned in the body": ("class A:\n    __init_subclass__ = print", F),
    "definable dunder bound outside a class body": ("__eq__ = lambda a, b: True", F),
    "definable dunder bound in a method": ("class A:\n    def f(self):\n        __eq__ = 1\n        return __eq__", F),
    "definable dunder bound by a for in a class body": ("class A:\n    for __eq__ in [print]:\n        pass", F),
    "dunder method set later": ("class A:\n    pass\nA.__getattr__ = lambda s, n: 1", F),
    "private name where nothing mangles it": ("class _:\n    def f(self):\n        return self.__dict\n_().f()", F),
    "private name outside a class": ("def f(o):\n    return o.__dict\nf(board)", F),
    "nested def named like a dunder": ("def __init__(self):\n    pass", F),
    "base from a builtin type": ("class S(str):\n    def __eq__(self, o):\n        return True", F),
    "base from the board's type": ("class B(type(board)):\n    pass", F),
    "base from a stand-in type": ("import collections\nclass D(collections.defaultdict):\n    pass", F),
    "base from a function": ("class A(print):\n    pass", F),
    # reading what is behind an object
    "type() of a class: its metaclass": ("class A:\n    pass\nt = type(A)", F),
    "type() making a class": ("t = type('A', (), {})", F),
    "__class__ of an instance, then its dict": ("class A:\n    pass\nc = A().__class__.__dict__", F),
    "metaclass through __class__": ("class A:\n    pass\nM = A.__class__\nB = M('B', (str,), {})", F),
    "metaclass through an instance's class": ("class A:\n    pass\nM = A().__class__.__class__", F),
    "__class__ of a builtin object": ("c = (1).__class__", F),
    "__globals__ of a function": ("def f():\n    pass\nn = f.__globals__", F),
    "__code__ of a function": ("def f():\n    pass\nn = f.__code__", F),
    "__name__ of a builtin function": ("n = len.__name__", F),
    "__dict__ of an instance": ("class A:\n    pass\nd = A().__dict__", F),
    "__dict__ of a class": ("class A:\n    pass\nd = A.__dict__", F),
    "mro of a class": ("mro = 1\nclass A:\n    pass\nm = A.mro()", X),
    "__class__ cell": ("class A:\n    def f(self):\n        return __class__", F),
    "method __self__": ("class A:\n    def f(self):\n        pass\ns = A().f.__self__", F),
    "method __func__ globals": ("class A:\n    def f(self):\n        pass\ng = A.f.__globals__", F),
    "super of a builtin": ("x = super(int, 5).bit_length", F),
    "super beyond DEFINABLE": ("class A:\n    def f(self):\n        return super().__getattribute__('x')\nA().f()", F),
    "property internals": ("fget = 1\nclass A:\n    @property\n    def p(self):\n        return 1\nf = A.p.fget", X),
    "staticmethod __func__": ("class A:\n    s = staticmethod(put)\nf = A.__dict__", F),
    "generator frame": ("def g():\n    yield 1\nf = g().gi_frame", F),
    "generator frame when named": ("gi_frame = 0\ndef g():\n    yield 1\nf = g().gi_frame", X),
    "generator code": ("gi_code = 0\ng = (i for i in [1])\nc = g.gi_code", X),
    "dataclass Field internals": ("from dataclasses import dataclass, fields\n@dataclass\nclass P:\n    x: int\n"
                                  "_field_type = 0\nf = fields(P)[0]._field_type", X),
    "dataclass internals": ("from dataclasses import dataclass\n@dataclass\nclass P:\n    x: int\nf = P.__dataclass_fields__", F),
    "dataclass on a non-program class": ("from dataclasses import dataclass\nimport collections\nD = dataclass(collections.Counter)", E.TYPE_ERROR),
    "dataclass weakref_slot option": ("from dataclasses import dataclass\n@dataclass(slots=True, weakref_slot=True)\n"
                                      "class P:\n    x: int", F),
    "dataclass slot descriptor": ("from dataclasses import dataclass\n@dataclass(slots=True)\nclass P:\n    x: int\n"
                                  "d = P.x\nv = d.__get__(P(1), P)", F),
    "wraps assigned": ("from functools import wraps\ndef f():\n    pass\nw = wraps(f, assigned=('__globals__',))", E.TYPE_ERROR),
    "namedtuple code injection": ("from collections import namedtuple\nP = namedtuple('P', 'x, y=__import__(\"os\")')", E.VALUE_ERROR),
    "namedtuple module": ("from collections import namedtuple\nP = namedtuple('P', 'x', module='os')", E.TYPE_ERROR),
    "random state": ("import random\ns = random.getstate()", F),
    "random instance state": ("getstate = 0\nimport random\ns = random.Random(1).getstate()", X),
    "random bits": ("import random\nb = random.getrandbits(10**9)", F),
    "numpy array internals": ("data = 0\nimport numpy as np\nd = np.array([1]).data", X),
    "numpy ndarray constructor": ("import numpy as np\na = np.ndarray((3, 3))", E.TYPE_ERROR),
    "numpy dtype object": ("import numpy as np\na = np.zeros(3, dtype=print)", E.TYPE_ERROR),
    # the world's objects through the new surface
    "attribute store on the board": ("board.puts = 0", F),
    "attribute store on a module": ("import math\nmath.pi = 3", F),
    # a program's own function takes attributes (`wrapper.calls = 0`); no other function does
    "attribute store on a stand-in's function": ("import math\nmath.factorial.x = 1", F),
    "attribute store on a method dataclass wrote": ("from dataclasses import dataclass\n@dataclass\nclass P:\n"
                                                    "    x: int\nP.__init__.calls = 0", F),
    "dunder store on the program's function": ("def f(x=1):\n    return x\nf.__defaults__ = (board,)", F),
    "board internals named by a class": ("class A:\n    stacks = 1\nboard.stacks[0].append(('screw', 'red'))", F),
    "forged colour": (SOME_PIECE + "class C:\n    def __eq__(self, o):\n        return True\n    def __hash__(self):\n        return 0\n"
                      "put(board, 'nut', C(), 3, 3)", E.KEY_ERROR),
    "forged shape": ("class C:\n    def __eq__(self, o):\n        return True\n    def __hash__(self):\n        return 0\n"
                     "put(board, C(), 'red', 3, 3)", E.KEY_ERROR),
    "forged coordinate": ("class N:\n    def __eq__(self, o):\n        return True\nput(board, 'nut', 'red', N(), 3)", E.TYPE_ERROR),
    # budgets reach class bodies, methods and generators
    "loop in a class body": ("class A:\n    while True:\n        pass", T),
    "loop in a method": ("class A:\n    def f(self):\n        while True:\n            pass\nA().f()", T),
    "endless generator": ("def g():\n    while True:\n        yield 1\nx = list(g())", T),
    "endless __next__": ("class I:\n    def __iter__(self):\n        return self\n    def __next__(self):\n        return 1\nx = list(I())", T),
    "method recursion": ("class A:\n    def f(self):\n        return self.f()\nA().f()", R),
    "__len__ bomb": ("class L:\n    def __len__(self):\n        return 10**9\nx = [0] * len(L())", R),
    "__str__ loop after the end": ("class Bad(Exception):\n    def __str__(self):\n        while True:\n            pass\nraise Bad()", T),
    "swallowed stop in __eq__": ("class A:\n    def __eq__(self, o):\n        try:\n            while True:\n                pass\n        finally:\n"
                                 "            return True\nx = A() == 1", T),
    "numpy broadcast bomb": ("import numpy as np\na = np.arange(10**5)\nb = a.reshape(-1, 1) + a", R),
    "numpy int growth": ("import numpy as np\na = np.array([3])\nwhile True:\n    a = a * a", R),
    "random sample bomb": ("import random\nx = random.choices([1], k=10**9)", R),
}
NAMES = list(HOSTILE)


@pytest.fixture(scope="module")
def results():
    return dict(zip(NAMES, execute_many([HOSTILE[n][0] for n in NAMES], limits=Limits(wall_time=10.0), cache=False)))


def test_a_program_object_in_a_put_gives_the_same_message_in_every_worker():
    forged = HOSTILE["forged colour"][0]
    runs = execute_many([forged] * 4, cache=False, workers=2)
    assert {ex.message for ex in runs} == {"line 7: a colour is one of red, green, blue, yellow, not a C"}


@pytest.mark.parametrize("name", NAMES)
def test_hostile_class_program_is_refused_or_harmless(results, name):
    ex = results[name]
    assert (ex.ok, ex.error) == (False, HOSTILE[name][1]), ex.message
    for stack in ex.cells.values():  # only pieces put placed: exact str pairs of the vocabulary
        assert all(type(s) is str and type(c) is str for s, c in stack)
    assert ex.puts == (1 if HOSTILE[name][0].startswith(SOME_PIECE) else 0)
