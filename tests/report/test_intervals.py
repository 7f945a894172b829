"""The bootstrap intervals of `sartco report` (sartco.report.intervals): a synthetic cell with
a known rate is covered at about the documented 95 %, and the report shows them."""
import numpy as np
import pytest

from sartco.report import intervals


def coverage(draw, truth: float, cells: int, seed: int) -> float:
    rng = np.random.default_rng(seed)
    hits = 0
    for _ in range(cells):
        lo, hi = intervals.interval(draw(rng))
        hits += lo <= truth <= hi
    return hits / cells


def test_a_binary_rate_is_covered_at_about_95_percent():
    # ES of a cell of 130 episodes at a true rate of 0.30 (the example), 1,000 cells
    share = coverage(lambda rng: (rng.random(130) < 0.30).astype(float), 0.30, 1000, seed=1)
    assert 0.935 <= share <= 0.965, share   # 95 % +- 2 standard errors of 1,000 cells


def test_a_continuous_rate_is_covered_at_about_95_percent():
    # CodeBLEU-like scores in [0, 1] (Beta(2, 5), mean 2/7), resampled episode by episode
    share = coverage(lambda rng: rng.beta(2, 5, 130), 2 / 7, 200, seed=2)
    assert 0.90 <= share <= 0.98, share


def test_the_binary_shortcut_matches_resampling():
    x = np.r_[np.ones(39), np.zeros(91)]
    fast = intervals.interval(x)
    rng = np.random.default_rng(intervals.SEED)
    slow = np.percentile(x[rng.integers(0, len(x), (intervals.RESAMPLES, len(x)))].mean(1), [2.5, 97.5])
    assert fast == pytest.approx(tuple(slow), abs=0.012)   # same distribution, other draws


def test_fixed_seed_and_edge_cases():
    x = np.random.default_rng(3).random(40)
    assert intervals.interval(x) == intervals.interval(x)
    assert intervals.interval(np.ones(5)) == (1.0, 1.0)
    assert all(np.isnan(v) for v in intervals.interval([]))


def test_bounds_count_a_missing_score_as_zero():
    group = [{"aborted": 1, "em": None, "cb": None, "es": None, "f1": None}] * 3 + \
            [{"aborted": 0, "em": 1.0, "cb": 0.5, "es": 1.0, "f1": 1.0}]
    b = intervals.bounds(group)
    assert (b["es_lo"], b["es_hi"], b["cb_hi"], b["played_lo"]) == (0.0, 75.0, 37.5, 0.0)  # 1 of 4 played
    assert intervals.columns(["model", "es"]) == ["model", "es", "es_lo", "es_hi"]
    assert intervals.shown({"es": 25.0, "es_lo": 0.0, "es_hi": 75.0}, "es") == "25.00 [0.00, 75.00]"
