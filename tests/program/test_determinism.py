"""The same program builds the same board in every worker, run and machine.

Order-sensitive programs (set and dict-of-set iteration, hash() of a str) run in several fresh
workers of this process and in fresh processes whose own environment differs (another or a random
hash seed, PYTHONOPTIMIZE, PYTHONPATH): one answer each. Workers get PYTHONHASHSEED=0 and
nothing else of the parent's PYTHON* variables (handle.py).
"""
import json
import os
import subprocess
import sys

import pytest

from sartco.program import execute, shutdown

ORDERED = {
    "the issue's set enumerate": "for i, c in enumerate({'red', 'green', 'blue', 'yellow'}):\n"
                                 "    put(board, 'washer', c, 7, i)",
    "a dict of sets": "d = {'a': {'nut', 'washer', 'screw'}, 'b': {'red', 'blue', 'green', 'yellow'}}\n"
                      "for x, s in enumerate(d['a']):\n    for y, c in enumerate(d['b']):\n"
                      "        put(board, s, c, x, y)",
    "a set of tuples": "cells = {(str(i), 'red') for i in range(6)}\nfor y, (k, c) in enumerate(cells):\n"
                       "    put(board, 'washer', c, int(k), y)",
    "hash of a str": "put(board, 'washer', 'red', hash('washer') % 8, hash('red') % 8)",
    "set arithmetic": "s = {'blue', 'red'} | {'green'} - {'red'}\nput(board, 'nut', s.pop(), 0, 0)\n"
                      "put(board, 'nut', s.pop(), 1, 0)",
}
FRESH_WORKERS = 4


def _answers(program: str) -> set:
    seen = set()
    for _ in range(FRESH_WORKERS):
        shutdown()  # the next call starts a fresh worker
        ex = execute(program)
        assert ex.ok, ex
        seen.add(json.dumps(ex.cells, sort_keys=True))
    return seen


@pytest.mark.parametrize("name", list(ORDERED))
def test_one_answer_in_fresh_workers(name):
    assert len(_answers(ORDERED[name])) == 1


RUN_ALL = ("import json, sys\nfrom sartco.program import execute_many\n"
           "print(json.dumps([[e.ok, e.cells] for e in execute_many(json.loads(sys.stdin.read()))], sort_keys=True))")


def test_one_answer_across_processes_with_other_environments():
    programs = [*ORDERED.values(), "assert False"]  # -O in a worker would skip the assert
    outputs = set()
    for extra in ({"PYTHONHASHSEED": "1"}, {"PYTHONHASHSEED": "random"}, {"PYTHONHASHSEED": "12345"},
                  {"PYTHONOPTIMIZE": "2", "PYTHONPATH": "/nonexistent"}):
        env = {**os.environ, **extra}
        proc = subprocess.run([sys.executable, "-c", RUN_ALL], input=json.dumps(programs), env=env,
                              capture_output=True, text=True, timeout=300)
        assert proc.returncode == 0, proc.stderr
        outputs.add(proc.stdout)
    assert len(outputs) == 1
    assert json.loads(outputs.pop())[-1] == [False, {}]
