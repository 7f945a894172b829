"""A big call in parts (pool.parts, issue 46): the templates run one part while the parent compiles
the next. The verdicts, their order, the memo and the answers' children are those of one part.
"""
import threading

import pytest

from sartco.program import pool
from sartco.program.verdict import failed
from sartco.world import ErrorCode

from test_gold_mode import DETERMINED, _benign

E = ErrorCode


def test_parts_double_and_keep_the_order():
    todo = list(range(3, 3000))
    cuts = pool.parts(todo)
    sizes = [pool.FIRST * 2 ** k for k in range(len(cuts))]
    assert [len(part) for part in cuts[:-1]] == sizes[:-1] and 0 < len(cuts[-1]) <= sizes[-1]
    assert sum(cuts, []) == todo
    assert pool.parts(todo[:pool.FIRST]) == [todo[:pool.FIRST]] and pool.parts([]) == []


def test_a_part_never_ends_inside_an_answer():
    todo = list(range(1500))
    labels = [i // 9 for i in range(1500)]  # answers of 9 programs: FIRST is no multiple of 9
    cuts = pool.parts(todo, labels)
    assert sum(cuts, []) == todo and len(cuts) > 2
    for k, (before, after) in enumerate(zip(cuts, cuts[1:])):
        assert labels[before[-1]] != labels[after[0]] and len(before) >= pool.FIRST * 2 ** k


@pytest.fixture
def spied(monkeypatch):
    """Parts of 8 programs; the answers (labels) of the programs each dispatch sent."""
    monkeypatch.setattr(pool, "FIRST", 8)
    calls: list[list[object]] = []
    real = pool.dispatch

    def dispatch(sandbox, items, rows, cols, limits, workers, semantics, mode, groups):
        calls.append(list(groups or [None] * len(items)))
        return real(sandbox, items, rows, cols, limits, workers, semantics, mode, groups)

    monkeypatch.setattr(pool, "dispatch", dispatch)
    return calls


def _mixed() -> tuple[list[str], list[int]]:
    """Answers of 1 to 5 programs: benign ones, the verdicts that each program decides alone
    (DETERMINED), refusals, syntax errors, probes that share a head, and repeats across parts."""
    programs, labels = [], []
    head = "def f(board, colors, x, y):\n    put(board, 'nut', colors[0], x, y)\nboard = init_board(8, 8)\n"
    answers = [[_benign(k)] for k in range(6)] + [DETERMINED[:3], DETERMINED[3:]] \
        + [[head + f"f(board, ['red'], {k}, {k})" for k in range(5)], ["import os", "put(board,", _benign(2)]] \
        + [[_benign(k) + f"\nz = {k}" for k in range(j, j + 4)] for j in range(0, 20, 4)] + [[_benign(1)]]
    for label, answer in enumerate(answers):
        programs += answer
        labels += [label] * len(answer)
    return programs, labels


def test_a_call_in_parts_gives_the_verdicts_of_one_call(spied, monkeypatch):
    programs, labels = _mixed()
    whole_box, parts_box = pool.LocalSandbox(workers=2), pool.LocalSandbox(workers=2)
    try:
        parted = parts_box.execute_many(programs, answers=labels)
        sent = list(spied)
        assert len(sent) >= 3, sent  # really in parts
        monkeypatch.setattr(pool, "FIRST", 10 ** 9)
        spied.clear()
        whole = whole_box.execute_many(programs, answers=labels)
        assert len(spied) == 1
    finally:
        whole_box.close()
        parts_box.close()
    assert parted == whole
    assert [ex.error for ex in whole[6:12]] == [E.SAME_SHAPE_STACKING, E.RESOURCE_LIMIT, E.TIMEOUT, E.FORBIDDEN,
                                               E.KEY_ERROR, E.ZERO_DIVISION]
    assert [ex.cells for ex in whole[12:17]] == [{f"{k}:{k}": [["nut", "red"]]} for k in range(5)]
    assert [ex.error for ex in whole[17:20]] == [E.FORBIDDEN, E.SYNTAX_ERROR, None]
    # the same programs ran (a repeat once: _benign(1) and _benign(2) twice), and no answer's
    # programs were split between parts (each part's answers go one child each: pool.dispatch)
    assert sorted(sum(sent, [])) == sorted(spied[0])
    for k, part in enumerate(sent):
        assert not set(part) & set(sum(sent[k + 1:], []))


def _feeders_ended() -> None:
    for thread in threading.enumerate():
        if thread.name == "sartco-feeder":
            thread.join(10)


def test_a_part_whose_templates_fail_makes_every_verdict_a_harness_error(spied, monkeypatch):
    """Nothing raises out of execute_many, whichever part's dispatch fails; the parts after it
    are not sent (their verdicts would be thrown away)."""
    calls = spied
    real = pool.dispatch
    raised = []

    def second_fails(sandbox, items, *args):
        if len(calls) == 1:
            raised.append(len(items))
            raise OSError("the templates are gone")
        return real(sandbox, items, *args)

    monkeypatch.setattr(pool, "dispatch", second_fails)
    box = pool.LocalSandbox(workers=1)
    try:
        results = box.execute_many([_benign(k) + f"\nz = {k}" for k in range(30)], cache=False)
    finally:
        box.close()
    _feeders_ended()
    assert len(calls) == 1 and raised == [16]  # the first part ran, the second failed, the third was not sent
    assert {(ex.error, ex.message) for ex in results} == {
        (E.HARNESS_ERROR, "sandbox failure: OSError: the templates are gone")}


@pytest.mark.parametrize("where", ["compiling", "waiting"])
def test_an_interrupted_call_does_not_wait_for_the_part_it_sent_and_sends_no_other(spied, monkeypatch, where):
    """Ctrl-C while the parent compiles a later part, or while it waits for a part's verdicts: the
    call ends at once, the part already sent goes on in a daemon thread (a process that ends does
    not wait for it), and no later part is sent (a trainer interrupted in a notebook leaves no
    call running on)."""
    running, finished, release = threading.Event(), threading.Event(), threading.Event()
    compiles, sent = [], []
    prepare_all = pool.compiled.prepare_all

    def blocked(sandbox, items, *args):
        sent.append(len(items))
        if len(sent) == 1:
            running.set()
            release.wait(5)
            finished.set()
        return [failed(E.HARNESS_ERROR, "not run") for _ in items]

    def interrupted(*args):
        running.wait(5)
        raise KeyboardInterrupt

    def compiled(sources, limits):
        compiles.append(len(sources))
        return interrupted() if len(compiles) == 2 else prepare_all(sources, limits)

    monkeypatch.setattr(pool, "dispatch", blocked)
    if where == "compiling":
        monkeypatch.setattr(pool.compiled, "prepare_all", compiled)
    else:
        monkeypatch.setattr(pool._Fed, "result", interrupted)
    box = pool.LocalSandbox(workers=1)
    try:
        with pytest.raises(KeyboardInterrupt):
            box.execute_many([_benign(k) + f"\nz = {k}" for k in range(30)], cache=False)
        assert running.is_set() and not finished.is_set()
        assert all(t.daemon for t in threading.enumerate() if t.name == "sartco-feeder")
        release.set()
        _feeders_ended()
        assert sent == [8]  # parts of 8, 16 and 6 programs: only the first was sent
    finally:
        release.set()
        box.close()
