"""The error between image pairs after relabelling, against the noise floor.

`symbench data symmetry` (report.py, whose docstring states the rule) compares each image
pair found by `pairing.py` column by column after acting on one with the group element,
and sets the error against what two recordings of one scenario would differ by: the
repeats, else the dataset's own high-frequency noise. This module holds that arithmetic
(the noise sigma from third differences, the floor, the fields repeats lack) and fills a
`SymmetryReport` with it.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import Any

import numpy as np

from symbench.core.common.errors import SymbenchError
from symbench.core.data.symmetry.alignment import (
    Alignment,
    align_pair,
    aligned_rows,
    difference,
)
from symbench.core.data.symmetry.pairing import pair_up
from symbench.core.data.symmetry.raw_action import act_on_raw
from symbench.core.data.symmetry.report import (
    FLAGS,
    GROUPS,
    NoImagePairsError,
    Pair,
    SymmetryReport,
    verdict,
)
from symbench.core.data.views.frames import LegFrames
from symbench.core.robot.specs import RobotSpec
from symbench.core.symmetry.groups import GroupElement, LegGroup

MAD_TO_SIGMA = 1.4826  # sigma of a normal distribution / its median absolute deviation
THIRD_DIFFERENCE_VARIANCE = 20.0  # var(third difference of white noise) / sigma^2
UNINFORMATIVE_FLOOR = 0.5  # a relative floor this large is no noise: the repeats differ
# the scenario fields that may tell two motions apart, named when repeats evidently differ
TELLING_FIELDS = ("leg_order", "direction", "seed", "inclination_deg", "heading_deg")


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
        raise NoImagePairsError(
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
