"""Plots shared by evaluators, the Markdown boards and the site (matplotlib, headless).

Every plot follows the same rules, so that none misleads: a model has one colour on every
plot and its several entries (variants, backends, protocols) differ by marker, line or hatch
(`palette`); each point shows the mean over seeds, its 95 % interval and each seed's value;
a line never joins two points across an x where it has no data; the legend sits beside the
axes, never on the data; a log axis is drawn from `portable_math` logarithms (`_log_axis`), so
that the files are the same bytes on every CPU. Figures are built without pyplot (no global
state, no display) and written by `plot_files`.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Generic, TypeVar

import numpy as np

from symbench.core.board.palette import colour_of, styles_of
from symbench.core.board.plot_files import write_png
from symbench.core.common import portable_math

if TYPE_CHECKING:
    from matplotlib.artist import Artist
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure

HEIGHT = 3.5  # inches, of every figure
RMSE_LABEL = "test torque RMSE (N m, log scale)"
MOST_DECADE_LABELS = 8  # a log axis spanning more labels every few powers of ten


@dataclass(frozen=True)
class Spread:
    """A mean over seeds, its 95 % bootstrap interval (NaN: one seed) and the seeds' own
    values: plots show all three, so that a reader sees how few seeds the interval rests on."""

    mean: float
    low: float
    high: float
    seeds: tuple[float, ...]


MISSING = Spread(np.nan, np.nan, np.nan, ())

X = TypeVar("X", float, str)


@dataclass(frozen=True)
class Series(Generic[X]):
    """One entry of a plot: `model` fixes its colour, `label` names it in the legend, and
    `points` holds its spread at each x (a fraction, an asymmetry) or group (a split)."""

    model: str
    label: str
    points: Mapping[X, Spread]


def _logged_series(series: Sequence[Series[X]]) -> list[Series[X]]:
    """The series with every value replaced by its base-10 logarithm, to be drawn on an axis
    that `_log_axis` labels; a value a log axis cannot show (0, negative) becomes NaN."""
    return [Series(s.model, s.label, {x: _logged(p) for x, p in s.points.items()}) for s in series]


def _logged(spread: Spread) -> Spread:
    return Spread(
        _log10(spread.mean),
        _log10(spread.low),
        _log10(spread.high),
        tuple(_log10(v) for v in spread.seeds),
    )


def _log10(value: float) -> float:
    return portable_math.log10(value) if value > 0 else math.nan


def _log_axis(ax: Axes) -> None:
    """Ticks and labels of a log axis on y, whose data are base-10 logarithms drawn linearly
    (`_logged_series`): a major tick at each power of ten (every few when the view spans
    many), minor ticks at 2 to 9 times them, some labelled when fewer than two powers are
    in view (all when under 0.4 of a power). Matplotlib's own log scale computes positions
    with numpy's log and power, whose last bits differ between CPUs (`portable_math`):
    enough to move a line by a pixel."""
    low, high = ax.get_ylim()
    stride = max(1, math.ceil((high - low) / MOST_DECADE_LABELS))
    span = range(math.floor(low), math.ceil(high) + 1)
    decades = [k for k in span if k % stride == 0 and low <= k <= high]
    minor = [(k, m, k + portable_math.log10(m)) for k in span for m in range(2, 10) if stride == 1]
    minor = [(k, m, y) for k, m, y in minor if low <= y <= high]
    ax.set_yticks(decades, [f"$\\mathdefault{{10^{{{k}}}}}$" for k in decades])
    named = range(2, 10) if high - low < 0.4 else (2, 3, 4, 6) if len(decades) < 2 else ()
    labels = [f"$\\mathdefault{{{m}\\times10^{{{k}}}}}$" if m in named else "" for k, m, _ in minor]
    ax.set_yticks([y for _, _, y in minor], labels, minor=True)
    ax.set_ylim(low, high)


# one run's curve (the sample-efficiency evaluator's plot of a single seed): x, values, None
RunCurve = tuple[Sequence[float], Sequence[float], None]


def _figure(width: float, axes: int = 1) -> tuple[Figure, list[Axes]]:
    from matplotlib.figure import Figure

    fig = Figure(figsize=(width, HEIGHT))
    return fig, list(fig.subplots(1, axes, squeeze=False)[0])


def _yerr(spreads: Sequence[Spread]) -> np.ndarray:
    """The intervals as matplotlib's asymmetric error bars (none for a single seed)."""
    means = np.array([s.mean for s in spreads])
    below = means - np.array([s.low for s in spreads])
    above = np.array([s.high for s in spreads]) - means
    bars: np.ndarray = np.nan_to_num(np.vstack([below, above]))
    return bars


def _seed_points(ax: Axes, x: Sequence[float], spreads: Sequence[Spread], colour: str) -> None:
    """Each seed's value as a small dot at its spread's x, ringed white to show on a bar."""
    xs = [xi for xi, s in zip(x, spreads) for _ in s.seeds]
    ys = [value for s in spreads for value in s.seeds]
    ax.scatter(xs, ys, s=12, color=colour, edgecolors="white", linewidths=0.5, zorder=3)


def draw_curves(ax: Axes, series: Sequence[Series[float]]) -> None:
    """One line per series over the x of all of them: where a series has no point, its line
    has NaN and breaks, so it never joins its neighbours across the gap (an isolated point
    shows as its marker alone)."""
    grid = sorted({x for s in series for x in s.points})
    for s, style in zip(series, styles_of([s.model for s in series])):
        spreads = [s.points.get(x, MISSING) for x in grid]
        colour = colour_of(s.model)
        ax.errorbar(
            grid,
            [p.mean for p in spreads],
            yerr=_yerr(spreads),
            color=colour,
            marker=style.marker,
            linestyle=style.linestyle,
            capsize=3,
            label=s.label,
        )
        _seed_points(ax, grid, spreads, colour)


def draw_bars(ax: Axes, series: Sequence[Series[str]], groups: Sequence[str]) -> None:
    """A group of bars per group name (a split, say), a bar per series: a series missing from
    a group leaves a gap, so each keeps its place in every group."""
    width = 0.8 / max(len(series), 1)
    for i, (s, style) in enumerate(zip(series, styles_of([s.model for s in series]))):
        x = [g + (i - (len(series) - 1) / 2) * width for g in range(len(groups))]
        bars = [s.points.get(group, MISSING) for group in groups]
        ax.bar(
            x,
            [b.mean for b in bars],
            width,
            yerr=_yerr(bars),
            capsize=3,
            color=colour_of(s.model),
            hatch=style.hatch,
            edgecolor="black",
            linewidth=0.5,
            label=s.label,
        )
        _seed_points(ax, x, bars, "black")
    ax.set_xticks(range(len(groups)), list(groups))


def _finish(fig: Figure) -> Figure:
    """Axes laid out to fill the figure, and one legend of every axes' entries (each label
    once) beside them, right of the figure (the files are cropped to include it)."""
    fig.tight_layout()
    entries: dict[str, Artist] = {}
    for ax in fig.axes:
        for handle, label in zip(*ax.get_legend_handles_labels(), strict=True):
            entries.setdefault(label, handle)
    handles, labels = list(entries.values()), list(entries)
    fig.legend(
        handles,
        labels,
        loc="upper left",
        bbox_to_anchor=(1.0, 1.0),
        fontsize=8,
        frameon=False,
    )
    return fig


def _rmse_curves(ax: Axes, series: Sequence[Series[float]], xlabel: str, title: str) -> None:
    """Test RMSE against `xlabel`, a line per series, on a log axis."""
    draw_curves(ax, _logged_series(series))
    ax.set(xlabel=xlabel, ylabel=RMSE_LABEL, title=title)
    _log_axis(ax)


def sample_efficiency_figure(panels: Mapping[str, Sequence[Series[float]]]) -> Figure:
    """Test RMSE against the fraction of training climbs, one axes per title in `panels` (a
    dataset: one dataset's fractions are not another's climbs, nor are its test climbs), a
    line per series."""
    fig, axes = _figure(5.0 * len(panels), axes=len(panels))
    for ax, (title, series) in zip(axes, panels.items(), strict=True):
        _rmse_curves(ax, series, "fraction of the training climbs (1: all, the iid split)", title)
    return _finish(fig)


def asymmetry_figure(
    series: Sequence[Series[float]],
    data_asymmetry: tuple[Sequence[float], Sequence[float]] | None,
    title: str,
) -> Figure:
    """Test RMSE against a robot variant's asymmetry, a line per series, and beside it the
    datasets' own torque asymmetry (relative error between rotated image climbs, one value
    per dataset), both on log scales."""
    fig, (left, right) = _figure(9.0, axes=2)
    _rmse_curves(left, series, "asymmetry A (leg 0 is 1 + A times as heavy)", title)
    if data_asymmetry is not None:
        x, asymmetry = data_asymmetry
        right.plot(x, [_log10(a) for a in asymmetry], marker="s", color="grey")
    right.set(
        xlabel="asymmetry A",
        ylabel="the data's torque asymmetry (relative, log scale)",
        title="the data's own symmetry",
    )
    _log_axis(right)
    return _finish(fig)


def bars_figure(
    series: Sequence[Series[str]],
    groups: Sequence[str],
    ylabel: str,
    title: str,
    reference: float | None = None,
) -> Figure:
    """Grouped bars (`draw_bars`), with a dashed line at `reference` when given (the value
    that means no effect)."""
    fig, (ax,) = _figure(max(4.0, 1.2 * len(groups) + 2.5))
    draw_bars(ax, series, groups)
    if reference is not None:
        ax.axhline(reference, color="grey", linestyle="--", linewidth=0.8, zorder=0)
    ax.set(ylabel=ylabel, title=title)
    return _finish(fig)


def sample_efficiency_png(curves: Mapping[str, RunCurve], title: str, path: Path) -> None:
    """A run's test RMSE against training fraction, a line per label, written atomically; a
    label's model, its text before ' (', fixes the line's colour."""
    series = [
        Series(
            label.split(" (")[0],
            label,
            {x: Spread(v, np.nan, np.nan, ()) for x, v in zip(fractions, values)},
        )
        for label, (fractions, values, _) in curves.items()
    ]
    write_png(sample_efficiency_figure({title: series}), path)
