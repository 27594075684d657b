"""Plots shared by evaluators and leaderboards (matplotlib, headless)."""

from __future__ import annotations

import io
from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import Any

import numpy as np

from symbench.core.common.atomic import write_bytes_atomic

Curve = tuple[Sequence[float], Sequence[float], Sequence[float] | None]  # x, mean, std
Bar = tuple[float, float]  # mean, std (NaN: one seed)


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


def sample_efficiency_png(curves: Mapping[str, Curve], title: str, path: Path) -> None:
    """Test RMSE against training fraction, one line per label, written atomically."""
    fig, ax = _pyplot().subplots(figsize=(5, 3.5), dpi=120)
    for label, (x, mean, std) in curves.items():
        ax.errorbar(x, mean, yerr=std, marker="o", capsize=3, label=label)
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
    groups: Mapping[str, Mapping[str, Bar]], ylabel: str, title: str, path: Path
) -> None:
    """One group of bars per key of `groups` (a split, say), one bar per label (a model)
    with its standard deviation, written atomically; a label missing from a group leaves a
    gap, so a label keeps its place and colour in every group."""
    labels = sorted({label for bars in groups.values() for label in bars})
    width = 0.8 / max(len(labels), 1)
    fig, ax = _pyplot().subplots(figsize=(max(5, 1.2 * len(groups) + 3), 3.5), dpi=120)
    for i, label in enumerate(labels):
        x = [g + (i - (len(labels) - 1) / 2) * width for g in range(len(groups))]
        bars = [groups[group].get(label, (np.nan, np.nan)) for group in groups]
        means = [mean for mean, _ in bars]
        stds = [0.0 if np.isnan(std) else std for _, std in bars]
        ax.bar(x, means, width, yerr=stds, capsize=3, label=label)
    ax.set_xticks(range(len(groups)), list(groups))
    ax.set(ylabel=ylabel, title=title)
    ax.legend(fontsize=7)
    fig.tight_layout()
    _write_png(fig, path)


def asymmetry_png(
    curves: Mapping[str, Curve], data_asymmetry: Curve | None, title: str, path: Path
) -> None:
    """Test RMSE against a robot variant's asymmetry, one line per label, and beside it the
    datasets' own torque asymmetry (relative error between rotated image climbs), both on
    log scales; written atomically."""
    fig, (left, right) = _pyplot().subplots(1, 2, figsize=(9, 3.5), dpi=120)
    for label, (x, mean, std) in curves.items():
        left.errorbar(x, mean, yerr=std, marker="o", capsize=3, label=label)
    left.set(xlabel="asymmetry A (leg 0 1 + A times as heavy)", ylabel="test torque RMSE (N m)")
    left.set(title=title, yscale="log")
    left.legend(fontsize=7)
    if data_asymmetry is not None:
        x, mean, _ = data_asymmetry
        right.plot(x, mean, marker="s", color="black")
    right.set(
        xlabel="asymmetry A",
        ylabel="dataset torque asymmetry (relative)",
        title="the data's own symmetry",
        yscale="log",
    )
    fig.tight_layout()
    _write_png(fig, path)
