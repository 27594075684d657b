"""Built-in splits: iid, unseen-heading, unseen-rotation, orbit-rotation, unseen-inclination,
unseen-gait, their size-matched iid controls (control-heading, ...) and fraction-F
(sample efficiency).

Registered through the `symbench_splits` hook exactly as a third-party split would be.
Each generalization split names its control (`SplitEntry.control`, `symbench.control_of`),
so that a board can divide the split's test error by the control's. The fraction-F splits
are those of the presets' sample-efficiency curves.
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
            "train on half of the slope headings, test on the others (gravity-axis invariance; "
            "v7: headings in [0, 180) train, [180, 360) test)",
            control="control-heading",
        ),
        SplitEntry(
            "unseen-rotation",
            splits.unseen_rotation,
            "train on the climbs starting in the first yaw sector, test on the others (v6 "
            "grids: every other yaw of it, test on yaws between them in the other sectors)",
            control="control-rotation",
        ),
        SplitEntry(
            "orbit-rotation",
            splits.orbit_rotation,
            "train on the yaws of one sector, test on their exact rotated images (pure "
            "equivariance; refused on datasets without any, as v7's continuous draws)",
        ),
        SplitEntry(
            "unseen-inclination",
            splits.unseen_inclination,
            "train on the gentler slopes, test on the steepest third (transfer preset: floor "
            "to wall trains, overhangs and ceiling test)",
            control="control-inclination",
        ),
        SplitEntry(
            "unseen-gait",
            splits.unseen_gait,
            "train on the default stepping sequence, test on the reversed one",
            control="control-gait",
        ),
    ]
    entries += [
        SplitEntry(
            e.control,
            splits.control(e.assign),
            f"size-matched iid control of {e.name}: as many training, validation and test "
            "climbs, drawn at random (the generalization gap's denominator)",
        )
        for e in entries
        if e.control
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
