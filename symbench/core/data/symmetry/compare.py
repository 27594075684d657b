"""Whether one climb is an image of another under a class of symmetries, judged on raw states.

**Classes** (what a model respects, nested from none to mirror):

- `none`: nothing; an image is the same climb, world frame and leg labels as they are (a
  world-frame model such as `ffnn` sees nothing else).
- `heading`: turning the whole scene about gravity (the slope's heading), the angle free
  (leg-frame models such as `ffnn-leg`).
- `group`: the robot's rotation group acting as `act_on_raw` does (legs relabelled, the base
  turned about its own z), each element tried, then the heading as above (`sdnn`, `sdgnn`).
- `mirror`: the group with the mirrors the geometry has (`spec.geometry_group`; a mirror also
  mirrors the scene in a vertical plane), then the heading (`sdnn --size mirror=1`).

**The error** of a candidate `a` as an image of `b` under an element g: `g . a` and `b` are
aligned on their lift-offs (`alignment.align_pair`, as `symbench data symmetry` does) and
compared over the rows that line up. With the heading free, the world-frame columns of
`g . a` are first turned about world z by the angle that best fits `b`'s (the closed-form
least-squares angle over positions, velocities, acceleration and the base axes, each column
weighted by 1 / its scale squared). Per column, the RMS difference over the rows and
channels is divided by the column's scale: its RMS over every climb being compared (its
typical magnitude in this dataset; quaternions up to sign). Columns are gathered as in
`report.GROUPS` (joint states, torques, base); the error is the largest group's RMS of its
columns' relative errors, so every part of the state must match. A class's error is the
least over its elements.

**Prefilter.** The RMS over a climb of each column's per-row norm is unchanged by every
element and by the heading (relabelling, sign flips and rotations keep norms), and by the
triangle inequality its difference, relative to the scale, bounds the column's error from
below when both climbs are compared over all their rows. Pairs whose bound exceeds
`NEAR_TOLERANCE * PREFILTER_SLACK` are never compared (the slack covers climbs compared on
part of their rows); the others are compared in the order of their bounds, so an image is
usually found first.

**Early stop.** The overlap only asks whether an error is below `EXACT_TOLERANCE` or below
`NEAR_TOLERANCE`. The groups are compared in `GROUPS` order (joint states, torques, then the
base, the only one the free heading turns) and a comparison stops at the first group whose
error exceeds `NEAR_TOLERANCE`: the whole error, their maximum, is above it too, and the
heading's fit and the base are never computed for a pair whose joints already differ. An
error at or below the near tolerance is computed whole, so every count is what the whole
comparison gives (on dataset v7 nearly every pair stops after the joint states).

**Screen.** Nearly every pair stops after the joint states: `screen` decides most of them
"above" for every element at once (`symbench.core.data.symmetry.screen`); every other
element is compared as here, so every count is unchanged.

**What is made once.** A paper-preset split compares each held-out climb with some 600
training climbs under 13 elements; relabelling every joint column of every candidate, and
converting each column to float64 and reading each flag's lift-offs per comparison, took
two thirds of that time (hexa `paper` `iid`, 2026-12-06). Each climb's joint columns in
float64 and its alignment flags (`alignment.Flags`, also under each element) are kept
(`Climbs.joints`, `Climbs.flags`), an element relabels only the columns of the group being
compared, and the figures are the same to the last digit. The Screen keeps each climb's joint
states a second time, laid out by channel and leg (`Climbs.channels`: about 0.33 GB more on
hexa's paper data), and one pair's matrices at a time.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field

import numpy as np

from symbench.core.common.errors import SymbenchError
from symbench.core.data.symmetry.alignment import (
    Flags,
    align,
    aligned_rows,
    alignment_flag,
    difference,
)
from symbench.core.data.symmetry.raw_action import act_on_base, base_map
from symbench.core.data.symmetry.report import GROUPS
from symbench.core.data.symmetry.screen import JOINT_STATES, SCREEN_MARGIN, Channels, JointGram
from symbench.core.data.views.frames import LegFrames, quat_multiply, quat_to_matrix, yaw_quat
from symbench.core.data.views.schema import FeatureType
from symbench.core.symmetry.groups import GroupElement, LegGroup

CLASSES = ("none", "heading", "group", "mirror")
# A generated climb's rotated twin matches it to ~1e-13 of the signal (float rounding of a
# turned simulation); 1e-6 leaves room for float32 storage and resampling rounding, and is
# far below any physical difference between two motions.
EXACT_TOLERANCE = 1e-6
# A test climb within 5 % relative RMS of an image of a training climb is the same motion
# for a learned model (its torque errors are of that order); a climb drawn with another
# swing height, goal offset or slope differs by more.
NEAR_TOLERANCE = 0.05
# The prefilter's bound holds for climbs compared over all their rows; twice the near
# tolerance lets a pair compared over part of its rows (other lengths or phases) through.
PREFILTER_SLACK = 2.0
COMPARED = tuple(c for cols in GROUPS.values() for c in cols)
WORLD_VECTORS = ("base_pos", "base_linvel", "base_angvel", "base_linacc")
FLAGS = ("contact", "magnet")
LEG_GROUPS = ("joint states", "torques")  # GROUPS whose columns are per leg (T, legs, 3)


def class_tiers(group: LegGroup, mirrors: LegGroup) -> list[list[tuple[GroupElement, bool]]]:
    """Per class, the (element, heading free) tried beyond those of the narrower classes."""
    identity = group.identity
    rotations = [g for g in group if not g.reflect and g != identity]
    reflections = [g for g in mirrors if g.reflect]
    return [[(identity, False)], [(identity, True)], [(g, True) for g in rotations],
            [(g, True) for g in reflections]]  # fmt: skip


def _heading_angle(
    moved: Mapping[str, np.ndarray],
    b: Mapping[str, np.ndarray],
    b_axes: np.ndarray,
    shift: int,
    scales: Mapping[str, float],
) -> float:
    """The turn about world z (rad) that best carries moved's world-frame columns onto b's
    (`b_axes`: b's base orientations as matrices)."""
    dot = cross = 0.0
    pairs = [(c, 1.0 / scales[c] ** 2) for c in WORLD_VECTORS if scales[c] > 0]
    for column, weight in pairs:
        x, y = aligned_rows(moved[column], b[column], shift)
        dot += weight * float(np.sum(x[:, 0] * y[:, 0] + x[:, 1] * y[:, 1]))
        cross += weight * float(np.sum(x[:, 0] * y[:, 1] - x[:, 1] * y[:, 0]))
    x, y = aligned_rows(quat_to_matrix(moved["base_quat"]), b_axes, shift)
    dot += float(np.sum(x[:, 0, :] * y[:, 0, :] + x[:, 1, :] * y[:, 1, :]))
    cross += float(np.sum(x[:, 0, :] * y[:, 1, :] - x[:, 1, :] * y[:, 0, :]))
    return float(np.arctan2(cross, dot))


def _relabel(column: np.ndarray, src: np.ndarray, signs: np.ndarray | None) -> np.ndarray:
    """A joint column (T, legs, 3) of g . a: leg j from a's leg src[j], times the joint signs
    of a mirror (as `raw_action.act_on_legs`)."""
    moved = column[:, src, :]
    return moved if signs is None else moved * signs


def turn_about_gravity(raw: Mapping[str, np.ndarray], angle: float) -> dict[str, np.ndarray]:
    """The world-frame columns of `raw` turned by `angle` (rad) about world z (the compared
    columns only: the others are not needed)."""
    c, s = np.cos(angle), np.sin(angle)
    rot = np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])
    out = dict(raw)
    for column in WORLD_VECTORS:
        out[column] = raw[column] @ rot.T
    out["base_quat"] = quat_multiply(yaw_quat(angle), raw["base_quat"])
    return out


@dataclass
class Climbs:
    """Raw climbs by id, with what comparing them needs: scales, invariant summaries and the
    errors already computed (kept across splits: `data info` asks about many)."""

    raw: dict[int, dict[str, np.ndarray]]
    group: LegGroup
    mirrors: LegGroup
    frames: LegFrames
    unknown: Sequence[str] = ()
    scales: dict[str, float] = field(init=False)
    summary: dict[int, np.ndarray] = field(init=False)
    _errors: dict[tuple[int, int, int], float] = field(init=False, default_factory=dict)
    _axes: dict[int, np.ndarray] = field(init=False, default_factory=dict)
    _joints: dict[int, dict[str, np.ndarray]] = field(init=False, default_factory=dict)
    _flag_names: dict[int, str | None] = field(init=False, default_factory=dict)
    _flags: dict[tuple[int, str, GroupElement | None], Flags] = field(
        init=False, default_factory=dict
    )
    _legs: dict[GroupElement, tuple[np.ndarray, np.ndarray | None]] = field(
        init=False, default_factory=dict
    )
    # the pair being compared, and its JointGram per shift: elements of one pair
    # are tried together, so older pairs' matrices are dropped rather than kept by the million
    _gram_pair: tuple[int, int] = field(init=False, default=(-1, -1))
    _grams: dict[int, JointGram] = field(init=False, default_factory=dict)
    _channels: dict[int, Channels] = field(init=False, default_factory=dict)

    def __post_init__(self) -> None:
        self.tiers = class_tiers(self.group, self.mirrors)
        self.scales = {}
        for column in COMPARED:
            sq = sum(float(np.sum(r[column] ** 2)) for r in self.raw.values())
            n = sum(r[column].size for r in self.raw.values())
            self.scales[column] = float(np.sqrt(sq / max(n, 1)))
        self.summary = {
            i: np.array([np.sqrt(np.mean(r[c] ** 2)) for c in COMPARED])
            for i, r in self.raw.items()
        }

    @property
    def compared(self) -> int:
        """How many (candidate, climb, class tier) errors have been computed so far."""
        return len(self._errors)

    def bounds(self, b: int, candidates: Sequence[int]) -> np.ndarray:
        """Per candidate, the lower bound on its error as an image of `b` (see the module)."""
        if not candidates:
            return np.zeros(0)
        s = np.stack([self.summary[a] for a in candidates])
        scale = np.array([self.scales[c] for c in COMPARED])
        rel = np.abs(s - self.summary[b]) / np.where(scale > 0, scale, 1.0)
        per_group = []
        start = 0
        for cols in GROUPS.values():
            per_group.append(np.sqrt(np.mean(rel[:, start : start + len(cols)] ** 2, axis=1)))
            start += len(cols)
        return np.max(np.stack(per_group, axis=1), axis=1)

    def candidates(self, b: int, pool: Sequence[int]) -> list[int]:
        """The climbs of `pool` that may be images of `b`, likeliest first."""
        pool = [a for a in pool if a != b]
        bound = self.bounds(b, pool)
        keep = np.nonzero(bound <= NEAR_TOLERANCE * PREFILTER_SLACK)[0]
        return [pool[k] for k in keep[np.argsort(bound[keep], kind="stable")]]

    def base_axes(self, i: int) -> np.ndarray:
        """Climb i's base orientations as rotation matrices, made once: every candidate
        compared with it under a free heading needs them."""
        if i not in self._axes:
            self._axes[i] = quat_to_matrix(self.raw[i]["base_quat"])
        return self._axes[i]

    def joints(self, i: int) -> dict[str, np.ndarray]:
        """Climb i's joint columns (`LEG_GROUPS`' columns) in float64, made once."""
        if i not in self._joints:
            raw = self.raw[i]
            self._joints[i] = {
                c: np.asarray(raw[c], np.float64) for g in LEG_GROUPS for c in GROUPS[g]
            }
        return self._joints[i]

    def flags(self, i: int, flag: str, g: GroupElement | None = None) -> Flags:
        """Climb i's flag `flag` as `align` reads it, relabelled by g (None: as recorded),
        made once: each training climb is aligned with every held-out one under every g."""
        key = (i, flag, g)
        if key not in self._flags:
            if g is None:
                self._flags[key] = Flags.of(self.raw[i][flag])
            else:
                self._flags[key] = self.flags(i, flag).relabelled(self.legs(g)[0])
        return self._flags[key]

    def legs(self, g: GroupElement) -> tuple[np.ndarray, np.ndarray | None]:
        """What g does to the per-leg columns: the source leg of each leg, and the joint
        columns' signs (None for a rotation); g is refused when the robot's legs lack it."""
        if g not in self._legs:
            base_map(self.frames, g)
            signs = np.asarray(FeatureType.JOINT.reflection_signs) if g.reflect else None
            self._legs[g] = (np.asarray(g.source_legs(), dtype=np.int64), signs)
        return self._legs[g]

    def _shift(self, a: int, b: int, g: GroupElement | None) -> int:
        """The rows b is ahead of g . a (g None: the identity) on their lift-offs, as
        `alignment.align_pair` gives for the relabelled climb."""
        if b not in self._flag_names:
            self._flag_names[b] = alignment_flag(self.raw[b], self.unknown)
        flag = self._flag_names[b]
        if flag is None or flag not in self.raw[a]:
            return align(None, None).shift
        return align(self.flags(a, flag, g), self.flags(b, flag)).shift

    def element_error(
        self, a: int, b: int, g: GroupElement, heading: bool, decided_above: float = np.inf
    ) -> float:
        """The error of climb a, acted on by g (heading free or not), as climb b. Once a
        group's error exceeds `decided_above` the rest is not computed and a lower bound of
        the whole above `decided_above` is returned: that group's error, or the joint states'
        screened one less half the margin (see the module's Early stop and Screen)."""
        identity, climb = g == self.group.identity, self.raw[a]
        src, signs = self.legs(g)
        shift = self._shift(a, b, None if identity else g)
        screened = self.screen(a, b, shift, src, signs) if decided_above < np.inf else 0.0
        if screened > decided_above + SCREEN_MARGIN:
            # the joint states alone are above (the Early stop's answer); less half the
            # margin, far beyond the screen's rounding, the value is a lower bound, as there
            return screened - SCREEN_MARGIN / 2
        worst = 0.0
        for name, cols in GROUPS.items():
            if name in LEG_GROUPS:  # g . a's columns of this group alone, relabelled
                mine = self.joints(a)
                moved = {c: mine[c] if identity else _relabel(mine[c], src, signs) for c in cols}
                target: Mapping[str, np.ndarray] = self.joints(b)
            else:  # the base, the only group the free heading turns
                moved = climb if identity else {**climb, **act_on_base(g, climb, self.frames)}
                target = self.raw[b]
                if heading:
                    axes = self.base_axes(b)
                    angle = _heading_angle(moved, target, axes, shift, self.scales)
                    moved = turn_about_gravity(moved, angle)
            worst = max(worst, self._group_error(moved, target, cols, shift))
            if worst > decided_above:
                break
        return worst

    def screen(
        self, a: int, b: int, shift: int, src: np.ndarray, signs: np.ndarray | None
    ) -> float:
        """The joint-state group's error of a relabelled by (src, signs) as b, from the pair's
        `JointGram` at this shift (see the module's Screen): accurate except where it is
        small, so it only decides "above"; 0 (never above) where a column has no scale."""
        scales = np.array([self.scales[c] for c in JOINT_STATES])
        if scales.min() <= 0:
            return 0.0
        if self._gram_pair != (a, b):
            self._gram_pair, self._grams = (a, b), {}
        if shift not in self._grams:
            self._grams[shift] = JointGram.of(self.channels(a), self.channels(b), shift)
        return self._grams[shift].error(src, signs, scales)

    def channels(self, i: int) -> Channels:
        """Climb i's joint states laid out for the Screen, made once."""
        if i not in self._channels:
            self._channels[i] = Channels.of(self.joints(i))
        return self._channels[i]

    def _group_error(
        self,
        moved: Mapping[str, np.ndarray],
        target: Mapping[str, np.ndarray],
        columns: Sequence[str],
        shift: int,
    ) -> float:
        """The RMS over `columns` of their relative errors (see the module)."""
        rel = []
        for column in columns:
            diff, _ = difference(moved, target, column, shift)
            scale = self.scales[column]
            rms = float(np.sqrt(np.mean(diff**2))) if diff.size else np.inf
            rel.append(rms / scale if scale > 0 else (0.0 if rms == 0 else np.inf))
        return float(np.sqrt(np.mean([r**2 for r in rel])))

    def tier_error(self, a: int, b: int, tier: int) -> float:
        """The least error over tier `tier`'s elements (stops below `EXACT_TOLERANCE`); an
        error above `NEAR_TOLERANCE` is only known to be above it (Early stop)."""
        key = (a, b, tier)
        if key not in self._errors:
            best = np.inf
            for g, heading in self.tiers[tier]:
                best = min(best, self.element_error(a, b, g, heading, NEAR_TOLERANCE))
                if best < EXACT_TOLERANCE:
                    break
            self._errors[key] = best
        return self._errors[key]

    def class_error(self, a: int, b: int, cls: int, below: float = EXACT_TOLERANCE) -> float:
        """The least error of a as an image of b under class `cls` (an index into CLASSES),
        stopping at the first tier below `below`."""
        best = np.inf
        for tier in range(cls + 1):
            best = min(best, self.tier_error(a, b, tier))
            if best < below:
                break
        return best


def check_columns(raw: Mapping[str, np.ndarray], unknown: Sequence[str], where: str) -> None:
    """Refuse raw states that lack a compared column or declare one unknown."""
    missing = [c for c in COMPARED if c not in raw]
    if missing:
        raise SymbenchError(f"{where}: raw column(s) {', '.join(missing)} missing")
    unknown_compared = [c for c in COMPARED if c in unknown]
    if unknown_compared:
        raise SymbenchError(
            f"{where}: column(s) {', '.join(unknown_compared)} declared unknown at import "
            "(images are judged on every raw state column)"
        )
