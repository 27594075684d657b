"""The figure of `symbench data symmetry`: each image pair's error against the floor.

Kept apart from the measure so that computing a report (the `data-symmetry` evaluator does
it in every run) never touches matplotlib, which is imported only when the figure is drawn.
"""

from __future__ import annotations

import io
from pathlib import Path

import numpy as np

from symbench.core.common.atomic import write_bytes_atomic
from symbench.core.data.symmetry.report import FLOAT_PRECISION, SymmetryReport

PLOT_NAME = "symmetry.png"


def symmetry_png(report: SymmetryReport, path: Path) -> Path:
    """Per column group, each pair's relative error after relabelling (dots) against the noise
    floor (bar), log scale; written atomically."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    labels = list(report.groups)
    fig, ax = plt.subplots(figsize=(7, 3.8), dpi=120)
    tiny = 1e-17  # exact zeros on a log axis
    rng = np.random.default_rng(0)
    for x, label in enumerate(labels):
        values = np.array([p.relative_error[label] for p in report.pairs]) + tiny
        jitter = rng.uniform(-0.15, 0.15, len(values))
        ax.scatter(
            x + jitter,
            values,
            s=8,
            alpha=0.6,
            color="C0",
            label="pairs" if x == 0 else "_nolegend_",
        )
        floor = report.groups[label]["relative_floor"]
        ax.hlines(
            floor,
            x - 0.35,
            x + 0.35,
            color="C3",
            lw=2,
            label="noise floor" if x == 0 else "_nolegend_",
        )
    ax.axhline(FLOAT_PRECISION, color="grey", ls=":", lw=1, label="float precision")
    ax.set_xticks(range(len(labels)), labels)
    ax.set(
        yscale="log",
        ylabel="relative RMS error after relabelling",
        title=f"{report.dataset}: {len(report.pairs)} image pairs under {report.group}"
        + (" (found" if report.constructed is None else " (constructed on purpose")
        + f"; floor: {report.floor_source})",
    )
    ax.title.set_fontsize(8)
    ax.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.0, 1.0))
    fig.tight_layout()
    buffer = io.BytesIO()
    fig.savefig(buffer, format="png", metadata={"Software": None})
    plt.close(fig)
    write_bytes_atomic(path, buffer.getvalue())
    return path
