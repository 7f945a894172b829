"""An answer's build and its function probes run in one confined child (sartco.clem.core.sandbox.together,
as sartco.reward.core.score uses it), with the rewards of a child per program: the gold and the
erring player's answers, a build that runs out of steps (the programs after it in the child then
run again, each in its own), a function that draws random numbers, an answer without code; and
a sandbox that fails them all ahead, after which they run as before."""
from __future__ import annotations

import contextlib
import json
from collections import Counter

import pytest

from play_helpers import GAMES, fence
from sartco.clem.core import sandbox
from sartco.clem.players.answers import instruct_answers
from sartco.program import Execution
from sartco.reward import Episodes, core, score
from sartco.world import ErrorCode

SMOKE = GAMES / "cobot_instruct" / "in" / "instances_smoke.json"
RANDOM = """import random
def f(board, colors, x, y):
    random.seed(x)
    put(board, 'nut', colors[random.randrange(len(colors))], x, y)
f(board, ['red', 'blue'], 1, 1)"""


@pytest.fixture(scope="module")
def pairs() -> tuple[Episodes, list]:
    episodes = Episodes.from_files([SMOKE])
    out = []
    for key, instance in episodes.items():
        turns = len(instance["turns"])
        for player in ("mock", "erring"):
            source = instruct_answers(player, instance)
            answers = [source.answer(t) for t in range(turns)]
            out.append((key, answers[0] if turns == 1 else answers))
        if instance["task"] in ("optimal_function", "repetition"):
            out += [(key, fence("while True:\n    pass")), (key, fence(RANDOM)), (key, "no code here")]
    return episodes, out


def _rewards(episodes: Episodes, pairs: list) -> list[str]:
    sandbox.restart()  # no verdict kept from a run before
    return [json.dumps([r.id, r.es, r.cell_f1, r.category, r.puts, r.aborted, r.function_generalisation,
                        r.probe_categories, r.message, r.scores], sort_keys=True, default=str)
            for r in score(pairs, episodes, probes=True)]


def test_the_rewards_are_those_of_a_child_per_program(pairs, monkeypatch):
    episodes, given = pairs
    together = _rewards(episodes, given)
    monkeypatch.setattr(core, "together", lambda answers: contextlib.nullcontext())
    assert _rewards(episodes, given) == together
    assert any('"timeout"' in r for r in together) and any('"parse_error"' in r for r in together)


def test_an_answers_build_and_probes_share_one_call_and_one_label(pairs, monkeypatch):
    episodes, given = pairs
    calls = []
    real = sandbox.execute_many

    def counted(programs, rows, cols, **kw):
        calls.append((list(programs), kw.get("answers")))
        return real(programs, rows, cols, **kw)

    monkeypatch.setattr(sandbox, "execute_many", counted)
    sandbox.restart()
    rewards = score(given, episodes, probes=True)
    probed = [r for r in rewards if r.function_generalisation is not None]
    assert probed and all(len(r.probe_categories) == 8 for r in probed)
    [(programs, labels)] = calls   # one board size: one sandbox call, nothing run again after it
    with_code = [r for r in rewards if not r.aborted]
    assert len(set(labels)) == len(with_code)   # one label, so one child, per answer with code
    sizes = Counter(labels)   # a build alone, or a build and its 8 probes
    assert set(sizes.values()) == {1, 9} and sum(sizes.values()) == len(programs)


def test_a_sandbox_failure_ahead_runs_the_programs_again(pairs, monkeypatch):
    episodes, given = pairs
    expected = _rewards(episodes, given)
    real, calls = sandbox.execute_many, []

    def failing_first(programs, rows, cols, **kw):
        calls.append(len(programs))
        if len(calls) == 1:   # together's call: the sandbox fails every program
            return [Execution(False, ErrorCode.HARNESS_ERROR, "sandbox failure: a test's") for _ in programs]
        return real(programs, rows, cols, **kw)

    monkeypatch.setattr(sandbox, "execute_many", failing_first)
    assert _rewards(episodes, given) == expected
    assert len(calls) == 3   # together's, then the builds' and the probes' own
