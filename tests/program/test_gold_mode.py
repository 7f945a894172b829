"""Mode "gold" (child/template.py): the harness's own reference programs of one batch share a confined
child, and every verdict equals the one a child per program gives; a model's program shares a
child only with the other probes of its own answer (mode "answer", test_answer_mode.py).
"""
import pytest

from sartco.clem.core import probes
from sartco.dataset import SHARED_DATA
from sartco.program import Limits, pool
from sartco.published.gold import gold_programs
from sartco.world import ErrorCode

E = ErrorCode
RUNAWAY = "x = sum(sum(range(10**6)) for i in range(10**6))"  # a loop in C code: only the kill stops it
DETERMINED = [  # verdicts that a program alone decides, whatever ran before it in its process
    "put(board, 'nut', 'red', 1, 1)\nput(board, 'nut', 'red', 1, 1)",  # the world's own error
    "def f(n):\n    return f(n + 1)\nf(0)",                              # the depth budget
    "while True:\n    pass",                                              # the step budget: timeout
    "import os",                                                         # forbidden
    "x = {}['k']",                                                       # key_error
    "put(board, 'washer', 'blue', 2, 3)\ny = 1 / 0",                      # the board so far and the error
]
# what may leave its process changed for the programs after it, or end it
ATTACKS = [
    RUNAWAY,                                                             # killed at the wall time
    "x = [[0] * 10**6 for i in range(1000)]",                            # memory: MemoryError
    "L = []\nL.append(L)\nL.append([[0] * 10**6 for i in range(50)])",   # ends ok, leaves 400 MB
    "x = [1]\nfor i in range(300000):\n    x = map(abs, x)\ny = list(x)",  # crashes the C stack
]


def _hungry(i: int) -> str:  # 120 MB for a moment
    return f"x = [[0] * 10**6 for i in range(15)]\nx = 0\nput(board, 'nut', 'red', {i % 8}, {i // 8 % 8})"


def _benign(i: int) -> str:
    return f"def f(board, colors, x, y):\n    put(board, 'nut', colors[0], x, y)\nf(board, ['red'], {i % 8}, {i // 8 % 8})"


@pytest.fixture
def box():
    sandbox = pool.LocalSandbox(workers=1)
    yield sandbox
    sandbox.close()


def test_a_gold_batch_gives_the_verdicts_of_a_child_per_program(box):
    programs = [_benign(i) for i in range(6)] + DETERMINED + [_benign(i) for i in range(6, 12)]
    code = box.execute_many(programs, cache=False)
    gold = box.execute_many(programs, cache=False, mode=pool.GOLD)
    assert gold == code
    assert [ex.error for ex in gold[6:12]] == [E.SAME_SHAPE_STACKING, E.RESOURCE_LIMIT, E.TIMEOUT, E.FORBIDDEN,
                                              E.KEY_ERROR, E.ZERO_DIVISION]
    assert gold[11].cells == {"2:3": [["washer", "blue"]]}
    assert all(ex.ok for ex in gold[:6] + gold[12:])


@pytest.mark.parametrize("attack", range(len(ATTACKS)))
def test_what_a_program_leaves_behind_reaches_no_verdict_after_it(box, attack):
    """After a kill, a crash, a MemoryError or 400 MB left behind, the programs after it in the
    batch run again, each in a child of its own: their verdicts are exact."""
    programs = [_benign(i) for i in range(3)] + [ATTACKS[attack]] + [_benign(i) for i in range(3, 9)]
    results = box.execute_many(programs, limits=Limits(wall_time=1.0), cache=False, mode=pool.GOLD)
    for i, ex in enumerate(results):
        if i != 3:
            assert ex.ok and ex.cells == {f"{j % 8}:{j // 8 % 8}": [["nut", "red"]]
                                          for j in [i if i < 3 else i - 1]}, (i, ex.message)


def test_a_program_that_keeps_memory_changes_no_verdict_after_it(box):
    """150 MB kept in a reference cycle by a program that ends ok: beside it, the next program's
    120 MB would pass the address-space limit; it gets the verdict it gets alone."""
    limits = Limits(memory=250 << 20)
    keep = "L = []\nL.append(L)\nL.append([[0] * 10**6 for i in range(19)])"
    programs = [_hungry(0), keep, _hungry(1), _hungry(2)]
    alone = box.execute_many(programs, limits=limits, cache=False)
    assert [ex.ok for ex in alone] == [True] * 4, [ex.message for ex in alone]
    assert box.execute_many(programs, limits=limits, cache=False, mode=pool.GOLD) == alone


@pytest.mark.skipif(not (SHARED_DATA / "published").is_dir(), reason="shared data missing")
def test_the_published_gold_programs_build_the_same_boards_in_gold_batches(box):
    firsts = {}
    for p in gold_programs():
        firsts.setdefault(p.code, p)
        if len(firsts) == 120:
            break
    programs = [p.code for p in firsts.values()]
    gold = []
    for k in range(0, len(programs), 16):  # a probe round's size
        gold += box.execute_many(programs[k:k + 16], cache=False, mode=pool.GOLD)
    assert gold == box.execute_many(programs, cache=False)
    assert sum(ex.ok and ex.cells == p.target for ex, p in zip(gold, firsts.values())) == len(programs)


def test_a_gold_verdict_is_kept_for_the_same_program_in_mode_code(box):
    [first] = box.execute_many([_benign(1)], mode=pool.GOLD)
    sent = []
    real = pool.dispatch
    try:
        pool.dispatch = lambda *args: sent.append(args) or real(*args)
        assert box.execute_many([_benign(1)]) == [first]
    finally:
        pool.dispatch = real
    assert sent == []


class Spy(pool.LocalSandbox):
    """A local sandbox that notes the mode each program ran in."""

    def __init__(self):
        super().__init__(workers=1)
        self.modes: list[tuple[str, str]] = []
        self.answers: list = []

    def execute_many(self, programs, *args, mode="code", answers=None, **kwargs):
        programs = list(programs)
        self.modes += [(p, pool.ANSWER if answers is not None and mode == "code" else mode) for p in programs]
        self.answers += answers or [None] * len(programs)
        return super().execute_many(programs, *args, mode=mode, answers=answers, **kwargs)


def test_a_models_function_shares_a_child_only_with_its_own_answers_probes():
    from sartco.program import use

    instance = {"task": "optimal_function", "board_id": "b1", "rows": 8, "cols": 8, "combo_name": "n",
                "given_code": "", "probes": 4, "target": {"3:3": [["nut", "red"]]},
                "gold_code": "def build(board, colors, x, y):\n    put(board, 'nut', colors[0], x, y)\n"
                             "build(board, ['red'], 3, 3)\n"}
    answer = "def mine(board, colors, x, y):\n    put(board, 'nut', colors[0], x, y)\nmine(board, ['red'], 3, 3)\n"
    spy = Spy()
    before = use(spy)
    try:
        result = probes.run_probes(instance, answer, seed=12345)
    finally:
        use(before)
        spy.close()
    assert result["share"] == 1.0 and len(result["probes"]) == 4
    model = [m for p, m in spy.modes if "def mine" in p]
    gold = [m for p, m in spy.modes if "def build" in p]
    assert model == [pool.ANSWER] * 4  # one answer's probes: one label (tests/program/test_answer_mode.py)
    assert len({a for (p, _), a in zip(spy.modes, spy.answers) if "def mine" in p}) == 1
    assert gold and set(gold) == {pool.GOLD}
