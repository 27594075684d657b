"""How many held-out climbs of a split a model has, in effect, already seen: the image overlap.

A model that respects a class of symmetries (see `compare`: none, heading, the robot's
group, the group with mirrors) predicts an image of a training climb as well as the climb
itself, so such a test climb measures recall, not generalisation. For each held-out side
(validation, test) and each class this counts the climbs that are images of some training
climb within `EXACT_TOLERANCE` (float precision: the simulator's rotated twins) and within
`NEAR_TOLERANCE` (near images: the same motion up to small differences), judged on the raw
states only, so it works on imported logs without scenario fields. On every side (train
too) it counts the distinct motions per class: climbs gathered greedily, in id order, with
the first earlier representative they are an image of (at each tolerance).

`split_overlap(dataset, split, seed)` is the entry point (what the runs layer may record);
`DatasetOverlap` keeps the loaded climbs and the errors already computed, so that
`symbench data info` asks about every registered split at the cost of little more than one.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Any

from symbench.core.common.errors import SymbenchError
from symbench.core.data.symmetry.compare import (
    CLASSES,
    EXACT_TOLERANCE,
    NEAR_TOLERANCE,
    Climbs,
    check_columns,
)

SIDES = ("train", "val", "test")
HELD_OUT = ("val", "test")


@dataclass(frozen=True)
class ClassOverlap:
    """One side under one class: images of training climbs (held-out sides only) and
    distinct motions, at the exact and the near tolerance."""

    distinct_exact: int
    distinct_near: int
    exact_images: int | None = None  # None on the training side
    near_images: int | None = None

    def to_dict(self, climbs: int) -> dict[str, Any]:
        out: dict[str, Any] = {
            "distinct_motions_exact": self.distinct_exact,
            "distinct_motions_near": self.distinct_near,
        }
        if self.exact_images is not None and self.near_images is not None:
            out |= {
                "exact_images": self.exact_images,
                "near_images": self.near_images,
                "exact_image_share": self.exact_images / climbs if climbs else None,
                "near_image_share": self.near_images / climbs if climbs else None,
            }
        return out


@dataclass(frozen=True)
class SideOverlap:
    climbs: int
    classes: dict[str, ClassOverlap]

    def to_dict(self) -> dict[str, Any]:
        return {
            "climbs": self.climbs,
            "classes": {k: v.to_dict(self.climbs) for k, v in self.classes.items()},
        }


@dataclass(frozen=True)
class SplitOverlap:
    """The image overlap of one split (see the module's docstring)."""

    dataset: str
    split: str
    seed: int
    group: str
    mirror_group: str
    sides: dict[str, SideOverlap]
    seconds: float = 0.0
    comparisons: int = 0

    def to_dict(self) -> dict[str, Any]:
        return {
            "dataset": self.dataset,
            "split": self.split,
            "seed": self.seed,
            "classes": {
                "none": "world frame as recorded",
                "heading": "scene turned about gravity",
                "group": f"{self.group} (legs relabelled, base turned) and heading",
                "mirror": f"{self.mirror_group} and heading",
            },
            "exact_tolerance": EXACT_TOLERANCE,
            "near_tolerance": NEAR_TOLERANCE,
            "sides": {k: v.to_dict() for k, v in self.sides.items()},
            "seconds": round(self.seconds, 3),
            "comparisons": self.comparisons,
        }


def image_counts(
    climbs: Climbs, side: Sequence[int], train: Sequence[int]
) -> dict[str, tuple[int, int]]:
    """Per class, how many climbs of `side` are exact and near images of a `train` climb."""
    exact = dict.fromkeys(CLASSES, 0)
    near = dict.fromkeys(CLASSES, 0)
    for b in side:
        best = [float("inf")] * len(CLASSES)
        for a in climbs.candidates(b, train):
            if best[0] < EXACT_TOLERANCE:
                break  # an exact image with nothing turned: every class is settled
            for cls in range(len(CLASSES)):
                if best[cls] < EXACT_TOLERANCE:
                    break  # this class and the wider ones are settled
                tier_best = climbs.tier_error(a, b, cls)
                for wider in range(cls, len(CLASSES)):
                    best[wider] = min(best[wider], tier_best)
        for cls, name in enumerate(CLASSES):
            exact[name] += best[cls] < EXACT_TOLERANCE
            near[name] += best[cls] < NEAR_TOLERANCE
    return {name: (exact[name], near[name]) for name in CLASSES}


def distinct_motions(climbs: Climbs, side: Sequence[int], cls: int, tolerance: float) -> int:
    """Climbs of `side` up to images under class `cls`: each joins the first earlier
    representative it is an image of within `tolerance`, else becomes one."""
    representatives: list[int] = []
    for b in side:
        joined = any(
            climbs.class_error(a, b, cls, tolerance) < tolerance
            for a in climbs.candidates(b, representatives)
        )
        if not joined:
            representatives.append(b)
    return len(representatives)


@dataclass
class DatasetOverlap:
    """A dataset's climbs loaded once, for the overlap of any of its splits."""

    dataset: Any  # a loaded `symbench.core.data.dataset.Dataset`
    _climbs: Climbs | None = field(default=None, repr=False)

    def climbs(self) -> Climbs:
        if self._climbs is None:
            from symbench.core.data.storage.files import read_trajectory

            ds = self.dataset
            unknown = tuple(ds.metadata.get("unknown_columns") or ())
            raw = {}
            for rec in ds.metadata["trajectories"]:
                raw[int(rec["id"])] = read_trajectory(ds.root / rec["file"], ds.n_legs)
                check_columns(raw[int(rec["id"])], unknown, f"dataset '{ds.id}'")
            spec = ds.spec
            self._climbs = Climbs(raw, spec.group, spec.geometry_group, ds.frames, unknown)
        return self._climbs

    def split(self, split: str, seed: int = 0) -> SplitOverlap:
        """The overlap of `split` (registered or a column split) with `seed`; a split that
        cannot be measured is refused in one line naming the dataset, split and why."""
        import time

        start = time.perf_counter()
        ds = self.dataset
        where = f"dataset '{ds.id}', split '{split}' (seed {seed})"
        try:
            parts = ds.split_indices(split, seed)
            climbs = self.climbs()
        except SymbenchError as exc:
            raise SymbenchError(f"image overlap of {where}: {exc}") from None
        ids = {name: [int(i) for i in getattr(parts, name)] for name in SIDES}
        empty = [name for name in ("train", "test") if not ids[name]]
        if empty:
            raise SymbenchError(f"image overlap of {where}: no {' or '.join(empty)} climbs")
        before = climbs.compared
        sides = {}
        for name in SIDES:
            if not ids[name]:
                continue
            counts = image_counts(climbs, ids[name], ids["train"]) if name in HELD_OUT else {}
            sides[name] = SideOverlap(
                len(ids[name]),
                {
                    cls: ClassOverlap(
                        distinct_motions(climbs, ids[name], k, EXACT_TOLERANCE),
                        distinct_motions(climbs, ids[name], k, NEAR_TOLERANCE),
                        *counts.get(cls, (None, None)),
                    )
                    for k, cls in enumerate(CLASSES)
                },
            )
        return SplitOverlap(
            ds.id,
            split,
            int(seed),
            climbs.group.name,
            climbs.mirrors.name,
            sides,
            time.perf_counter() - start,
            climbs.compared - before,
        )


def split_overlap(dataset: Any, split: str, seed: int = 0) -> SplitOverlap:
    """The image overlap of `dataset`'s (a loaded `Dataset`) split `split` with `seed`."""
    return DatasetOverlap(dataset).split(split, seed)
