"""The cyclic collector paused for a batch call (sartco.collector, issue 46): off while `score`
runs, and afterwards as the caller had it, with calls in several threads and after an error."""
from __future__ import annotations

import gc
import os
import threading

import pytest

from sartco import collector
from sartco.reward import Episodes, core, score


@pytest.fixture
def collecting():
    """The collector on; as it was afterwards."""
    was = gc.isenabled()
    gc.enable()
    yield
    (gc.enable if was else gc.disable)()


def test_a_block_pauses_the_collector_and_an_error_still_resumes_it(collecting):
    with collector.paused():
        assert not gc.isenabled()
    assert gc.isenabled()
    with pytest.raises(KeyError):
        with collector.paused():
            raise KeyError("x")
    assert gc.isenabled()


def test_a_caller_that_keeps_it_off_finds_it_off(collecting):
    gc.disable()
    with collector.paused():
        pass
    assert not gc.isenabled()


def test_overlapping_blocks_in_threads_resume_it_after_the_last(collecting):
    first_in, second_in, first_out = threading.Event(), threading.Event(), threading.Event()
    seen = []

    def first():
        with collector.paused():
            first_in.set()
            second_in.wait(10)
        seen.append(("first ended", gc.isenabled()))
        first_out.set()

    def second():
        first_in.wait(10)
        with collector.paused():
            second_in.set()
            first_out.wait(10)
            seen.append(("second still in", gc.isenabled()))
        seen.append(("second ended", gc.isenabled()))

    threads = [threading.Thread(target=first), threading.Thread(target=second)]
    for t in threads:
        t.start()
    for t in threads:
        t.join(20)
    assert seen == [("first ended", False), ("second still in", False), ("second ended", True)]


def test_a_child_forked_inside_a_block_collects(collecting):
    with collector.paused():
        pid = os.fork()
        if pid == 0:  # the child: no block runs here
            os._exit(0 if gc.isenabled() else 1)
        _, status = os.waitpid(pid, 0)
    assert os.waitstatus_to_exitcode(status) == 0


def test_score_runs_with_the_collector_off(collecting, monkeypatch):
    seen = []
    real = core.build_jobs

    def spy(jobs):
        seen.append(gc.isenabled())
        return real(jobs)

    monkeypatch.setattr(core, "build_jobs", spy)
    instance = {"turns": ["Build it."], "task": "sequence_function", "rows": 8, "cols": 8, "given_code": "",
                "gold_code": "put(board, 'nut', 'red', 0, 0)", "target": {"0:0": [["nut", "red"]]},
                "board_id": "b", "combo_name": "n"}
    episodes = Episodes({"e/1": instance})
    [reward] = score([("e/1", "```python\nput(board, 'nut', 'red', 0, 0)\n```")], episodes)
    assert seen == [False] and gc.isenabled()
    assert reward.es == 1
    with pytest.raises(ValueError):
        score([("nope", "x")], episodes)
    assert gc.isenabled()
