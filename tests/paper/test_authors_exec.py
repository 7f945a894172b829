"""The paper protocol runs a program as the authors' scorer did (paper-protocol README, "How the
authors ran a program"): one test per rule, each program run in the sandbox with PAPER semantics
and by the plain-exec model of the authors' scorer (tests/helpers/authors_scorer.py); verdict and board
must agree, and each rule's programs give the verdict the README states. Our protocol (MODULE)
keeps a script's semantics for the same programs."""
import numpy
import pytest

from authors_scorer import reference
from sartco.paper.scoring import score_turn
from sartco.program import MODULE, PAPER, execute, execute_many
from sartco.world import Board, ErrorCode, put

E = ErrorCode
RED = "put(board, 'washer', 'red', 0, 0)"


def sandbox(program: str, semantics=PAPER) -> tuple:
    ex = execute(program, semantics=semantics)
    return ex.ok, ex.error, ex.cells


def script(program: str) -> tuple:
    """Plain exec as a script's module (our protocol's contract), with `np` bound as the authors'
    namespace bound it (our protocol binds it too)."""
    env = {"__name__": "__main__", "board": Board(), "put": put, "init_board": Board, "np": numpy}
    exec(program, env)
    return True, None, (env["board"] if type(env["board"]) is Board else Board()).cells()


def agree(programs):
    got = execute_many(programs, semantics=PAPER)
    for program, ex in zip(programs, got):
        assert (ex.ok, ex.error, ex.cells) == reference(program), program
    return got


# rule 1: the top level sees the scorer module's globals and the function's locals
GLOBALS = [
    "put(board, 'washer', 'red', int(np.sqrt(16)), 0)",                       # np without an import
    "for x in np.arange(3):\n    put(board, 'nut', 'blue', int(x), 1)",
    "put(board, 'washer', json.loads('[\"green\"]')[0], 1, 1)",               # json
    "c = Counter('aab')\nput(board, 'washer', 'red', c['a'], c['b'])",        # Counter
    "cells = deepcopy([[1, 2]])\nput(board, 'washer', 'red', *cells[0])",      # deepcopy
    "b = init_board(8, 8)\nput(b, 'washer', 'red', 0, 0)\nput(board, 'nut', 'red', 2, 2)",
    "put(board, 'washer', 'red', 0, len(instruction) % 8)",                   # the local `instruction`
    "import math\nput(board, 'washer', 'red', math.floor(2.5), 3)",            # imports still work
]


def test_top_level_sees_the_scorer_globals_and_the_function_locals():
    got = agree(GLOBALS)
    assert all(ex.ok and ex.cells for ex in got)
    # our protocol binds np as the authors did (runtime.namespace); a script has no json, Counter,
    # deepcopy or instruction without an import
    assert [execute(p).error for p in GLOBALS[:7]] == [None, None] + [E.NAME_ERROR] * 3 + [None, E.NAME_ERROR]


def test_re_is_bound_but_refused_naming_why():
    """The authors' re worked; ours stays refused (a pattern can backtrack in C code beyond every
    budget), with a one-line reason instead of a NameError or a silently different board."""
    program = "put(board, 'washer', re.sub('x', '', 'rxed'), 0, 0)"
    assert reference(program)[0]
    ex = execute(program, semantics=PAPER)
    assert ex.error == E.FORBIDDEN and ex.message == \
        "line 1: re.sub is not available in the sandbox: a regular expression can run in C code beyond every budget"


# rule 2: __name__ is the scorer module's name
MAIN_GUARD = f"if __name__ == '__main__':\n    {RED}\nput(board, 'nut', 'blue', 1, 1)"


def test_the_main_guard_never_runs():
    (ex,) = agree([MAIN_GUARD])
    assert ex.cells == {"1:1": [["nut", "blue"]]}
    assert sandbox(MAIN_GUARD, MODULE) == script(MAIN_GUARD)  # a script runs the guarded block
    assert execute(MAIN_GUARD).cells == {"0:0": [["washer", "red"]], "1:1": [["nut", "blue"]]}


# rule 3: top-level assignments go to a snapshot of the locals: rebinding `board` is lost
REBIND = [
    f"board = init_board(8, 8)\n{RED}",                                       # puts on the new board lost
    f"{RED}\nboard = init_board(8, 8)\nput(board, 'nut', 'blue', 1, 1)",      # the board before stays
    f"global board\nboard = init_board(8, 8)\n{RED}",
    "def make():\n    b = init_board(8, 8)\n    put(b, 'nut', 'red', 3, 3)\n    return b\nboard = make()",
]


def test_rebinding_board_is_lost():
    got = agree(REBIND)
    assert [ex.cells for ex in got] == [{}, {"0:0": [["washer", "red"]]}, {}, {}]
    assert [sandbox(p, MODULE) for p in REBIND] == [script(p) for p in REBIND]
    assert execute(REBIND[0]).cells == {"0:0": [["washer", "red"]]}


def test_an_answer_that_starts_with_a_new_board_fails_es_in_the_paper_protocol():
    """The issue's case: ES 1 under module semantics, 0 under the authors' exec."""
    answer = f"board = init_board(8, 8)\n{RED}"
    turn = score_turn({"output": answer}, {"output": RED}, "multi_turn")
    assert (turn.es, turn.category) == (False, "mismatch_location")  # the scored board is empty
    assert execute(answer).cells == execute(RED).cells               # as a script it builds the gold board


# rule 4: functions the program defines look names up in the scorer module's globals only
BLIND = [
    f"def build():\n    {RED}\nbuild()",                                                          # board
    "x = 3\ndef build(b):\n    put(b, 'washer', 'red', 0, x)\nbuild(board)",                   # a top-level variable
    "def place(b, y):\n    put(b, 'nut', 'red', 0, y)\n"
    "def build(b):\n    for y in range(2):\n        place(b, y)\nbuild(board)",                 # a helper function
    "COLORS = ['red', 'blue']\nfor y, c in enumerate(COLORS):\n    put(board, 'washer', c, 1, y)\n"
    "def more(b):\n    put(b, 'nut', COLORS[0], 1, 0)\nmore(board)",                           # puts before the error stay
]
SEEING = [
    "def build(b):\n    for y in np.arange(2):\n        put(b, 'washer', 'red', 0, int(y))\n"
    "    c = deepcopy(['blue'])\n    put(b, 'nut', c[0], 0, 0)\n    return init_board(8, 8)\nbuild(board)",
    "build = lambda b, y: put(b, 'screw', 'green', 2, y)\nfor y in range(3):\n    build(board, y)",
    "def build(b):\n    global shade\n    shade = 'yellow'\n    put(b, 'washer', shade, 4, 4)\n"
    "def again(b):\n    put(b, 'nut', shade, 4, 4)\nbuild(board)\nagain(board)",              # global writes the globals
]


def test_functions_are_blind_to_top_level_names():
    got = agree(BLIND)
    assert [ex.error for ex in got] == [E.NAME_ERROR] * 4
    assert got[3].cells == {"1:0": [["washer", "red"]], "1:1": [["washer", "blue"]]}
    assert all(sandbox(p, MODULE)[0] for p in BLIND)  # a script's functions see its top level


def test_functions_see_the_scorer_globals_and_their_parameters():
    got = agree(SEEING)
    assert all(ex.ok and ex.cells for ex in got)


def test_the_given_object_function_in_front_of_a_regular_answer_is_blind_too():
    """Regular cells put the gold object function in front: a repetition that calls it at the top
    level works; one that calls it from its own function does not (README, rule 4)."""
    given = "def build_object(board, x, y):\n    put(board, 'washer', 'red', x, y)\n    put(board, 'nut', 'blue', x, y)"
    top = "for y in range(2):\n    build_object(board, 0, y)"
    nested = "def repeat(b):\n    for y in range(2):\n        build_object(b, 0, y)\nrepeat(board)"
    gold = {"output": top}
    assert score_turn({"output": top}, gold, "regular", given).es
    turn = score_turn({"output": nested}, gold, "regular", given)
    assert (turn.es, turn.category) == (False, "name_error")
    agree([f"{given}\n{top}", f"{given}\n{nested}"])


@pytest.mark.parametrize("program", GLOBALS + [MAIN_GUARD] + REBIND + BLIND + SEEING)
def test_module_semantics_stay_a_scripts(program):
    """Our protocol: the same programs run as a script's module, where a script can run them."""
    try:
        expected = script(program)
    except NameError:
        expected = None
    got = sandbox(program, MODULE)
    assert got == expected if expected is not None else got[1] == E.NAME_ERROR


# the authors' module was importable: dataclasses reads string annotations through it
RECORDS = [
    "from __future__ import annotations\nfrom dataclasses import dataclass\n@dataclass\nclass P:\n    x: int\n"
    "    nxt: P | None = None\np = P(2, P(3))\nput(board, 'washer', 'red', p.x, p.nxt.x)",
    "from dataclasses import dataclass\n@dataclass(frozen=True)\nclass P:\n    x: 'int'\n    y: 'int' = 1\n"
    "    tags: 'tuple' = ()\ns = {P(2), P(2), P(4, 5)}\n"
    "for p in s:\n    put(board, 'nut', 'blue', p.x, p.y)\nput(board, 'washer', 'red', 0, len(s))",
    "import dataclasses\n@dataclasses.dataclass(order=True)\nclass P:\n    x: 'typing.Any'\n    y: 'ClassVar[int]' = 3\n"
    "for p in sorted([P(4), P(1)]):\n    put(board, 'screw', 'green', p.x, p.y)\nput(board, 'washer', 'red', 0, len(dataclasses.fields(P)))",
]


def test_a_dataclass_with_string_annotations_runs_as_under_the_authors_exec():
    got = agree(RECORDS)
    assert all(ex.ok and ex.cells for ex in got), [ex.message for ex in got]
    assert [sandbox(p, MODULE) for p in RECORDS] == [script(p) for p in RECORDS]
