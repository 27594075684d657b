"""Built-in splits: iid, unseen-heading, unseen-rotation and fraction-F (sample efficiency).

Registered through the `symbench_splits` hook exactly as a third-party split would be.
"""

from __future__ import annotations

from symbench import SplitEntry, hookimpl
from symbench.plugins.splits import assign as splits

FRACTIONS = (0.1, 0.25, 0.5, 0.75)


@hookimpl
def symbench_splits() -> list[SplitEntry]:
    entries = [
        SplitEntry("iid", splits.iid, "held-out trajectories of the same scenario distribution"),
        SplitEntry(
            "unseen-heading",
            splits.unseen_heading,
            "train on half of the slope headings, test on the others (gravity-axis invariance)",
        ),
        SplitEntry(
            "unseen-rotation",
            splits.unseen_rotation,
            "train on initial yaws in one fundamental sector, test on the rest (equivariance)",
        ),
    ]
    entries += [
        SplitEntry(
            f"fraction-{share:g}",
            splits.fraction(share),
            f"iid with {share:g} of its training trajectories (sample efficiency)",
        )
        for share in FRACTIONS
    ]
    return entries
