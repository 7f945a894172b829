"""Work started at an episode's setup on the background thread (sartco.clem.core.ahead): done
there, in order, and the step's result is the same as without it."""
from __future__ import annotations

import threading

from sartco.clem.core import ahead
from sartco.scores import code_bleu_detail, metrics

GOLD = "def tower(board, colors, x, y):\n    for i, c in enumerate(colors):\n        put(board, 'washer', c, x, y)\n\ntower(board, ['red', 'blue'], 1, 2)\n"
ANSWER = "for c in ['red', 'blue']:\n    put(board, 'washer', c, 1, 2)\n"


def test_work_runs_on_the_background_thread_in_the_order_submitted():
    seen = []
    futures = [ahead.submit(lambda i=i: seen.append((i, threading.current_thread().name)) or i) for i in range(5)]
    assert [f.result(timeout=60) for f in futures] == list(range(5))
    assert [i for i, _ in seen] == list(range(5)) and {name for _, name in seen} == {"sartco-ahead-setup"}
    failing = ahead.submit(lambda: 1 / 0)
    assert isinstance(failing.exception(timeout=60), ZeroDivisionError)   # left to the step
    assert ahead.submit(lambda: "after").result(timeout=60) == "after"   # the thread goes on


def test_the_gold_analysed_ahead_gives_the_same_codebleu_and_the_step_only_reads_it():
    metrics._analyse.cache_clear()
    metrics._code_bleu.cache_clear()
    cold = code_bleu_detail(ANSWER, GOLD)   # both analyses in the step
    metrics._analyse.cache_clear()
    metrics._code_bleu.cache_clear()
    ahead.submit(lambda: metrics.analyse_gold(GOLD)).result(timeout=60)
    before = metrics._analyse.cache_info()
    assert before.currsize == 1
    assert code_bleu_detail(ANSWER, GOLD) == cold
    after = metrics._analyse.cache_info()
    assert (after.hits - before.hits, after.misses - before.misses) == (1, 1)   # the gold read, the answer analysed
    metrics.analyse_gold("")   # nothing to analyse: no error, nothing kept
    metrics.analyse_gold("x = (" * 10)   # what codebleu cannot parse is left to the step, which says why


def _episode():
    import json
    from pathlib import Path

    data = json.loads((Path(__file__).resolve().parents[2] / "games" / "cobot_instruct" / "in" / "instances.json").read_text())
    return next(ep for e in data["experiments"] for ep in e["game_instances"] if ep["task"] == "optimal_function")


def _begun(answer_builds, episode, code) -> None:
    """Wait until the build started for `code` has begun on its lane (a step drops one that has not)."""
    import time

    future = answer_builds._started._futures[answer_builds._build_key(episode, code, [code])]
    while not (future.running() or future.done()):
        time.sleep(0.001)


def test_a_build_started_when_its_answer_came_in_is_the_one_the_step_takes(monkeypatch):
    """answer_builds.start_build (the builder's answer came in) builds on the "answers" lane;
    build_for takes that build: the same record as a build in the step. A build that has not
    begun is dropped and built in the step (no step waits behind another's); one that failed
    there is built again in the step."""
    from sartco.clem.core import answer_builds, building

    episode = _episode()
    code, codes = episode["gold_code"], [episode["gold_code"]]
    real, built_in = building.build, []

    def counted(*args, **kwargs):
        built_in.append(threading.current_thread().name)
        return real(*args, **kwargs)

    monkeypatch.setattr(building, "build", counted)
    own = answer_builds.build_for(episode, code, turn_codes=codes)
    assert built_in == ["MainThread"] and own.es == 1
    answer_builds.start_build(episode, code, turn_codes=codes)
    answer_builds.start_build(episode, code, turn_codes=codes)   # once per answer
    _begun(answer_builds, episode, code)
    assert answer_builds.build_for(episode, code, turn_codes=codes).to_json() == own.to_json()
    assert built_in[1:] == ["sartco-ahead-answers"]
    assert answer_builds._build_key(episode, code, codes) not in answer_builds._started._futures   # taken

    held, release = threading.Event(), threading.Event()
    ahead.submit(lambda: held.set() or release.wait(60), lane="answers")   # the lane is busy
    held.wait(60)
    answer_builds.start_build(episode, code, turn_codes=codes)
    assert answer_builds.build_for(episode, code, turn_codes=codes).to_json() == own.to_json()
    assert built_in[-1] == "MainThread"   # built in the step, not waited for
    release.set()

    def failing(*args, **kwargs):
        if threading.current_thread().name == "sartco-ahead-answers":
            raise RuntimeError("the sandbox failed here")
        return counted(*args, **kwargs)

    monkeypatch.setattr(building, "build", failing)
    answer_builds.start_build(episode, code, turn_codes=codes)
    _begun(answer_builds, episode, code)
    assert answer_builds.build_for(episode, code, turn_codes=codes).to_json() == own.to_json()
    assert built_in[-1] == "MainThread" and len(built_in) == 4


def test_a_process_forked_while_work_was_started_takes_none_of_it_and_starts_its_own():
    """A process forked (a trainer's own multiprocessing) while the parent held a Started's lock
    and had work started there: the child has a lock of its own, nothing started (the parent's
    futures would never end in it: their thread is not forked), and starts and takes its own."""
    from fork_helpers import forked_while_held

    started = ahead.Started("test-fork", 8)
    release = threading.Event()
    started.start("parent's", lambda: release.wait(60))   # running in the parent when it forks

    def own() -> bool:
        nothing = len(started) == 0 and started.take("parent's", wait_queued=True) is None
        started.start("child's", lambda: "mine")
        return nothing and started.take("child's", wait_queued=True) == "mine"

    assert forked_while_held(started._lock, own, seconds=60) == 0
    release.set()
    assert started.take("parent's", wait_queued=True) is True   # the parent's own work, taken in the parent
