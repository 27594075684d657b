"""How symmetric a dataset is: `symbench data symmetry ID`.

**Image pairs.** Trajectory B is the image of trajectory A under a rotation g of the robot's
group when B's scenario is A's with every field mapped by g the way the simulator builds a
twin (`symbench.core.sim.scene.setup.turn_gait`, the one map that `Climb.turned` uses): the
yaw grows by g's angle (a multiple of 360 / rotation order degrees), the body step direction
turns back by it, the leg order is relabelled by g's leg permutation, and slope, heading,
seed and the other fields stay. Then B is A seen with turned base axes and relabelled legs:
`act_on_raw(g, A)` relabels A's legs and turns its base axes the way B's are turned; on a
perfectly symmetric robot it equals B. Reflections are not paired (no scenario field says
that one climb is another's mirror image).

**How the scenario is read.** A generated dataset stores the simulator's input: its
direction and leg order are those of the yaw's first symmetry sector, which the simulator
turns with the base (`scenario_gait`, as `Climb.from_scenario` does), so two scenarios that
differ only in yaw by g's angle are images. An imported log stores what the robot did
(`recorded`): the leg order in which its legs stepped and the base-frame direction it
stepped in, mapped by g as they are. An imported dataset with no image pair read so but some
read as the simulator's input (an export of a generated dataset) is read as the simulator's;
the report says which reading it used.

**Alignment.** Two logs of one motion may start at different phases of the gait (one logger
started earlier). Each pair (images and repeats) is aligned on its lift-offs (a row where a
leg's magnet flag, else its contact flag, drops from 1 to 0): among the shifts that put the
first lift-off of a leg in one log on a lift-off of the same leg in the other (and no
shift), the one whose flags then differ in the fewest rows, ties to the smallest shift, is
kept when the flags differ in at most `ALIGN_TOLERANCE` of the rows both then have (at least
half the shorter log). Otherwise the pair could not be aligned: it is compared row by row
and the report says so. Without known flags every pair is compared row by row.

**The error after relabelling**, per column, is the RMS of `g . A - B` over the pairs'
aligned rows (quaternions up to sign), relative to the column's RMS in B. Columns are
gathered into groups: joint states (q, qd, qdd), torques (tau) and base (position,
orientation, velocities, acceleration); a group's relative error is the RMS of its columns'
relative errors. Contact and magnet flags are compared as the share of rows where a flag
differs.

**The noise floor** is what two recordings of the same scenario would differ by:

- `repeats`: when some scenario appears more than once (a real robot's repeated runs), the
  RMS difference between repeats (aligned like the images), per column;
- `high-frequency`: otherwise, the dataset's own sampling noise: per scalar channel, the
  noise sigma estimated from third differences (white noise of sigma gives third differences
  of variance 20 sigma^2; a robust scale, 1.4826 x median absolute deviation, ignores the
  rare jumps at contact changes), times sqrt(2) for the difference of two recordings. A
  smooth signal's own third differences count as noise here, so this floor is an upper
  bound on the sampling noise.

A floor from repeats tells nothing when the repeats are not one motion: when some repeat
pair could not be aligned (their flags say they step differently), or when a group's floor
is at least its image error and at least `UNINFORMATIVE_FLOOR` of the signal (repeats that
differ as much as images, and as much as the signal itself). Then no verdict is given; the
report names the scenario fields the dataset lacks that would tell the motions apart.

A dataset whose error is at the float-precision level (`FLOAT_PRECISION`) is exactly
symmetric (a generated dataset); one whose error is below an informative floor is symmetric
within its noise; anything above is a measurable asymmetry, reported as the ratio
error / floor.
"""

from __future__ import annotations

import io
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from itertools import combinations
from pathlib import Path
from typing import Any

import numpy as np

from symbench.core.common.atomic import write_bytes_atomic
from symbench.core.common.errors import SymbenchError
from symbench.core.data.symmetry.alignment import (
    Alignment,
    align_pair,
    aligned_rows,
    difference,
)
from symbench.core.data.symmetry.raw_action import act_on_raw, base_map
from symbench.core.data.views.frames import LegFrames
from symbench.core.robot.specs import RobotSpec
from symbench.core.sim.scene.scenario import DIRECTIONS
from symbench.core.sim.scene.setup import Gait, scenario_gait, turn_gait
from symbench.core.symmetry.groups import GroupElement, LegGroup

GROUPS: dict[str, tuple[str, ...]] = {
    "joint states": ("q", "qd", "qdd"),
    "torques": ("tau",),
    "base": ("base_pos", "base_quat", "base_linvel", "base_angvel", "base_linacc"),
}
FLAGS = ("contact", "magnet")
FLOAT_PRECISION = 1e-6  # relative error below this: symmetric up to rounding
ANGLE_TOLERANCE_DEG = 1e-6
MAD_TO_SIGMA = 1.4826  # sigma of a normal distribution / its median absolute deviation
THIRD_DIFFERENCE_VARIANCE = 20.0  # var(third difference of white noise) / sigma^2
PLOT_NAME = "symmetry.png"
READINGS = ("simulator", "recorded")
READING_NAMES = {  # how `symbench data symmetry` names each reading of the scenarios
    "simulator": "the simulator's input",
    "recorded": "recorded (leg order and direction as stepped)",
}
UNINFORMATIVE_FLOOR = 0.5  # a relative floor this large is no noise: the repeats differ
# the scenario fields that may tell two motions apart, named when repeats evidently differ
TELLING_FIELDS = ("leg_order", "direction", "seed", "inclination_deg", "heading_deg")


@dataclass(frozen=True)
class Pair:
    """Trajectory `b` is trajectory `a` acted on by `element` (ids as in the dataset)."""

    a: int
    b: int
    element: GroupElement
    rows: int
    relative_error: dict[str, float]  # per column group
    alignment: Alignment = field(default_factory=Alignment)


@dataclass
class SymmetryReport:
    dataset: str
    robot: str
    group: str
    trajectories: int
    floor_source: str  # "repeats" or "high-frequency"
    pairs: list[Pair] = field(default_factory=list)
    repeats: int = 0  # pairs of trajectories of one scenario
    columns: dict[str, dict[str, float]] = field(default_factory=dict)
    groups: dict[str, dict[str, Any]] = field(default_factory=dict)
    flags: dict[str, float] = field(default_factory=dict)
    plot: str | None = None
    reading: str = "recorded"  # how the scenarios were read: "simulator" or "recorded"
    repeat_alignments: list[tuple[int, int, Alignment]] = field(default_factory=list)
    floor_note: str | None = None  # why the floor from repeats tells nothing, when it does not

    @property
    def unaligned(self) -> list[Pair]:
        return [p for p in self.pairs if not p.alignment.aligned]

    def to_dict(self) -> dict[str, Any]:
        return {
            "dataset": self.dataset,
            "robot": self.robot,
            "group": self.group,
            "trajectories": self.trajectories,
            "scenario_reading": self.reading,
            "image_pairs": len(self.pairs),
            "repeat_pairs": self.repeats,
            "floor": self.floor_source,
            "floor_note": self.floor_note,
            "groups": self.groups,
            "columns": self.columns,
            "flag_mismatch": self.flags,
            "pairs": [
                {
                    "a": p.a,
                    "b": p.b,
                    "element": p.element.name,
                    "rows": p.rows,
                    "relative_error": p.relative_error,
                    "alignment": p.alignment.to_dict(),
                }
                for p in self.pairs
            ],
            "repeats": [
                {"a": a, "b": b, "alignment": al.to_dict()} for a, b, al in self.repeat_alignments
            ],
            "plot": self.plot,
        }


def _scenario_key(scenario: Mapping[str, Any], drop: Sequence[str] = ()) -> str:
    return repr(sorted((k, v) for k, v in scenario.items() if k not in drop))


def rotation_angles(group: LegGroup, frames: LegFrames) -> list[tuple[GroupElement, float]]:
    """Each rotation of the group with the angle (degrees, in [0, 360)) by which a
    trajectory's yaw must grow for `act_on_raw(g, .)` to map it onto its image."""
    out = []
    for g in group:
        if g.reflect or g == group.identity:
            continue
        gb = base_map(frames, g)
        angle = float(np.degrees(np.arctan2(gb[1, 0], gb[0, 0])))
        out.append((g, (-angle) % 360.0))
    return out


def _same_angle(a: float, b: float) -> bool:
    d = (a - b) % 360.0
    return min(d, 360.0 - d) < ANGLE_TOLERANCE_DEG


GAIT_FIELDS = ("yaw_deg", "direction", "leg_order")


def scenario_gait_of(
    scenario: Mapping[str, Any], reading: str, spec: RobotSpec | None = None
) -> Gait | None:
    """The gait (yaw, body direction, swing order) a stored scenario says the robot performed,
    read as the simulator's input or as recorded; None when it cannot be paired (no yaw, or a
    leg order that is not a permutation of the legs)."""
    yaw = scenario.get("yaw_deg")
    if yaw is None:
        return None
    name = scenario.get("direction")
    direction = None if name is None else DIRECTIONS[name]
    order = scenario.get("leg_order")
    order = None if order is None else tuple(int(leg) for leg in order)
    if reading == "recorded":
        return (float(yaw), direction, order)
    if spec is None:
        raise SymbenchError("reading scenarios as the simulator's input needs the robot's spec")
    if order is not None and sorted(order) != list(range(spec.n_legs)):
        return None
    return scenario_gait(spec, float(yaw), direction, order)


def _same_gait(x: Gait, y: Gait) -> bool:
    (yaw_x, dir_x, order_x), (yaw_y, dir_y, order_y) = x, y
    assert yaw_x is not None and yaw_y is not None
    if (dir_x is None) != (dir_y is None) or order_x != order_y:
        return False
    return _same_angle(yaw_x, yaw_y) and (dir_x is None or _same_angle(dir_x, dir_y))  # type: ignore[arg-type]


@dataclass(frozen=True)
class Pairing:
    """Image pairs (a, b, g) with b = g . a, repeat pairs (a, b) of one scenario, and how the
    scenarios were read."""

    images: list[tuple[int, int, GroupElement]]
    repeats: list[tuple[int, int]]
    reading: str


def pair_up(
    scenarios: Sequence[Mapping[str, Any]],
    ids: Sequence[int],
    group: LegGroup,
    frames: LegFrames,
    reading: str = "auto",
    spec: RobotSpec | None = None,
) -> Pairing:
    """The image and repeat pairs of a dataset's scenarios, read as `reading`: "simulator"
    (a generated dataset), "recorded" (imported logs) or "auto" (recorded, unless that finds
    no image pair and the simulator's reading, possible with `spec`, finds some)."""
    if reading == "auto":
        recorded = pair_up(scenarios, ids, group, frames, "recorded", spec)
        if recorded.images or spec is None:
            return recorded
        simulated = pair_up(scenarios, ids, group, frames, "simulator", spec)
        return simulated if simulated.images else recorded
    if reading not in READINGS:
        raise SymbenchError(f"scenario reading must be one of {', '.join(READINGS)}: {reading}")
    rotations = rotation_angles(group, frames)
    n_legs = group.n_legs
    by_rest: dict[str, list[int]] = {}
    by_all: dict[str, list[int]] = {}
    gaits: dict[int, Gait] = {}
    for i, scenario in zip(ids, scenarios):
        by_all.setdefault(_scenario_key(scenario), []).append(int(i))
        gait = scenario_gait_of(scenario, reading, spec)
        if gait is not None:
            gaits[int(i)] = gait
            by_rest.setdefault(_scenario_key(scenario, GAIT_FIELDS), []).append(int(i))
    images = []
    for members in by_rest.values():
        for a, b in combinations(members, 2):
            for g, angle in rotations:
                # b = act_on_raw(g, a) is the simulator's twin of a under g's inverse: leg i
                # of a is leg g.perm[i] of b
                order = gaits[a][2]
                if order is not None and max(order, default=0) >= n_legs:
                    break
                if _same_gait(turn_gait(gaits[a], angle, g.perm), gaits[b]):
                    images.append((a, b, g))
                    break
    # in the order of the scenarios but for their yaw, then of the ids: the order in which
    # pairs were taken before leg orders and directions were mapped (the same sums, bit for bit)
    rest = {int(i): _scenario_key(s, ("yaw_deg",)) for i, s in zip(ids, scenarios)}
    rank: dict[str, int] = {}
    for key in rest.values():
        rank.setdefault(key, len(rank))
    position = {int(i): n for n, i in enumerate(ids)}
    images.sort(key=lambda p: (rank[rest[p[0]]], position[p[0]], position[p[1]]))
    repeats = [pair for members in by_all.values() for pair in combinations(members, 2)]
    return Pairing(images, repeats, reading)


def find_pairs(
    scenarios: Sequence[Mapping[str, Any]],
    ids: Sequence[int],
    group: LegGroup,
    frames: LegFrames,
    reading: str = "auto",
    spec: RobotSpec | None = None,
) -> tuple[list[tuple[int, int, GroupElement]], list[tuple[int, int]]]:
    """Image pairs (a, b, g) with b = g . a, and repeat pairs (a, b) of one scenario."""
    pairing = pair_up(scenarios, ids, group, frames, reading, spec)
    return pairing.images, pairing.repeats


def _columns(raw: Mapping[str, np.ndarray]) -> list[str]:
    return [c for cols in GROUPS.values() for c in cols if c in raw]


def _noise_sigma(x: np.ndarray) -> np.ndarray:
    """Per channel (last axis of the flattened rows) noise sigma from third differences."""
    if len(x) < 5:
        return np.full(x.shape[1], np.nan)
    d3 = np.diff(x, n=3, axis=0)
    mad = np.median(np.abs(d3 - np.median(d3, axis=0)), axis=0)
    return MAD_TO_SIGMA * mad / np.sqrt(THIRD_DIFFERENCE_VARIANCE)


def measure(
    trajectories: Mapping[int, Mapping[str, np.ndarray]],
    scenarios: Sequence[Mapping[str, Any]],
    group: LegGroup,
    frames: LegFrames,
    name: str = "",
    robot: str = "",
    unknown: Sequence[str] = (),
    reading: str = "auto",
    spec: RobotSpec | None = None,
) -> SymmetryReport:
    """The symmetry report of raw trajectories by id (`scenarios` in the same id order),
    the scenarios read as `reading` (see `pair_up`; `spec`, else `robot`'s, for the
    simulator's reading); flags in `unknown` (declared unknown by an import, stored as 0) are
    not compared."""
    if spec is None and reading != "recorded":
        spec = _spec_of(robot)
    ids = list(trajectories)
    pairing = pair_up(scenarios, ids, group, frames, reading, spec)
    images, repeats = pairing.images, pairing.repeats
    if not images:
        raise SymbenchError(
            f"dataset '{name}' has no pair of trajectories that are images of each other "
            f"under {group.name}: no two scenarios are equal but for yaws a multiple of "
            f"{360 / group.rotation_order:g} degrees apart (with the direction turned and "
            f"the leg order relabelled with the base)"
        )
    floor_source = "repeats" if repeats else "high-frequency"
    report = SymmetryReport(
        name,
        robot,
        group.name,
        len(ids),
        floor_source,
        repeats=len(repeats),
        reading=pairing.reading,
    )
    columns = _columns(next(iter(trajectories.values())))
    sq_err = dict.fromkeys(columns, 0.0)
    sq_val = dict.fromkeys(columns, 0.0)
    count = dict.fromkeys(columns, 0)
    max_abs = dict.fromkeys(columns, 0.0)
    flag_diff = dict.fromkeys(FLAGS, 0.0)
    flag_rows = 0
    per_pair_columns: list[tuple[int, int, GroupElement, int, dict[str, float], Alignment]] = []
    for a, b, g in images:
        moved = act_on_raw(g, trajectories[a], frames)
        target = trajectories[b]
        alignment = align_pair(moved, target, unknown)
        shift = alignment.shift
        rows = aligned_rows(moved["t"], target["t"], shift)[0].shape[0]
        rel = {}
        for column in columns:
            diff, values = difference(moved, target, column, shift)
            sq_err[column] += float(np.sum(diff**2))
            sq_val[column] += float(np.sum(values**2))
            count[column] += diff.size
            max_abs[column] = max(max_abs[column], float(np.abs(diff).max(initial=0.0)))
            scale = float(np.sqrt(np.mean(values**2)))
            rel[column] = float(np.sqrt(np.mean(diff**2))) / scale if scale > 0 else 0.0
        for flag in FLAGS:
            if flag in target and flag not in unknown:
                x, y = aligned_rows(
                    np.asarray(moved[flag], np.float64), np.asarray(target[flag], np.float64), shift
                )
                if np.isfinite(x).all() and np.isfinite(y).all():
                    flag_diff[flag] += float(np.mean(np.any(x != y, axis=-1))) * rows
        flag_rows += rows
        per_pair_columns.append((a, b, g, rows, rel, alignment))
    report.repeat_alignments = [
        (a, b, align_pair(trajectories[a], trajectories[b], unknown)) for a, b in repeats
    ]
    shifts = {(a, b): al.shift for a, b, al in report.repeat_alignments}
    floor = _floor(
        trajectories, repeats, columns, floor_source, {i for p in images for i in p[:2]}, shifts
    )
    for column in columns:
        scale = np.sqrt(sq_val[column] / max(count[column], 1))
        error = np.sqrt(sq_err[column] / max(count[column], 1))
        report.columns[column] = {
            "rms_error": float(error),
            "max_abs_error": max_abs[column],
            "rms": float(scale),
            "relative_error": float(error / scale) if scale > 0 else 0.0,
            "relative_floor": float(floor[column] / scale) if scale > 0 else 0.0,
        }
    stepping_differs = any(
        not al.aligned and al.flag_mismatch is not None for _, _, al in report.repeat_alignments
    )
    missing = _missing_fields(scenarios, {i for p in repeats for i in p}, ids, stepping_differs)
    for label, cols in GROUPS.items():
        present = [c for c in cols if c in report.columns]
        if not present:
            continue
        error = _rms([report.columns[c]["relative_error"] for c in present])
        floor_ = _rms([report.columns[c]["relative_floor"] for c in present])
        note = None
        if floor_source == "repeats":
            if stepping_differs:
                note = (
                    "repeats step differently (their flags disagree at every shift): the logs "
                    f"lack a field that tells their motions apart{missing}"
                )
            elif floor_ >= error and floor_ >= UNINFORMATIVE_FLOOR:
                note = (
                    "repeats differ as much as images: the logs lack a field that tells their "
                    f"motions apart{missing}"
                )
        if note is not None:
            report.floor_note = note
        report.groups[label] = {
            "columns": present,
            "relative_error": error,
            "relative_floor": floor_,
            "ratio": error / floor_ if floor_ > 0 else None,  # None: a floor of 0
            "floor_informative": note is None,
            "verdict": verdict(error, floor_, note),
        }
    report.flags = {f: flag_diff[f] / flag_rows for f in FLAGS if flag_rows and f not in unknown}
    for a, b, g, rows, rel, alignment in per_pair_columns:
        by_group = {
            label: _rms([rel[c] for c in cols if c in rel])
            for label, cols in GROUPS.items()
            if any(c in rel for c in cols)
        }
        report.pairs.append(Pair(a, b, g, rows, by_group, alignment))
    return report


def _spec_of(robot: str) -> RobotSpec | None:
    """`robot`'s spec, or None when no robot of that name is registered."""
    from symbench.core.robot.specs import load_robot

    try:
        return load_robot(robot) if robot else None
    except SymbenchError:
        return None


def _missing_fields(
    scenarios: Sequence[Mapping[str, Any]], used: set[int], ids: Sequence[int], stepping: bool
) -> str:
    """' (leg_order?, seed?)': the fields that could tell the motions of repeats apart and
    that none of them has; only the leg order when their flags say they step differently and
    they lack it."""
    chosen = [s for i, s in zip(ids, scenarios) if int(i) in used]
    missing = [f for f in TELLING_FIELDS if all(s.get(f) is None for s in chosen)]
    if stepping and "leg_order" in missing:
        missing = ["leg_order"]
    return f" ({', '.join(f + '?' for f in missing)})" if missing else ""


def _rms(values: Sequence[float]) -> float:
    return float(np.sqrt(np.mean(np.square(values)))) if len(values) else float("nan")


def _floor(
    trajectories: Mapping[int, Mapping[str, np.ndarray]],
    repeats: Sequence[tuple[int, int]],
    columns: Sequence[str],
    source: str,
    used: set[int],
    shifts: Mapping[tuple[int, int], int] | None = None,
) -> dict[str, float]:
    """Per column, the RMS difference two recordings of one scenario would show (repeats
    lined up by `shifts`, rows of a to rows of b)."""
    out = {}
    for column in columns:
        if source == "repeats":
            sq, n = 0.0, 0
            for a, b in repeats:
                shift = (shifts or {}).get((a, b), 0)
                diff, _ = difference(trajectories[a], trajectories[b], column, shift)
                sq, n = sq + float(np.sum(diff**2)), n + diff.size
            out[column] = float(np.sqrt(sq / max(n, 1)))
            continue
        sigmas = []
        for i in sorted(used):
            x = np.asarray(trajectories[i][column], np.float64)
            sigmas.append(_noise_sigma(x.reshape(len(x), -1)))
        sigma = np.concatenate(sigmas)
        out[column] = float(np.sqrt(2.0 * np.nanmean(sigma**2)))
    return out


def verdict(relative_error: float, relative_floor: float, uninformative: str | None = None) -> str:
    """The verdict on a group; `uninformative` says why the floor tells nothing, if so."""
    if relative_error < FLOAT_PRECISION:
        return "exact (float precision)"
    if uninformative:
        return f"no verdict: {uninformative}"
    if relative_error <= relative_floor:
        return "within noise"
    if relative_floor <= 0:
        return "asymmetric (the floor is 0)"
    return f"asymmetric ({relative_error / relative_floor:.3g}x floor)"


def dataset_symmetry(dataset: Any) -> SymmetryReport:
    """The symmetry report of `dataset`, a loaded `Dataset` (its robot's group and leg
    frames): what `symbench data symmetry` prints. A generated dataset's scenarios are read
    as the simulator's input, an imported one's as recorded (see `pair_up`)."""
    from symbench.core.data.storage.files import read_trajectory

    spec = dataset.spec
    trajectories = {
        int(rec["id"]): read_trajectory(dataset.root / rec["file"], dataset.n_legs)
        for rec in dataset.metadata["trajectories"]
    }
    unknown = dataset.metadata.get("unknown_columns") or ()
    imported = dataset.metadata.get("source") == "imported"
    return measure(
        trajectories,
        dataset.scenarios,
        spec.group,
        dataset.frames,
        dataset.id,
        dataset.robot,
        unknown,
        reading="auto" if imported else "simulator",
        spec=spec,
    )


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
        title=f"{report.dataset}: {len(report.pairs)} image pairs under {report.group} "
        f"(floor: {report.floor_source})",
    )
    ax.title.set_fontsize(8)
    ax.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.0, 1.0))
    fig.tight_layout()
    buffer = io.BytesIO()
    fig.savefig(buffer, format="png", metadata={"Software": None})
    plt.close(fig)
    write_bytes_atomic(path, buffer.getvalue())
    return path
