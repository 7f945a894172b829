"""The board is the world's alone: no program builds a board that `put` did not build.

- the issue's smallest case (copy.deepcopy's memo handing out the board's lists) and its
  variants through the other stand-ins end `forbidden` or build only what put placed;
- a board's copy is an independent board; a board refuses to be reduced or pickled;
- put compares shapes and colours by value on exact str (a str subclass that equals anything is
  not a colour);
- the result check (program/result.py) turns a board whose storage was changed outside put into
  `forbidden` with the cells put placed, whatever the storage held (lists, lone surrogates, str
  subclasses, six pieces in a cell, cells off the board, zero puts): never a crash of the caller,
  always strict JSON.
"""
import copy
import json
import pickle
import subprocess
import sys
import typing

import pytest

from sartco.program import Limits, execute, judge
from sartco.program.child import runtime
from sartco.program.lines import encode
from sartco.program.child.result import FORGED, board_result
from sartco.world import Board, ErrorCode, WorldError, put

E = ErrorCode
L = Limits()
SMALLEST = """import copy
m = {}
copy.deepcopy(board, m)
for v in list(m.values()):
    if isinstance(v, list) and len(v) == 64:
        v[0].append(('screw', 'purple'))
board = list(m.values())[0]
"""
WR = [["washer", "red"]]


class Sneaky(str):
    """A str that equals everything (the kind of object class support lets a program make)."""

    def __eq__(self, other):
        return True

    __hash__ = str.__hash__


# --- programs: each ends forbidden, or builds only what put placed --------------------------------

REFUSED = {  # name: program (each must end `forbidden` with an empty board)
    "the issue's smallest case": SMALLEST,
    "memo as a keyword": "import copy\nm = {}\ncopy.deepcopy(board, memo=m)",
    "memo through from-import": "from copy import deepcopy\nm = {}\ndeepcopy([board], m)",
    "memo through functools.partial": "import copy, functools\nm = {}\nf = functools.partial(copy.deepcopy, memo=m)\nf(board)",
    "memo through map": "import copy\nm = {}\nlist(map(copy.deepcopy, [board], [m]))",
    "memo through functools.reduce": "import copy, functools\nfunctools.reduce(copy.deepcopy, [board], {})",
    "memo through itertools.starmap": "import copy, itertools\nlist(itertools.starmap(copy.deepcopy, [(board, {})]))",
    "memo through a dict's default": "import copy, collections\nd = collections.defaultdict(dict)\ncopy.deepcopy(board, d)",
    "memo through a numpy stand-in list": "import copy\nimport numpy as np\ncopy.deepcopy(np.array([board]), {})",
}


@pytest.mark.parametrize("name", list(REFUSED))
def test_the_memo_is_refused(name):
    ex = execute(REFUSED[name])
    assert (ex.ok, ex.error, ex.cells, ex.puts) == (False, E.FORBIDDEN, {}, 0), ex
    assert "memo" in ex.message


PLACED_ONLY = {  # name: (program, the cells of the scored board)
    "copy of the board, put on the copy": ("import copy\nb = copy.copy(board)\nput(b, 'washer', 'red', 0, 0)", {}),
    "deepcopy of the board, put on the copy": ("import copy\nb = copy.deepcopy(board)\nput(b, 'washer', 'red', 0, 0)", {}),
    "put on the board, then on its copy": (
        "import copy\nput(board, 'washer', 'red', 0, 0)\nb = copy.copy(board)\nput(b, 'screw', 'blue', 0, 0)",
        {"0:0": WR}),
    "the copy scored": (
        "import copy\nput(board, 'washer', 'red', 0, 0)\nboard = copy.deepcopy(board)\nput(board, 'nut', 'red', 0, 0)",
        {"0:0": WR + [["nut", "red"]]}),
    "a copied list of boards": ("import copy\nx = copy.deepcopy([board, board])\nput(x[0], 'washer', 'red', 0, 0)\n"
                                "put(x[1], 'nut', 'red', 0, 0)", {}),
    "a copied partial of put": ("import copy, functools\np = copy.deepcopy(functools.partial(put, board))\n"
                                "p('washer', 'red', 0, 0)", {}),
    "a copied deque of boards": ("import copy, collections\nd = copy.copy(collections.deque([board]))\n"
                                 "put(d[0], 'washer', 'red', 0, 0)", {"0:0": WR}),
    "a copied stand-in module": ("import copy, math\nm = copy.deepcopy(math)\nput(board, 'washer', 'red', 0, m.floor(0.5))",
                                 {"0:0": WR}),
    "numpy's full of boards": ("import numpy as np\nbs = np.full(2, board)\nput(bs[1], 'washer', 'red', 0, 0)", {"0:0": WR}),
    "typing's cache holding the board": ("from typing import Literal\nt = Literal[board]\nput(board, 'washer', 'red', 0, 0)",
                                         {"0:0": WR}),
}


@pytest.mark.parametrize("name", list(PLACED_ONLY))
def test_copies_are_independent_boards(name):
    program, cells = PLACED_ONLY[name]
    ex = execute(program)
    assert ex.ok, ex
    assert ex.cells == cells


@pytest.mark.parametrize("program,code", [
    ("import copy\ncopy.copy(board, {})", E.TYPE_ERROR),
    ("import operator\noperator.itemgetter(0)(board)", E.TYPE_ERROR),
    ("import functools\nfunctools.reduce(lambda a, b: a + b, [board, board])", E.TYPE_ERROR),
])
def test_other_stand_ins_reach_no_storage(program, code):
    ex = execute(program)
    assert (ex.ok, ex.error, ex.cells) == (False, code, {}), ex


def test_sartco_execute_answers_the_smallest_case_in_strict_json():
    line = json.dumps({"id": "forge", "code": SMALLEST, "target": {"0:0": [["screw", "purple"]]}})
    proc = subprocess.run([sys.executable, "-m", "sartco", "execute"], input=line.encode() + b"\n",
                          capture_output=True, timeout=120)
    out = json.loads(proc.stdout.decode("utf-8", errors="strict"))
    assert (out["ok"], out["error"], out["cells"], out["es"]) == (False, "forbidden", {}, 0)


# --- the world's types -------------------------------------------------------------------------

def test_a_board_copy_shares_no_storage():
    board = put(Board(), "washer", "red", 0, 0)
    for twin in (copy.copy(board), copy.deepcopy(board), copy.deepcopy([board])[0]):
        put(twin, "nut", "red", 0, 0)
        assert board.cells() == {"0:0": WR} and board.puts == 1 and len(board.log) == 1
        assert twin.cells() == {"0:0": WR + [["nut", "red"]]} and twin.puts == 2
        assert board_result(twin)[2] is None


def test_a_board_refuses_to_be_reduced_or_pickled():
    board = Board()
    for attempt in (lambda: pickle.dumps(board), lambda: board.__reduce_ex__(4), lambda: board.__reduce__()):
        with pytest.raises(WorldError) as caught:
            attempt()
        assert caught.value.code == E.FORBIDDEN


@pytest.mark.parametrize("args", [
    ("washer", Sneaky("purple"), 0, 0), (Sneaky("gear"), "red", 0, 0), (Sneaky("washer"), "red", 0, 0),
    ("washer", ["red"], 0, 0), ("washer", "purple", 0, 0),
])
def test_put_takes_only_exact_str_shapes_and_colours(args):
    board = Board()
    with pytest.raises(WorldError) as caught:
        put(board, *args)
    assert caught.value.code == E.KEY_ERROR
    assert board.cells() == {} and board.puts == 0


def test_a_sneaky_shape_runs_no_comparison_on_a_stack():
    board = put(Board(), "washer", "red", 0, 0)
    with pytest.raises(WorldError) as caught:  # its == would say "washer on a washer"
        put(board, Sneaky("nut"), "red", 0, 0)
    assert caught.value.code == E.KEY_ERROR


@pytest.mark.parametrize("coordinate", [True, 1.0, "1", Sneaky("1")])
def test_coordinates_are_exact_ints(coordinate):
    with pytest.raises(WorldError) as caught:
        put(Board(), "washer", "red", coordinate, 0)
    assert caught.value.code == E.TYPE_ERROR


# --- the result check --------------------------------------------------------------------------

def _forge_purple_screw(b):
    b.stacks[0].append(("screw", "purple"))


def _forge_six(b):
    b.stacks[9].extend([("washer", "red"), ("nut", "red")] * 3)


def _forge_off_board(b):
    b.stacks.append([("washer", "red")])


def _forge_screw_on_screw(b):
    b.stacks[0].append(("screw", "red"))


def _forge_eight_without_puts(b):
    b.stacks[:] = [[("washer", "red")]] * 8 + b.stacks[8:]
    b.puts = 0
    b.log.clear()


def _forge_list_piece(b):
    b.stacks[3].append(["washer", "red"])


def _forge_list_stack(b):
    b.stacks[3] = ("washer", "red")


def _forge_surrogate(b):
    b.stacks[5].append(("washer", "\ud800"))


def _forge_sneaky(b):
    b.stacks[5].append((Sneaky("washer"), Sneaky("red")))


def _forge_log(b):  # storage and log forged alike: the replay's checks refuse the purple screw
    piece = ("screw", "purple")
    b.log.append((piece, 4, 4))
    b.stacks[36].append(piece)
    b.puts += 1


def _forge_log_screw_on_screw(b):
    piece = ("screw", "red")
    b.log.append((piece, 0, 0))
    b.stacks[0].append(piece)
    b.puts += 1


def _forge_unhashable_log(b):
    b.log.append(((["washer"], "red"), 99, 4))


def _forge_log_of_lists(b):
    b.log.append((["washer", "red"], 1, 1))


def _forge_equal_copy(b):  # an equal piece that put did not place
    b.stacks[0][0] = ("screw", "green")


FORGERIES = [_forge_purple_screw, _forge_six, _forge_off_board, _forge_screw_on_screw, _forge_eight_without_puts,
             _forge_list_piece, _forge_list_stack, _forge_surrogate, _forge_sneaky, _forge_log,
             _forge_log_screw_on_screw, _forge_unhashable_log, _forge_log_of_lists, _forge_equal_copy]


@pytest.mark.parametrize("forge", FORGERIES, ids=lambda f: f.__name__[7:])
def test_a_board_changed_outside_put_is_forbidden(forge):
    board = put(Board(), "screw", "green", 0, 0)
    forge(board)
    cells, puts, problem = board_result(board)
    assert problem is not None and problem.startswith(FORGED)
    assert cells in ({"0:0": [["screw", "green"]]}, {}) and puts == len(cells)
    verdict = judge(False, E.FORBIDDEN, cells, {"0:0": [["screw", "purple"]]})  # the master's comparison
    assert verdict.es == 0
    json.loads(encode([False, E.FORBIDDEN, problem, cells, puts]).encode("utf-8", errors="strict"))


def test_an_honest_board_passes_the_check():
    board = Board()
    for args in [("bridge-h", "red", 2, 2), ("washer", "blue", 2, 2), ("bridge-v", "green", 5, 5), ("screw", "red", 5, 5)]:
        put(board, *args)
    assert board_result(board) == (board.cells(), 4, None)


@pytest.mark.parametrize("forge", [_forge_purple_screw, _forge_surrogate, _forge_list_piece], ids=lambda forge: forge.__name__)
def test_the_worker_runs_the_check(monkeypatch, forge):
    """A leak of the storage (simulated: put forges the cell) ends forbidden with what put placed."""
    def leaky_put(board, *args):
        put(board, *args)
        forge(board)

    monkeypatch.setattr(runtime, "put", leaky_put)
    compiled = runtime.compile_program("put(board, 'washer', 'red', 1, 1)", L)
    ok, error, message, cells, puts = runtime.run(compiled, 8, 8, L)
    assert (ok, error, message, cells, puts) == (False, E.FORBIDDEN, FORGED, {"1:1": WR}, 1)


def test_typing_caches_keep_nothing_of_an_earlier_program(monkeypatch):
    """Emptied before a program when one before it imported typing (modules.forget_typing), also
    after programs that did not (which leave nothing there to empty)."""
    for _ in range(2):
        runtime.run(runtime.compile_program("x = 0", L), 8, 8, L)
        runtime.run(runtime.compile_program("from typing import Literal, List\nt = Literal[board]\nu = List[str]", L,
                                            ), 8, 8, L)
        assert any(clear.__self__.cache_info().currsize for clear in typing._cleanups)
        runtime.run(runtime.compile_program("x = 1", L, ), 8, 8, L)
        assert all(clear.__self__.cache_info().currsize == 0 for clear in typing._cleanups)


# --- attribute names given as strings ----------------------------------------------------------

@pytest.mark.parametrize("program", [
    "import operator\nx = operator.attrgetter('stacks')(board)",
    "import operator\nx = operator.attrgetter('log', 'puts')(board)",
    "import operator\nx = operator.attrgetter('__class__')('red')",
    "import operator\nx = operator.attrgetter('upper.__self__')('red')",
    "import operator\nx = operator.methodcaller('__reduce_ex__', 4)(board)",
    "import operator\nx = operator.methodcaller('count', 1)(board)",
    "from operator import methodcaller\nx = methodcaller('__deepcopy__', {})(board)",
    "x = getattr(board, 'stacks')",
    "x = vars(board)",
    "setattr(board, 'puts', 8)",
])
def test_attribute_names_as_strings_follow_the_attribute_rule(program):
    ex = execute(program)
    assert (ex.ok, ex.error, ex.cells) == (False, E.FORBIDDEN, {}), ex


def test_attrgetter_and_methodcaller_read_what_a_program_may_read():
    program = ("import math, operator\nnames = list(map(operator.methodcaller('lower'), ['RED', 'Blue']))\n"
               "floor = operator.attrgetter('floor')(math)\nput(board, 'washer', names[0], floor(1.5), 0)\n"
               "put(board, 'washer', operator.attrgetter('lower')('BLUE')(), 0, 0)")
    ex = execute(program)
    assert ex.ok, ex
    assert ex.cells == {"0:0": [["washer", "blue"]], "1:0": WR}
