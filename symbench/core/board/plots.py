"""Plots shared by evaluators and leaderboards (matplotlib, headless)."""

from __future__ import annotations

import io
from collections.abc import Mapping, Sequence
from pathlib import Path

from symbench.core.common.atomic import write_bytes_atomic

Curve = tuple[Sequence[float], Sequence[float], Sequence[float] | None]  # x, mean, std


def sample_efficiency_png(curves: Mapping[str, Curve], title: str, path: Path) -> None:
    """Test RMSE against training fraction, one line per label, written atomically."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(5, 3.5), dpi=120)
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
    buffer = io.BytesIO()
    fig.savefig(buffer, format="png", metadata={"Software": None})
    plt.close(fig)
    write_bytes_atomic(path, buffer.getvalue())
