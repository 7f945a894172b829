"""EpisodeScore: recorded facts -> one frozen, JSON-ready record."""
from __future__ import annotations

import dataclasses
import json
import math
from types import SimpleNamespace

import pytest

from sartco.scores import EpisodeScore
from sartco.world import ErrorCode

GOLD = "board = init_board(8, 8)\nput(board, 'washer', 'red', 7, 3)\nput(board, 'nut', 'blue', 7, 3)"


def _ex(ok=True, error=None, message="", puts=2):
    return SimpleNamespace(ok=ok, error=error, message=message, cells={}, puts=puts)


def _cmp(es=1, category=None, p=1.0, r=1.0, f1=1.0):
    return SimpleNamespace(es=es, category=category, precision=p, recall=r, f1=f1)


def test_a_perfect_episode():
    score = EpisodeScore.from_run(GOLD + "\n", GOLD, _ex(), _cmp())
    assert (score.em, score.es, score.category, score.puts, score.aborted) == (1, 1, None, 2, False)
    assert score.codebleu == pytest.approx(1.0)
    assert score.main_score == 100.0


def test_a_program_error_wins_over_the_mismatch_category():
    ex = _ex(ok=False, error=ErrorCode.NOT_ON_TOP_OF_SCREW, message="cell (7, 3) has a screw on top", puts=1)
    score = EpisodeScore.from_run(GOLD, GOLD, ex, _cmp(es=0, category=ErrorCode.MISMATCH_COUNT, p=1.0, r=0.5, f1=0.667))
    assert score.es == 0 and score.category is ErrorCode.NOT_ON_TOP_OF_SCREW
    assert score.error == "cell (7, 3) has a screw on top" and score.recall == 0.5
    assert score.main_score == 0.0


def test_a_mismatch():
    score = EpisodeScore.from_run(GOLD.replace("red", "green"), GOLD, _ex(), _cmp(es=0, category="mismatch_color", p=0.5, r=0.5, f1=0.5))
    assert score.category is ErrorCode.MISMATCH_COLOR and score.em == 0 and 0 < score.codebleu < 1


def test_an_aborted_episode_has_a_nan_main_score():
    score = EpisodeScore.from_abort("no code found in the answer", gold=GOLD)
    assert score.aborted and math.isnan(score.main_score)
    assert (score.em, score.codebleu, score.es, score.category) == (0, 0.0, 0, ErrorCode.PARSE_ERROR)


def test_without_gold_code_em_and_codebleu_are_none():
    score = EpisodeScore.from_run("put(board, 'nut', 'red', 0, 0)", None, _ex(), _cmp())
    assert score.em is None and score.codebleu is None
    assert EpisodeScore.from_abort("no code").em is None


def test_round_trip_through_json():
    for score in (EpisodeScore.from_run(GOLD, GOLD, _ex(), _cmp()), EpisodeScore.from_abort("no code", gold=GOLD),
                  EpisodeScore.from_run(GOLD, GOLD, _ex(ok=False, error=ErrorCode.TIMEOUT, message="slow"), _cmp(es=0))):
        data = json.loads(json.dumps(score.as_dict()))
        assert list(data) == ["em", "codebleu", "es", "precision", "recall", "f1", "category", "puts", "error", "aborted"]
        assert EpisodeScore.from_dict(data) == score


def test_it_is_a_frozen_slotted_record():
    score = EpisodeScore.from_abort("x")
    with pytest.raises(dataclasses.FrozenInstanceError):
        score.es = 1  # type: ignore[misc]
    assert not hasattr(score, "__dict__")
    with pytest.raises(ValueError, match="unknown field"):
        EpisodeScore.from_dict({**score.as_dict(), "bogus": 1})
