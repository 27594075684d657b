"""How symmetric a dataset is: `symbench data symmetry ID`.

**Image pairs.** Two trajectories are images of each other under a rotation g of the robot's
group when their scenarios are equal but for the initial yaw, and the yaws differ by g's
angle (a multiple of 360 / rotation order degrees): the simulator carries a yaw of k whole
symmetry steps to the first step's climb turned k times (`Climb.from_scenario`), so the
second trajectory is the first one seen with turned base axes and relabelled legs. For such
a pair (A, B), `act_on_raw(g, A)` relabels A's legs and turns its base axes the way B's are
turned; on a perfectly symmetric robot it equals B. Reflections are not paired (no scenario
field says that one climb is another's mirror image).

**The error after relabelling**, per column, is the RMS of `g . A - B` over the pairs' rows
(trajectories of unequal length are compared over the rows both have; quaternions up to
sign), relative to the column's RMS in B. Columns are gathered into groups: joint states
(q, qd, qdd), torques (tau) and base (position, orientation, velocities, acceleration); a
group's relative error is the RMS of its columns' relative errors. Contact and magnet flags
are compared as the share of rows where a flag differs.

**The noise floor** is what two recordings of the same scenario would differ by:

- `repeats`: when some scenario appears more than once (a real robot's repeated runs), the
  RMS difference between repeats, per column;
- `high-frequency`: otherwise, the dataset's own sampling noise: per scalar channel, the
  noise sigma estimated from third differences (white noise of sigma gives third differences
  of variance 20 sigma^2; a robust scale, 1.4826 x median absolute deviation, ignores the
  rare jumps at contact changes), times sqrt(2) for the difference of two recordings. A
  smooth signal's own third differences count as noise here, so this floor is an upper
  bound on the sampling noise.

A dataset whose error is at the float-precision level (`FLOAT_PRECISION`) is exactly
symmetric (a generated dataset); one whose error is below its floor is symmetric within its
noise; anything above is a measurable asymmetry, reported as the ratio error / floor.
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
from symbench.core.data.symmetry.raw_action import act_on_raw, base_map
from symbench.core.data.views.frames import LegFrames
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


@dataclass(frozen=True)
class Pair:
    """Trajectory `b` is trajectory `a` acted on by `element` (ids as in the dataset)."""

    a: int
    b: int
    element: GroupElement
    rows: int
    relative_error: dict[str, float]  # per column group


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

    def to_dict(self) -> dict[str, Any]:
        return {
            "dataset": self.dataset,
            "robot": self.robot,
            "group": self.group,
            "trajectories": self.trajectories,
            "image_pairs": len(self.pairs),
            "repeat_pairs": self.repeats,
            "floor": self.floor_source,
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
                }
                for p in self.pairs
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


def find_pairs(
    scenarios: Sequence[Mapping[str, Any]],
    ids: Sequence[int],
    group: LegGroup,
    frames: LegFrames,
) -> tuple[list[tuple[int, int, GroupElement]], list[tuple[int, int]]]:
    """Image pairs (a, b, g) with b = g . a, and repeat pairs (a, b) of one scenario."""
    rotations = rotation_angles(group, frames)
    by_rest: dict[str, list[int]] = {}
    by_all: dict[str, list[int]] = {}
    for i, scenario in zip(ids, scenarios):
        by_all.setdefault(_scenario_key(scenario), []).append(int(i))
        if scenario.get("yaw_deg") is not None:
            by_rest.setdefault(_scenario_key(scenario, ("yaw_deg",)), []).append(int(i))
    yaw = {
        int(i): float(s["yaw_deg"]) for i, s in zip(ids, scenarios) if s.get("yaw_deg") is not None
    }
    images = []
    for members in by_rest.values():
        for a, b in combinations(members, 2):
            turn = (yaw[b] - yaw[a]) % 360.0
            for g, angle in rotations:
                if _same_angle(turn, angle):
                    images.append((a, b, g))
                    break
    repeats = [pair for members in by_all.values() for pair in combinations(members, 2)]
    return images, repeats


def _columns(raw: Mapping[str, np.ndarray]) -> list[str]:
    return [c for cols in GROUPS.values() for c in cols if c in raw]


def _difference(
    moved: Mapping[str, np.ndarray], b: Mapping[str, np.ndarray], column: str, rows: int
):
    x = np.asarray(moved[column][:rows], np.float64)
    y = np.asarray(b[column][:rows], np.float64)
    if column == "base_quat":  # q and -q are one orientation
        flip = np.sum(x * y, axis=-1, keepdims=True) < 0
        x = np.where(flip, -x, x)
    return (x - y).reshape(rows, -1), y.reshape(rows, -1)


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
) -> SymmetryReport:
    """The symmetry report of raw trajectories by id (`scenarios` in the same id order);
    flags in `unknown` (declared unknown by an import, stored as 0) are not compared."""
    ids = list(trajectories)
    images, repeats = find_pairs(scenarios, ids, group, frames)
    if not images:
        raise SymbenchError(
            f"dataset '{name}' has no pair of trajectories that are images of each other "
            f"under {group.name}: no two scenarios are equal but for yaws a multiple of "
            f"{360 / group.rotation_order:g} degrees apart"
        )
    floor_source = "repeats" if repeats else "high-frequency"
    report = SymmetryReport(name, robot, group.name, len(ids), floor_source, repeats=len(repeats))
    columns = _columns(next(iter(trajectories.values())))
    sq_err = dict.fromkeys(columns, 0.0)
    sq_val = dict.fromkeys(columns, 0.0)
    count = dict.fromkeys(columns, 0)
    max_abs = dict.fromkeys(columns, 0.0)
    flag_diff = dict.fromkeys(FLAGS, 0.0)
    flag_rows = 0
    per_pair_columns: list[tuple[int, int, GroupElement, int, dict[str, float]]] = []
    for a, b, g in images:
        moved = act_on_raw(g, trajectories[a], frames)
        target = trajectories[b]
        rows = min(len(moved["t"]), len(target["t"]))
        rel = {}
        for column in columns:
            diff, values = _difference(moved, target, column, rows)
            sq_err[column] += float(np.sum(diff**2))
            sq_val[column] += float(np.sum(values**2))
            count[column] += diff.size
            max_abs[column] = max(max_abs[column], float(np.abs(diff).max(initial=0.0)))
            scale = float(np.sqrt(np.mean(values**2)))
            rel[column] = float(np.sqrt(np.mean(diff**2))) / scale if scale > 0 else 0.0
        for flag in FLAGS:
            if flag in target and flag not in unknown:
                x = np.asarray(moved[flag][:rows], np.float64)
                y = np.asarray(target[flag][:rows], np.float64)
                if np.isfinite(x).all() and np.isfinite(y).all():
                    flag_diff[flag] += float(np.mean(np.any(x != y, axis=-1))) * rows
        flag_rows += rows
        per_pair_columns.append((a, b, g, rows, rel))
    floor = _floor(trajectories, repeats, columns, floor_source, {i for p in images for i in p[:2]})
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
    for label, cols in GROUPS.items():
        present = [c for c in cols if c in report.columns]
        if not present:
            continue
        error = _rms([report.columns[c]["relative_error"] for c in present])
        floor_ = _rms([report.columns[c]["relative_floor"] for c in present])
        report.groups[label] = {
            "columns": present,
            "relative_error": error,
            "relative_floor": floor_,
            "ratio": error / floor_ if floor_ > 0 else None,  # None: a floor of 0
            "verdict": verdict(error, floor_),
        }
    report.flags = {f: flag_diff[f] / flag_rows for f in FLAGS if flag_rows and f not in unknown}
    for a, b, g, rows, rel in per_pair_columns:
        by_group = {
            label: _rms([rel[c] for c in cols if c in rel])
            for label, cols in GROUPS.items()
            if any(c in rel for c in cols)
        }
        report.pairs.append(Pair(a, b, g, rows, by_group))
    return report


def _rms(values: Sequence[float]) -> float:
    return float(np.sqrt(np.mean(np.square(values)))) if len(values) else float("nan")


def _floor(
    trajectories: Mapping[int, Mapping[str, np.ndarray]],
    repeats: Sequence[tuple[int, int]],
    columns: Sequence[str],
    source: str,
    used: set[int],
) -> dict[str, float]:
    """Per column, the RMS difference two recordings of one scenario would show."""
    out = {}
    for column in columns:
        if source == "repeats":
            sq, n = 0.0, 0
            for a, b in repeats:
                rows = min(len(trajectories[a]["t"]), len(trajectories[b]["t"]))
                diff, _ = _difference(trajectories[a], trajectories[b], column, rows)
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


def verdict(relative_error: float, relative_floor: float) -> str:
    if relative_error < FLOAT_PRECISION:
        return "exact (float precision)"
    if relative_error <= relative_floor:
        return "within noise"
    if relative_floor <= 0:
        return "asymmetric (the floor is 0)"
    return f"asymmetric ({relative_error / relative_floor:.3g}x floor)"


def dataset_symmetry(dataset: Any) -> SymmetryReport:
    """The symmetry report of `dataset`, a loaded `Dataset` (its robot's group and leg
    frames): what `symbench data symmetry` prints."""
    from symbench.core.data.storage.files import read_trajectory

    spec = dataset.spec
    trajectories = {
        int(rec["id"]): read_trajectory(dataset.root / rec["file"], dataset.n_legs)
        for rec in dataset.metadata["trajectories"]
    }
    unknown = dataset.metadata.get("unknown_columns") or ()
    return measure(
        trajectories,
        dataset.scenarios,
        spec.group,
        dataset.frames,
        dataset.id,
        dataset.robot,
        unknown,
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
