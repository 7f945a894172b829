"""Mode "answer" (issue 46): the programs of one model answer (its function probes) share a confined
child, never with another answer's, and every verdict equals the one a child per program gives.
"""
import pytest

from sartco.program import Limits, compiled, execute_many, handle, pool
from sartco.world import ErrorCode

from test_gold_mode import ATTACKS, DETERMINED, _benign

E = ErrorCode


@pytest.fixture
def chunks(monkeypatch):
    """A fresh local sandbox (one template) and the (mode, items) of every chunk sent to it."""
    sent: list[tuple[str, int]] = []
    real = handle.TemplateHandle._send

    def spy(self, stdin, items, rows, cols, limits, semantics, mode, starts=frozenset()):
        sent.extend((mode, len(chunk)) for chunk in handle._chunks(items, starts))
        return real(self, stdin, items, rows, cols, limits, semantics, mode, starts)

    monkeypatch.setattr(handle.TemplateHandle, "_send", spy)
    box = pool.LocalSandbox(workers=1)
    yield box, sent
    box.close()


def test_each_answers_programs_go_in_a_chunk_of_their_own(chunks):
    box, sent = chunks
    programs = [_benign(i) for i in range(11)]
    labels = ["a"] * 4 + ["b"] * 5 + ["c"] * 2
    results = box.execute_many(programs, cache=False, answers=labels)
    assert sent == [("answer", 4), ("answer", 5), ("answer", 2)]
    assert all(ex.ok for ex in results)
    assert [ex.cells for ex in results] == [{f"{i % 8}:{i // 8 % 8}": [["nut", "red"]]} for i in range(11)]


def test_two_templates_never_split_an_answer(monkeypatch):
    """Shares are balanced by whole answers: every chunk holds one answer's programs."""
    sent: list[list[bytes]] = []
    real = handle.TemplateHandle._send

    def spy(self, stdin, items, rows, cols, limits, semantics, mode, starts=frozenset()):
        sent.extend(handle._chunks(items, starts))
        return real(self, stdin, items, rows, cols, limits, semantics, mode, starts)

    monkeypatch.setattr(handle.TemplateHandle, "_send", spy)
    box = pool.LocalSandbox(workers=2)
    try:
        programs = [_benign(i) + f"\nz = {i}" for i in range(80)]  # 80 distinct codes
        results = box.execute_many(programs, cache=False, answers=[i // 8 for i in range(80)])
    finally:
        box.close()
    assert all(ex.ok for ex in results)
    answer_of = {compiled.prepare(p, Limits()): i // 8 for i, p in enumerate(programs)}
    assert sorted(sorted(answer_of[item] for item in chunk) for chunk in sent) == [[k] * 8 for k in range(10)]


def test_answer_mode_gives_the_verdicts_of_a_child_per_program():
    programs = [_benign(i) for i in range(3)] + DETERMINED + [_benign(i) for i in range(3, 6)]
    alone = execute_many(programs, cache=False)
    shared = execute_many(programs, cache=False, answers=[0] * len(programs))
    assert shared == alone
    assert [ex.error for ex in shared[3:9]] == [E.SAME_SHAPE_STACKING, E.RESOURCE_LIMIT, E.TIMEOUT, E.FORBIDDEN,
                                               E.KEY_ERROR, E.ZERO_DIVISION]


@pytest.mark.parametrize("attack", range(len(ATTACKS)))
def test_what_an_answers_program_leaves_behind_reaches_no_verdict_after_it(attack):
    programs = [_benign(i) for i in range(3)] + [ATTACKS[attack]] + [_benign(i) for i in range(3, 9)]
    results = execute_many(programs, limits=Limits(wall_time=1.0), cache=False, answers=[7] * len(programs))
    for i, ex in enumerate(results):
        if i != 3:
            assert ex.ok and ex.cells == {f"{j % 8}:{j // 8 % 8}": [["nut", "red"]]
                                          for j in [i if i < 3 else i - 1]}, (i, ex.message)


def test_a_shared_childs_answers_are_read_for_their_error_code_as_json_reads_them():
    import json

    from sartco.program.child.batch import UNSURE, outcome
    from sartco.program.child.runtime import encode

    class Logged:
        rows, cols, log = 8, 8, [(("nut", "red"), 0, 0), (("bridge-h", "blue"), 1, 2)]

    for ok, code in [(True, None)] + [(False, c) for c in ErrorCode]:
        for message in ("", 'line 3: "quoted", [bracketed], null'):
            for board in (None, Logged()):
                answer = encode(ok, code, message, board)
                assert outcome(answer) == ("" if code is None else json.loads(answer)[1]) == (code or "")
    assert outcome(encode(False, E.RESOURCE_LIMIT, "", None)) in UNSURE
    # what runtime.encode never writes goes through the JSON reading: no answer
    for other in (b"", b"[true, null", b'[false, 3, ""]', b'{"ok": true}', b"[true]", b"\xff"):
        assert outcome(other) is None, other
