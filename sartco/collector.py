"""Python's cyclic garbage collector, paused for a batch call (issue 46).

A batch (`sartco.reward.score`: hundreds of answers, thousands of programs) makes tens of thousands
of objects that live until its end: the programs' Executions, boards and rewards. The collector
moves them into its oldest generation as they survive its young collections, and when a quarter
as many have moved there as it held, it walks the whole heap of the process: in bench-reward's
process (300,000 objects) about 0.2 s, every second or third call, a sixth of the call's CPU;
in a trainer's process, whose heap is larger, longer. What such a call makes is freed by
reference counting when its results go (it makes no cycles that outlive it), so the collector
has nothing to find there.

`paused()` turns the collector off for the block (or the decorated call) and back on after the
last block that overlapped it ends, if it was on before the first one: calls in several threads
at once, and a caller that keeps it off itself, are both left as they were.
"""
from __future__ import annotations

import gc
import os
import threading
from collections.abc import Iterator
from contextlib import contextmanager

_lock = threading.Lock()
_depth = 0  # blocks running now
_resume = False  # whether the collector was on when the first of them began


@contextmanager
def paused() -> Iterator[None]:
    """The collector off for the block; usable as a decorator (`@paused()`)."""
    global _depth, _resume
    with _lock:
        if _depth == 0:
            _resume = gc.isenabled()
            gc.disable()
        _depth += 1
    try:
        yield
    finally:
        with _lock:
            _depth -= 1
            if _depth == 0 and _resume:
                gc.enable()


def _forked() -> None:
    """In a forked child: no block runs there, whatever ran in the parent's other threads."""
    global _lock, _depth
    _lock = threading.Lock()
    if _depth and _resume:
        gc.enable()
    _depth = 0


os.register_at_fork(after_in_child=_forked)
