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
    assert [i for i, _ in seen] == list(range(5)) and {name for _, name in seen} == {"sartco-ahead"}
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
