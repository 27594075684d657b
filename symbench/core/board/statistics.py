"""The boards' statistics over seeds: confidence intervals of means, rank bands, and the
aggregate across robots (docs/leaderboard-protocol.md#statistics says why each method).

A board has 3 to 5 seeds per run group, so every method is chosen to stay honest at that
size. The resamples come from fixed seeds, so the same records give the same board bytes.
The aggregate follows rliable (Agarwal et al. 2021: stratified bootstrap, interquartile
mean, probability of improvement) in numpy: rliable's own bootstrap imports `arch` < 8,
which fails to import beside pandas 3, and it draws from numpy's global random state.
"""

from __future__ import annotations

import functools
from collections.abc import Mapping, Sequence
from dataclasses import dataclass

import numpy as np
import pandas as pd
from scipy import stats

from symbench.core.common import portable_math

CONFIDENCE = 0.95  # of every interval
LEVEL = 0.05  # of the paired test that splits rank bands (two-sided, unadjusted)
RESAMPLES = 10_000
BOOTSTRAP_SEED = 0


@dataclass(frozen=True)
class Interval:
    """A point estimate with its 95 % bootstrap interval (NaN bounds: fewer than 2 seeds)."""

    value: float
    low: float
    high: float


@functools.cache
def _resamples(n: int) -> np.ndarray:
    """RESAMPLES draws of n seed positions with replacement, the same for every cell of n
    seeds: a cell's interval depends on its own values only, never on the other cells."""
    return np.random.default_rng([BOOTSTRAP_SEED, n]).integers(0, n, size=(RESAMPLES, n))


def _bounds(samples: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The percentile interval of bootstrap samples along their first axis."""
    tail = 100 * (1 - CONFIDENCE) / 2
    low, high = np.percentile(samples, [tail, 100 - tail], axis=0)
    return low, high


def mean_interval(values: Sequence[float]) -> tuple[float, float]:
    """The percentile bootstrap interval of the mean over seeds (missing values left out);
    NaN bounds below two values. With 3 seeds it is the range of the values."""
    x = np.asarray(values, dtype=float)
    x = x[~np.isnan(x)]
    if len(x) < 2:
        return np.nan, np.nan
    low, high = _bounds(x[_resamples(len(x))].mean(axis=1))
    return float(low), float(high)


def t_interval(samples: Sequence[float]) -> Interval:
    """The mean of per-seed `samples` (paired differences, or log ratios) with its two-sided
    Student-t interval at CONFIDENCE: the rank bands' paired test as an interval, so that a
    claim's verdict and the bands agree. NaN bounds below two samples."""
    x = np.asarray(samples, dtype=float)
    mean = float(x.mean())
    if len(x) < 2:
        return Interval(mean, np.nan, np.nan)
    half = _critical_t(len(x) - 1) * float(x.std(ddof=1)) / np.sqrt(len(x))
    return Interval(mean, mean - half, mean + half)


def welch_interval(a: Sequence[float], b: Sequence[float]) -> Interval:
    """mean(a) - mean(b) with its Welch interval at CONFIDENCE, for samples that do not pair
    up (two datasets' seeds). NaN bounds below two samples on either side."""
    x, y = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    difference = float(x.mean() - y.mean())
    if min(len(x), len(y)) < 2:
        return Interval(difference, np.nan, np.nan)
    vx, vy = x.var(ddof=1) / len(x), y.var(ddof=1) / len(y)
    if vx + vy == 0:
        return Interval(difference, difference, difference)
    dof = (vx + vy) ** 2 / (vx**2 / (len(x) - 1) + vy**2 / (len(y) - 1))
    half = float(stats.t.ppf(1 - LEVEL / 2, dof)) * float(np.sqrt(vx + vy))
    return Interval(difference, difference - half, difference + half)


def differ(a: Mapping[int, float], b: Mapping[int, float]) -> bool:
    """Whether two models' test RMSEs differ: a two-sided paired t-test at LEVEL on the log
    RMSE of the seeds both have (a seed fixes the split and the initialization). Below two
    common seeds nothing can be told apart; with no spread the difference is exact."""
    common = sorted(set(a) & set(b))
    if len(common) < 2:
        return False
    d = portable_math.log([a[s] for s in common]) - portable_math.log([b[s] for s in common])
    spread = np.std(d, ddof=1)
    if spread == 0:
        return bool(d[0] != 0)
    return bool(abs(np.mean(d)) / (spread / np.sqrt(len(d))) > _critical_t(len(d) - 1))


@functools.cache
def _critical_t(dof: int) -> float:
    """The two-sided critical value of Student's t at LEVEL (4.30 for 3 seeds, 2.78 for 5)."""
    return float(stats.t.ppf(1 - LEVEL / 2, dof))


def rank_bands(rmse: Sequence[Mapping[int, float]]) -> list[str]:
    """Each model's rank band among `rmse` (its test RMSE by seed): from 1 + the number of
    models significantly better, to the number of models not significantly worse; "2" when
    both ends meet, "1-3" when it cannot be told apart from its neighbours."""
    means = [float(np.mean(list(r.values()))) for r in rmse]
    bands = []
    for i, own in enumerate(rmse):
        split = [differ(own, other) for other in rmse]
        better = sum(s and m < means[i] for s, m in zip(split, means))
        worse = sum(s and m > means[i] for s, m in zip(split, means))
        low, high = 1 + better, len(rmse) - worse
        bands.append(str(low) if low == high else f"{low}-{high}")
    return bands


@dataclass(frozen=True)
class Aggregate:
    """The models across tasks (dataset and split): the interquartile mean of normalized
    errors per model, and per ordered pair the probability that the first improves on the
    second, each with a stratified bootstrap interval."""

    tasks: int
    seeds: int  # (task, seed) pairs per model
    iqm: dict[str, Interval]
    improvement: dict[tuple[str, str], Interval]


def across_tasks(tasks: Sequence[pd.DataFrame]) -> Aggregate:
    """The aggregate of `tasks`, each a seeds x models frame of test RMSE (the same models
    in each, seeds paired within a task). A seed's normalized error is its RMSE over the
    lowest mean RMSE of any model on its task (1: the best model's mean). The stratified
    bootstrap resamples seeds within each task, the same seeds for every model."""
    models = list(tasks[0].columns)
    normalized = [t[models].to_numpy() / t[models].mean().min() for t in tasks]
    rng = np.random.default_rng(BOOTSTRAP_SEED)
    resampled = [v[rng.integers(0, len(v), size=(RESAMPLES, len(v)))] for v in normalized]
    iqm = _iqm(np.concatenate(normalized)), _iqm(np.concatenate(resampled, axis=1), axis=1)
    wins = np.mean([_wins(v) for v in normalized], axis=0)
    wins_resampled = np.mean([_wins(v, axis=1) for v in resampled], axis=0)
    iqm_low, iqm_high = _bounds(iqm[1])
    win_low, win_high = _bounds(wins_resampled)
    return Aggregate(
        tasks=len(tasks),
        seeds=sum(len(v) for v in normalized),
        iqm={m: Interval(iqm[0][k], iqm_low[k], iqm_high[k]) for k, m in enumerate(models)},
        improvement={
            (x, y): Interval(wins[i, j], win_low[i, j], win_high[i, j])
            for i, x in enumerate(models)
            for j, y in enumerate(models)
            if i != j
        },
    )


def _iqm(errors: np.ndarray, axis: int = 0) -> np.ndarray:
    """The interquartile mean (25 % trimmed from each end) over the (task, seed) axis."""
    return np.asarray(stats.trim_mean(errors, 0.25, axis=axis))


def _wins(errors: np.ndarray, axis: int = 0) -> np.ndarray:
    """[i, j]: the share of seeds on which model i's error is below model j's (a tie
    counts one half), over the seed `axis` of `errors` (..., seeds, models)."""
    x, y = errors[..., :, None], errors[..., None, :]
    return np.mean((x < y) + 0.5 * (x == y), axis=axis)
