"""A big call in parts, fed to the templates as it is compiled (feed.py, issue 46): the templates
run one part while the parent compiles the next, each takes its next programs when it runs low,
and the verdicts, their order, the memo and the answers' children are those of one part.
"""
import threading

import pytest

from sartco.program import feed, pool
from sartco.world import ErrorCode

from test_gold_mode import DETERMINED, _benign

E = ErrorCode


def test_parts_double_and_keep_the_order():
    todo = list(range(3, 3000))
    cuts = feed.parts(todo)
    sizes = [feed.FIRST * 2 ** k for k in range(len(cuts))]
    assert [len(part) for part in cuts[:-1]] == sizes[:-1] and 0 < len(cuts[-1]) <= sizes[-1]
    assert sum(cuts, []) == todo
    assert feed.parts(todo[:feed.FIRST]) == [todo[:feed.FIRST]] and feed.parts([]) == []


def test_a_part_never_ends_inside_an_answer():
    todo = list(range(1500))
    labels = [i // 9 for i in range(1500)]  # answers of 9 programs: FIRST is no multiple of 9
    cuts = feed.parts(todo, labels)
    assert sum(cuts, []) == todo and len(cuts) > 2
    for k, (before, after) in enumerate(zip(cuts, cuts[1:])):
        assert labels[before[-1]] != labels[after[0]] and len(before) >= feed.FIRST * 2 ** k


def test_takes_share_what_is_left_and_never_split_an_answer():
    labels = [i // 3 for i in range(300)]  # answers of 3 programs
    fed = feed.Feed(300, 2, labels)
    fed.put(list(range(60)), 60)  # the first part: compiled, the rest not yet
    first = fed.take()
    assert len(first) == 30  # half of what is ready: the other template gets the other half
    fed.put(list(range(60, 300)), 240)
    fed.close()
    takes = [first]
    while batch := fed.take():
        takes.append(batch)
    assert sum(takes, []) == list(range(300))
    assert all(len(t) % 3 == 0 for t in takes)  # whole answers only
    assert len(takes[1]) > len(takes[-2]) >= feed.GRAIN  # shares shrink as the call ends
    assert fed.starts(takes[1]) == frozenset(range(0, len(takes[1]), 3))
    alone = feed.Feed(40, 1)  # one template: all that is ready at once, and then no more
    alone.put(list(range(40)), 40)
    alone.close()
    assert alone.take() == list(range(40)) and alone.done()


def test_a_stopped_feed_hands_out_nothing_more():
    fed = feed.Feed(20, 1)
    fed.put(list(range(10)), 10)
    waiting = []
    taker = threading.Thread(target=lambda: waiting.append((fed.take(), fed.take())))
    taker.start()  # takes the ten, then waits for the next part
    taker.join(0.2)
    assert taker.is_alive()
    fed.stop()
    taker.join(5)
    assert waiting == [(list(range(10)), [])]


@pytest.fixture
def spied(monkeypatch):
    """Parts of 8 programs; the answers (labels) of the programs each take handed out."""
    monkeypatch.setattr(feed, "FIRST", 8)
    takes: list[list[object]] = []
    real = feed.Feed.take

    def take(self):
        batch = real(self)
        if batch:
            takes.append([self.labels[i] if self.labels else None for i in batch])
        return batch

    monkeypatch.setattr(feed.Feed, "take", take)
    return takes


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
        taken = list(spied)
        assert len(taken) >= 3, taken  # really in several takes
        monkeypatch.setattr(feed, "FIRST", 10 ** 9)
        spied.clear()
        whole = whole_box.execute_many(programs, answers=labels)
    finally:
        whole_box.close()
        parts_box.close()
    assert parted == whole
    assert [ex.error for ex in whole[6:12]] == [E.SAME_SHAPE_STACKING, E.RESOURCE_LIMIT, E.TIMEOUT, E.FORBIDDEN,
                                               E.KEY_ERROR, E.ZERO_DIVISION]
    assert [ex.cells for ex in whole[12:17]] == [{f"{k}:{k}": [["nut", "red"]]} for k in range(5)]
    assert [ex.error for ex in whole[17:20]] == [E.FORBIDDEN, E.SYNTAX_ERROR, None]
    # the same programs ran (a repeat once: _benign(1) and _benign(2) twice), and no answer's
    # programs were split between takes (each take's answers go one child each)
    assert sorted(sum(taken, [])) == sorted(sum(spied, []))
    for k, batch in enumerate(taken):
        assert not set(batch) & set(sum(taken[k + 1:], []))


def _feeders_ended() -> None:
    for thread in threading.enumerate():
        if thread.name == "sartco-feeder":
            thread.join(10)


def test_a_dispatch_that_fails_makes_every_verdict_a_harness_error(spied, monkeypatch):
    """Nothing raises out of execute_many when its templates fail while the parent compiles; no
    template takes anything after (its verdict would be thrown away)."""
    def fails(sandbox, fed, *args):
        fed.take()
        raise OSError("the templates are gone")

    monkeypatch.setattr(pool, "dispatch", fails)
    box = pool.LocalSandbox(workers=1)
    try:
        results = box.execute_many([_benign(k) + f"\nz = {k}" for k in range(30)], cache=False)
    finally:
        box.close()
    _feeders_ended()
    assert [len(t) for t in spied] == [8]  # the first part was taken, nothing after the failure
    assert {(ex.error, ex.message) for ex in results} == {
        (E.HARNESS_ERROR, "sandbox failure: OSError: the templates are gone")}


@pytest.mark.parametrize("where", ["compiling", "waiting"])
def test_an_interrupted_call_does_not_wait_for_its_templates_and_feeds_them_no_more(spied, monkeypatch, where):
    """Ctrl-C while the parent compiles a later part, or while it waits for the verdicts: the call
    ends at once, the programs already taken go on in a daemon thread (a process that ends does
    not wait for it), and no template takes more (a trainer interrupted in a notebook leaves no
    call running on)."""
    running, finished, release = threading.Event(), threading.Event(), threading.Event()
    compiles, taken = [], []
    prepare_all = pool.compiled.prepare_all

    def blocked(sandbox, fed, *args):
        taken.append(len(fed.take()))
        running.set()
        release.wait(5)
        taken.append(len(fed.take()))
        finished.set()
        return {}

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
        monkeypatch.setattr(feed.Background, "result", interrupted)
    box = pool.LocalSandbox(workers=1)
    try:
        with pytest.raises(KeyboardInterrupt):
            box.execute_many([_benign(k) + f"\nz = {k}" for k in range(30)], cache=False)
        assert running.is_set() and not finished.is_set()
        assert all(t.daemon for t in threading.enumerate() if t.name == "sartco-feeder")
        release.set()
        _feeders_ended()
        assert taken == [8, 0]  # parts of 8, 16 and 6 programs: only the first was taken
    finally:
        release.set()
        box.close()
