"""Figures written as files, atomically and the same bytes for the same data: PNG for the
Markdown boards, SVG (vectors, sharp at any zoom) for the site, whose builds are tested to be
byte-reproducible. Both are cropped to what the figure draws, the legend beside the axes
included, so nothing is clipped."""

from __future__ import annotations

import io
from pathlib import Path
from typing import TYPE_CHECKING

from symbench.core.common.atomic import write_bytes_atomic

if TYPE_CHECKING:
    from matplotlib.figure import Figure

PNG_DPI = 150
# the seed of the SVG's element ids, which matplotlib otherwise draws at random per file
SVG_HASHSALT = "symbench"


def write_png(fig: Figure, path: Path) -> None:
    """The figure as PNG, without the matplotlib version in its metadata."""
    buffer = io.BytesIO()
    fig.savefig(buffer, format="png", dpi=PNG_DPI, bbox_inches="tight", metadata={"Software": None})
    write_bytes_atomic(path, buffer.getvalue())


def write_svg(fig: Figure, path: Path) -> None:
    """The figure as SVG, its ids seeded and without a date or the matplotlib version."""
    import matplotlib

    buffer = io.BytesIO()
    with matplotlib.rc_context({"svg.hashsalt": SVG_HASHSALT}):
        fig.savefig(
            buffer, format="svg", bbox_inches="tight", metadata={"Date": None, "Creator": None}
        )
    write_bytes_atomic(path, buffer.getvalue())
