"""95 % percentile bootstrap intervals over episodes, for every rate of `sartco report`.

Method (docs/scores.md, "How sure is a number"): a cell's n episodes are resampled with replacement
RESAMPLES = 10,000 times; the interval is the 2.5th and 97.5th percentile of the resampled
means. The generator is numpy's default_rng(SEED), seeded afresh for every cell, so a cell's
interval does not depend on which other cells a report holds. A missing value (an aborted
episode) counts 0, as in the point estimate (files.percent). For a 0/1 metric the resampled mean
is drawn directly as Binomial(n, k/n) / n, which has exactly the distribution of the mean of n
draws with replacement (and is what keeps ~10,000 episodes fast); other metrics (CodeBLEU, cell
F1) are resampled episode by episode.
"""
from __future__ import annotations

import numpy as np

SEED = 20220601          # fixed: the same results folder gives the same intervals
RESAMPLES = 10_000
LEVEL = 0.95
RATES = ("played", "em", "cb", "es", "f1")   # the rates of a report row, by their column names
PROBED_RATES = ("fg",)   # rates of probed episodes only (Function Generalisation): NaN in a row without any


def values(group: list[dict], metric: str) -> np.ndarray:
    """A row's episodes as numbers in [0, 1]: played = not aborted; missing counts 0."""
    if metric == "played":
        return np.array([1.0 - e["aborted"] for e in group], dtype=float)
    return np.array([0.0 if e[metric] is None else e[metric] for e in group], dtype=float)


def resampled_means(x: np.ndarray, rng: np.random.Generator, resamples: int = RESAMPLES) -> np.ndarray:
    """`resamples` bootstrap means of x (rows of x resampled together when x is 2-D: paired data)."""
    n = len(x)
    if x.ndim == 1 and np.isin(x, (0.0, 1.0)).all():
        return rng.binomial(n, x.mean(), size=resamples) / n
    idx = rng.integers(0, n, size=(resamples, n))
    return x[idx].mean(axis=1)


def interval(x, *, seed: int = SEED, resamples: int = RESAMPLES) -> tuple[float, float]:
    """The 95 % percentile bootstrap interval of the mean of x (NaN, NaN when x is empty)."""
    x = np.asarray(x, dtype=float)
    if not len(x):
        return float("nan"), float("nan")
    means = resampled_means(x, np.random.default_rng(seed), resamples)
    lo, hi = np.percentile(means, [50 * (1 - LEVEL), 50 * (1 + LEVEL)])
    return float(lo), float(hi)


def bounds(group: list[dict]) -> dict:
    """`<rate>_lo` and `<rate>_hi` (percent, 2 places) of every rate of a group of episodes."""
    out = {}
    probed = any(e.get("probed") for e in group)
    for metric in RATES + PROBED_RATES:
        lo, hi = interval(values(group, metric) if probed or metric in RATES else [])
        out[f"{metric}_lo"], out[f"{metric}_hi"] = round(100 * lo, 2), round(100 * hi, 2)
    return out


def columns(header: list[str]) -> list[str]:
    """The CSV header with `_lo`/`_hi` after every rate column."""
    return [c for h in header for c in ((h, f"{h}_lo", f"{h}_hi") if h in RATES + PROBED_RATES else (h,))]


def shown(row: dict, metric: str) -> str:
    """`x [lo, hi]` for Markdown ("n/a": a rate the row's episodes do not have, as FG of unprobed cells)."""
    if row[metric] != row[metric]:
        return "n/a"
    return f"{row[metric]:.2f} [{row[f'{metric}_lo']:.2f}, {row[f'{metric}_hi']:.2f}]"


def shown_counts(successes: int, n: int) -> str:
    """`x [lo, hi]` (percent) of a 0/1 rate given as a count of successes out of n."""
    lo, hi = interval(np.r_[np.ones(successes), np.zeros(n - successes)])
    return f"{100 * successes / n:.2f} [{100 * lo:.2f}, {100 * hi:.2f}]" if n else "nan"
