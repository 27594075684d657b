"""Built-in splits: iid, unseen-heading, unseen-rotation, orbit-rotation, unseen-inclination,
unseen-gait and fraction-F (sample efficiency).

Registered through the `symbench_splits` hook exactly as a third-party split would be.
The fraction-F splits are those of the presets' sample-efficiency curves.
"""

from __future__ import annotations

from symbench import PRESETS, SplitEntry, hookimpl
from symbench.plugins.splits import assign as splits


def fractions() -> list[float]:
    """Every preset's sample-efficiency fractions, each once, ascending."""
    return sorted({f for p in PRESETS.values() for f in p.sample_efficiency.fractions})


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
            "train on every other yaw of one sector, test on yaws between them in the other "
            "sectors (rotations never seen)",
        ),
        SplitEntry(
            "orbit-rotation",
            splits.orbit_rotation,
            "train on the yaws of one sector, test on their rotated images (pure equivariance)",
        ),
        SplitEntry(
            "unseen-inclination",
            splits.unseen_inclination,
            "train on the gentler slopes, test on the steepest third (transfer preset: floor "
            "to wall trains, overhangs and ceiling test)",
        ),
        SplitEntry(
            "unseen-gait",
            splits.unseen_gait,
            "train on the default stepping sequence, test on the reversed one",
        ),
    ]
    entries += [
        SplitEntry(
            f"fraction-{share:g}",
            splits.fraction(share),
            f"iid with {share:g} of its training trajectories (sample efficiency)",
        )
        for share in fractions()
    ]
    return entries
