"""Programs of one batch that differ only in their last line (an answer's probes, a draw's gold
candidates) share the check and compile of the rest (instrument.Head, compiled._in_parts): each
gets the Execution it gets alone, whatever its last line, head or semantics."""
import sys

import pytest

from sartco.program import Limits, compiled, pool
from sartco.program.check import instrument
from sartco.program.execution import MODULE, PAPER
from sartco.program.standins.budget import Forbidden
from sartco.world import ErrorCode

FUNCTION = """def f(board, colors, x, y):
    for c in colors:
        put(board, 'nut', c, x, y)
        y += 1
    return len(colors)
board = init_board(6, 6)"""

CASES = {
    "probes": (FUNCTION, ["f(board, ['red'], 1, 2)", "f(board, ['blue', 'green'], 3, 4)",
                          "f(board, ['red', 'red'], 5, 5)", "f(board, ['pink'], 0, 0)",
                          "f(board, ['red'], 0, 0) + 1 / 0", "f(board, colors=['red'], x=2, y=2)"]),
    "last lines that bind, read or refuse": (FUNCTION, [
        "x = f(board, ['red'], 1, 1)", "import math", "print(eval('1'))", "f(board, ['red'], 1, 1).real",
        "for k in range(2): f(board, ['red'], k, 0)", "f(board, ['red'], 1, 1); board = None", "__import__('os')",
        "(lambda: f(board, ['red'], 2, 2))()", "f(board, [c for c in ['red']], 0, 0)"]),
    "a last line that continues the head": ("x = 1\nif x:\n    put(board, 'nut', 'red', 0, 0)",
                                            ["else: put(board, 'nut', 'blue', 0, 0)",
                                             "    put(board, 'nut', 'blue', 1, 1)", "put(board, 'nut', 'blue', 2, 2)"]),
    "a head that does not parse alone": ("put(board, 'nut', 'red',", ["0, 0)", "1, 1)", "1, 1"]),
    "a head that does not compile alone": ("put(board, 'nut', 'red', 0, 0)\nreturn", ["1", "(yield)"]),
    "last lines that do not compile": (FUNCTION, ["(yield)", "*f(board, ['red'], 0, 0)", "await f(board, ['red'], 0, 0)",
                                                  "f(board, ['red'], 0, 0)"]),
    "a head refused at a node": ("import os\nboard = init_board(3, 3)", ["put(board, 'nut', 'red', 0, 0)", "1"]),
    # `.crimson` is a word of the program's strings only when the last line brings it
    "a head refused as a whole": ("def f(board, o):\n    return o.crimson", ["f(board, 'crimson')", "f(board, 'scarlet')"]),
    # a last line that binds a name the head reads, or reads an attribute that the head's strings name
    "names between head and last line": ("word = 'crimson'\ndef g(board):\n    return eval",
                                         ["g(board).crimson", "g(board).scarlet", "eval = len", "eval", "g(board)"]),
    "a head of the task's world": ("put = 1", ["put", "put + 1"]),
    "a head with a future import": ("from __future__ import annotations\ndef f(board) -> int:\n    return 1",
                                    ["f(board)", "f(board) + 'a'"]),
    "a head with a set constant": ("def f(board, c):\n    if c in {'red', 'blue', 'green'}:\n"
                                   "        put(board, 'nut', c, 0, 0)", ["f(board, 'red')", "f(board, 'pink')"]),
    "comments and blank lines": (FUNCTION + "\n", ["# done", "", "\n", "f(board, ['red'], 0, 0)  # probe\n"]),
    "carriage returns": ("x = 1\r\nput(board, 'nut', 'red', x, x)", ["1 / 0", "put(board, 'nut', 'red', 2, 2)"]),
}


def _alone_and_together(programs: list[str], semantics: str) -> tuple[list, list]:
    box = pool.LocalSandbox(workers=1)
    try:
        alone = [box.execute_many([p], 6, 6, Limits(), cache=False, semantics=semantics)[0] for p in programs]
        together = box.execute_many(programs, 6, 6, Limits(), cache=False, semantics=semantics)
    finally:
        box.close()
    return alone, together


@pytest.mark.parametrize("semantics", [MODULE, PAPER])
@pytest.mark.parametrize("case", sorted(CASES))
def test_a_program_that_shares_its_head_gets_its_own_verdict(case, semantics):
    head, lines = CASES[case]
    programs = [f"{head}\n{line}" for line in lines]
    alone, together = _alone_and_together(programs, semantics)
    for program, mine, shared in zip(programs, alone, together):
        assert shared == mine, program


def test_the_probes_share_their_head():
    """Each probe's last line is judged and compiled alone; the messages keep its line number."""
    head, lines = CASES["probes"]
    heads: dict = {}
    made = [instrument.prepare(f"{head}\n{line}", heads) for line in lines]
    assert list(heads) == [head] and all(type(code) is tuple and code[0] is heads[head].code for code in made)
    alone, together = _alone_and_together([f"{head}\n{line}" for line in lines], MODULE)
    assert together[1].cells == {"3:4": [["nut", "blue"]], "3:5": [["nut", "green"]]}
    assert together[4].message == alone[4].message and together[4].message.startswith("line 7: ZeroDivisionError")


def test_a_last_line_that_binds_or_reads_is_prepared_whole():
    heads: dict = {}
    assert type(instrument.prepare(f"{FUNCTION}\nf(board, ['red'], 1, 1)", heads)) is tuple
    for line in ("x = 1", "import math", "board.cells", "eval", "    f(board, ['red'], 1, 1)", "else: pass",
                 "class C: pass", "global x", "f(board, ['red'], 1, 1) if x else None; y = 2",
                 "'a docstring binds __doc__'; f(board, ['red'], 1, 1)"):
        try:
            code = instrument.prepare(f"{FUNCTION}\n{line}", heads)
        except (SyntaxError, Forbidden):
            continue
        assert type(code) is not tuple, line


@pytest.mark.parametrize("source, parts", [
    ("a\nb", ("a", "b")), ("a\nb\n", ("a", "b\n")), ("a\n\nb", ("a\n", "b")), ("a\n", None), ("a", None),
    ("a\r\nb", None), ("from __future__ import annotations\nb", None)])
def test_split(source, parts):
    assert instrument.split(source) == parts


@pytest.mark.skipif(sys.version_info[:2] != (3, 11), reason="the nesting figures are CPython 3.11's")
def test_a_shared_head_keeps_the_nesting_limit():
    """test_parent_compile's limit (986 terms compile, 987 do not) holds for heads shared by two."""
    def summed(terms: int, last: str) -> str:
        return "x = 1\ny = " + " + ".join(["x"] * terms) + "\n" + last

    lasts = ["put(board, 'nut', 'red', 0, 0)", "put(board, 'nut', 'red', 1, 1)"]
    made = compiled.prepare_all([summed(terms, last) for terms in (986, 987, 986) for last in lasts], Limits())
    assert [type(m) is bytes for m in made] == [True, True, False, False, True, True]
    assert {(m.error, m.message) for m in made[2:4]} == {(ErrorCode.RESOURCE_LIMIT, "the program is too deeply nested to compile")}


def test_a_program_that_shares_its_head_counts_the_heads_compile_time():
    """A compile longer than the wall time is `timeout` (compiled.py); a program whose head was
    made for another program of the batch counts that head's compile, as its whole compile would."""
    head = "\n".join(f"x{i} = [{i}, {i} + 1, 'a{i}']" for i in range(6000))
    limits = Limits(wall_time=0.005, source=1_000_000)  # the head takes far longer to compile
    made = compiled.prepare_all([f"{head}\nput(board, 'nut', 'red', {k}, 0)" for k in range(3)], limits)
    assert [(m.error, m.message) for m in made] == [(ErrorCode.TIMEOUT, "the program ran longer than 0.005 s")] * 3
