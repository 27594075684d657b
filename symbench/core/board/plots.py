"""Plots shared by evaluators and leaderboards (matplotlib, headless)."""

from __future__ import annotations

import io
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from symbench.core.common.atomic import write_bytes_atomic


@dataclass(frozen=True)
class Spread:
    """A mean over seeds, its 95 % bootstrap interval (NaN: one seed) and the seeds' own
    values: plots show all three, so that a reader sees how few seeds the interval rests on."""

    mean: float
    low: float
    high: float
    seeds: tuple[float, ...]


Curve = tuple[Sequence[float], Sequence[Spread]]  # x, and a spread at each x
# one run's curve (the sample-efficiency evaluator's plot of a single seed): x, values, None
RunCurve = tuple[Sequence[float], Sequence[float], None]


def _yerr(spreads: Sequence[Spread]) -> np.ndarray:
    """The intervals as matplotlib's asymmetric error bars (none for a single seed)."""
    means = np.array([s.mean for s in spreads])
    below = means - np.array([s.low for s in spreads])
    above = np.array([s.high for s in spreads]) - means
    bars: np.ndarray = np.nan_to_num(np.vstack([below, above]))
    return bars


def _seed_points(ax: Any, x: Sequence[float], spreads: Sequence[Spread], color: Any) -> None:
    """Each seed's value as a small dot at its spread's x."""
    xs = [xi for xi, s in zip(x, spreads) for _ in s.seeds]
    ys = [value for s in spreads for value in s.seeds]
    ax.scatter(xs, ys, s=9, color=color, alpha=0.5, linewidths=0, zorder=3)


def _spreads(curve: Curve | RunCurve) -> Curve:
    """A run's curve as spreads of one value each (no interval, no dots)."""
    if len(curve) == 2:
        return curve
    x, values, _ = curve
    return x, [Spread(v, np.nan, np.nan, ()) for v in values]


def _curves(ax: Any, curves: Mapping[str, Curve]) -> None:
    """One line per label: the means with their intervals, and the seeds' dots."""
    for label, (x, spreads) in curves.items():
        means = [s.mean for s in spreads]
        line = ax.errorbar(x, means, yerr=_yerr(spreads), marker="o", capsize=3, label=label)
        _seed_points(ax, x, spreads, line[0].get_color())


def _pyplot() -> Any:
    """pyplot on the Agg backend: no display is needed, on servers and in tests."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    return plt


def _write_png(fig: Any, path: Path) -> None:
    """The figure as PNG, written atomically; without the matplotlib version in its
    metadata, so the same data gives the same bytes."""
    buffer = io.BytesIO()
    fig.savefig(buffer, format="png", metadata={"Software": None})
    _pyplot().close(fig)
    write_bytes_atomic(path, buffer.getvalue())


def sample_efficiency_png(curves: Mapping[str, Curve | RunCurve], title: str, path: Path) -> None:
    """Test RMSE against training fraction, one line per label (mean, 95 % interval and
    each seed; a run's curve is its values alone), written atomically."""
    fig, ax = _pyplot().subplots(figsize=(5, 3.5), dpi=120)
    _curves(ax, {label: _spreads(curve) for label, curve in curves.items()})
    ax.set(
        xlabel="fraction of training trajectories",
        ylabel="test torque RMSE (N m)",
        title=title,
        yscale="log",
    )
    ax.legend(fontsize=7)
    fig.tight_layout()
    _write_png(fig, path)


def grouped_bars_png(
    groups: Mapping[str, Mapping[str, Spread]], ylabel: str, title: str, path: Path
) -> None:
    """One group of bars per key of `groups` (a split, say), one bar per label (a model):
    its mean, 95 % interval and each seed; written atomically. A label missing from a group
    leaves a gap, so a label keeps its place and colour in every group."""
    labels = sorted({label for bars in groups.values() for label in bars})
    width = 0.8 / max(len(labels), 1)
    missing = Spread(np.nan, np.nan, np.nan, ())
    fig, ax = _pyplot().subplots(figsize=(max(5, 1.2 * len(groups) + 3), 3.5), dpi=120)
    for i, label in enumerate(labels):
        x = [g + (i - (len(labels) - 1) / 2) * width for g in range(len(groups))]
        bars = [groups[group].get(label, missing) for group in groups]
        ax.bar(x, [b.mean for b in bars], width, yerr=_yerr(bars), capsize=3, label=label)
        _seed_points(ax, x, bars, "black")
    ax.set_xticks(range(len(groups)), list(groups))
    ax.set(ylabel=ylabel, title=title)
    ax.legend(fontsize=7)
    fig.tight_layout()
    _write_png(fig, path)


def asymmetry_png(
    curves: Mapping[str, Curve],
    data_asymmetry: tuple[Sequence[float], Sequence[float]] | None,
    title: str,
    path: Path,
) -> None:
    """Test RMSE against a robot variant's asymmetry, one line per label (mean, 95 %
    interval and each seed), and beside it the datasets' own torque asymmetry (relative
    error between rotated image climbs, one value per dataset), both on log scales; written
    atomically."""
    fig, (left, right) = _pyplot().subplots(1, 2, figsize=(9, 3.5), dpi=120)
    _curves(left, curves)
    left.set(xlabel="asymmetry A (leg 0 1 + A times as heavy)", ylabel="test torque RMSE (N m)")
    left.set(title=title, yscale="log")
    left.legend(fontsize=7)
    if data_asymmetry is not None:
        x, asymmetry = data_asymmetry
        right.plot(x, asymmetry, marker="s", color="black")
    right.set(
        xlabel="asymmetry A",
        ylabel="dataset torque asymmetry (relative)",
        title="the data's own symmetry",
        yscale="log",
    )
    fig.tight_layout()
    _write_png(fig, path)
