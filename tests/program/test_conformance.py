"""The conformance suite of the Sandbox interface (sartco/program/sandbox.py): every implementation
runs the same programs and must give exactly the Executions this machine's LocalSandbox gives, and
those must be right (plain exec's board for honest programs; the documented refusal, stop or
error for the rest). A new Sandbox is added to IMPLEMENTATIONS; it passes this module or it is not
one.

The cases: honest programs (both semantics), hostile ones (refused), resource ones (stopped),
forging ones (only put's pieces count), determinism (the same program twice, in any order of a
batch, the same Execution), bytes no program should send (never an exception out of the sandbox).

RaySandbox runs on a local Ray instance this module starts (the `ray` extra); where
SARTCO_REQUIRE_RAY is set (CI) a missing Ray fails instead of skipping.
"""
from __future__ import annotations

import os

import pytest
from oracle_helpers import plain_run

from sartco.program import MODULE, PAPER, LocalSandbox, Limits, Sandbox, execute_many, use
from sartco.world import ErrorCode

E = ErrorCode
# a memory cap that a hog reaches at once, and a wall time no loaded machine reaches first
LIMITS = Limits(wall_time=10.0, memory=64 * 1024 ** 2, steps=200_000)

HONEST = {  # programs plain exec runs: the sandbox builds plain exec's board
    "straight puts": "put(board, 'nut', 'red', 0, 0)\nput(board, 'washer', 'blue', 0, 1)",
    "a loop": "for i in range(8):\n    put(board, 'washer', 'blue', i, i)",
    "a helper": "def f(b, c, x, y):\n    put(b, 'bridge-h', c, x, y)\nf(board, 'green', 3, 3)",
    "a class": ("class Tower:\n    def __init__(self, x, y):\n        self.x, self.y = x, y\n"
                "    def add(self, shape, color):\n        put(board, shape, color, self.x, self.y)\n        return self\n"
                "Tower(2, 2).add('washer', 'red').add('nut', 'yellow')"),
    "seeded random": "import random\nrandom.seed(7)\nfor i in range(4):\n    put(board, 'washer', random.choice(['red', 'blue']), i, random.randint(0, 7))",
    "a set of strings": "for i, c in enumerate(sorted({'red', 'blue', 'green'})):\n    put(board, 'nut', c, i, 0)",
    "a new board": "board = init_board(4, 4)\nput(board, 'screw', 'green', 3, 3)",
}
# name: (program, the error it must end in, a word of its message)
OTHERS = {
    "a world error": ("put(board, 'screw', 'red', 1, 1)\nput(board, 'nut', 'red', 1, 1)", E.NOT_ON_TOP_OF_SCREW, ""),
    "an import of os": ("import os", E.FORBIDDEN, "os"),
    "the interpreter through a dunder": ("x = ().__class__", E.FORBIDDEN, "__class__"),
    "eval": ("eval('1')", E.FORBIDDEN, "eval"),
    "steps": ("while True:\n    pass", E.TIMEOUT, ""),
    "memory": ("x = [[0] * 10**6 for i in range(1000)]", E.RESOURCE_LIMIT, ""),
    "a forged board": ("import copy\nm = {}\ncopy.deepcopy(board, m)", E.FORBIDDEN, "memo"),
    "a syntax error": ("put(board, 'nut', 'red', 0, 0", E.SYNTAX_ERROR, ""),
    "a lone surrogate in the source": ("put(board, '\udcff', 'red', 0, 0)", E.SYNTAX_ERROR, "surrogates"),
}
# programs whose verdict depends on a run, not on a rule: equal across sandboxes and repeats
VARYING = [
    "x = [1]\nfor i in range(300000):\n    x = map(abs, x)\ny = list(x)",  # a crash, or the memory cap first
    "class P:\n    pass\nfor i, p in enumerate({P() for _ in range(8)}):\n    put(board, 'nut', 'red', i, 0)",
]


def _ray_sandbox():
    if os.environ.get("SARTCO_REQUIRE_RAY"):
        import ray  # noqa: F401  (CI: a missing Ray is a failure, not a skip)
    else:
        pytest.importorskip("ray")
    from sartco.program.cluster import RaySandbox

    return RaySandbox(None, chunk=7, num_cpus=2, include_dashboard=False)


IMPLEMENTATIONS = {  # name: a function that starts one (the module closes it)
    "local": lambda: LocalSandbox(workers=2),
    "ray": _ray_sandbox,
}


@pytest.fixture(scope="module", params=list(IMPLEMENTATIONS))
def box(request):
    sandbox = IMPLEMENTATIONS[request.param]()
    assert isinstance(sandbox, Sandbox)
    yield sandbox
    sandbox.close()


@pytest.fixture(scope="module")
def reference():
    """This process's own local sandbox: what every implementation must equal."""
    sandbox = LocalSandbox(workers=2)
    yield sandbox
    sandbox.close()


@pytest.mark.parametrize("semantics", [MODULE, PAPER])
def test_honest_programs_build_plain_execs_board(box, semantics):
    names = list(HONEST)
    if semantics == PAPER:  # the authors' exec: a function's locals, no __main__, and their board
        names = [n for n in names if n not in ("a class", "a new board")]
    got = box.execute_many([HONEST[n] for n in names], limits=LIMITS, semantics=semantics)
    for name, ex in zip(names, got):
        assert ex.ok, (name, ex)
        assert (ex.cells, ex.puts) == plain_run(HONEST[name]), name


def test_refusals_stops_and_errors_are_the_documented_ones(box):
    names = list(OTHERS)
    got = box.execute_many([OTHERS[n][0] for n in names], limits=LIMITS)
    for name, ex in zip(names, got):
        _, error, word = OTHERS[name]
        assert (ex.ok, ex.error) == (False, error), (name, ex)
        assert word in ex.message, (name, ex)
        assert "\n" not in ex.message and ex.message.isprintable(), (name, ex.message)
    assert got[names.index("a forged board")].cells == {}


def test_every_execution_equals_the_reference_sandbox(box, reference):
    programs = (list(HONEST.values()) + [p for p, _, _ in OTHERS.values()] + VARYING) * 2
    assert box.execute_many(programs, limits=LIMITS) == reference.execute_many(programs, limits=LIMITS, cache=False)


def test_the_same_program_gives_the_same_execution_in_any_batch(box):
    programs = list(HONEST.values()) + VARYING
    alone = [box.execute(p, limits=LIMITS) for p in programs]
    assert box.execute_many(programs[::-1], limits=LIMITS) == alone[::-1]


def test_a_sandbox_in_use_serves_the_module_functions(box):
    before = use(box)
    try:
        through = execute_many(list(HONEST.values()), limits=LIMITS)
    finally:
        use(before)
    assert through == [box.execute(p, limits=LIMITS) for p in HONEST.values()]
