"""A split's image overlap, measured once per output folder (`EvaluationContext.image_overlap`).

The overlap depends on the dataset's content, the split and the seed, never on the model, and
on dataset v7 it cost a run more than its closed loop's rollouts (hexa `iid`: about 150 s of
comparisons); a sweep's five models of a split and seed now measure it once. The cache file is
named by the dataset id, its content hash, the split and the seed, and holds them with
`CACHE_VERSION`: a file of another key or version, or one that does not read as an overlap
(damaged, edited), is measured again and rewritten, never trusted and never an internal error.
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

from filelock import FileLock

from symbench.core.common.atomic import write_text_atomic
from symbench.core.data.symmetry.overlap import (
    ClassOverlap,
    SideOverlap,
    SplitOverlap,
    split_overlap,
)

CACHE_VERSION = 1  # bump when what the overlap counts, or how, changes (symmetry/compare.py)
FOLDER = "image-overlap-cache"
# what reading a damaged file may raise; each means "measure it again"
DAMAGE = (OSError, ValueError, KeyError, TypeError, AttributeError, RecursionError)


def cached_split_overlap(dataset: Any, split: str, seed: int, output_dir: Path) -> SplitOverlap:
    """`split_overlap(dataset, split, seed)`, read from `output_dir`'s cache when measured
    there before; measured and written otherwise. Runs of one folder in parallel wait for
    the one measuring it."""
    key = {
        "version": CACHE_VERSION,
        "dataset": dataset.id,
        "content_hash": dataset.content_hash,
        "split": split,
        "seed": int(seed),
    }
    name = f"{dataset.id}-{dataset.content_hash[:12]}__{split}__seed{seed}.json"
    path = Path(output_dir) / FOLDER / name
    path.parent.mkdir(parents=True, exist_ok=True)
    with FileLock(path.with_name(f"{path.name}.lock")):
        cached = _read(path, key)
        if cached is not None:
            return cached
        measured = split_overlap(dataset, split, seed)
        write_text_atomic(path, json.dumps({"key": key, "overlap": _encode(measured)}, indent=1))
        return measured


def _read(path: Path, key: dict[str, Any]) -> SplitOverlap | None:
    try:
        data = json.loads(path.read_text())
        return _decode(data["overlap"]) if data["key"] == key else None
    except DAMAGE:  # missing (OSError) or damaged
        return None


def _encode(overlap: SplitOverlap) -> dict[str, Any]:
    return {
        "dataset": overlap.dataset,
        "split": overlap.split,
        "seed": overlap.seed,
        "group": overlap.group,
        "mirror_group": overlap.mirror_group,
        "seconds": overlap.seconds,
        "comparisons": overlap.comparisons,
        "sides": {
            name: {
                "climbs": side.climbs,
                "classes": {
                    cls: [c.distinct_exact, c.distinct_near, c.exact_images, c.near_images]
                    for cls, c in side.classes.items()
                },
            }
            for name, side in overlap.sides.items()
        },
    }


def _decode(data: dict[str, Any]) -> SplitOverlap:
    """The overlap `_encode` wrote; a field of another type raises TypeError."""
    sides = {
        _typed(name, str): SideOverlap(
            _typed(side["climbs"], int),
            {
                _typed(cls, str): ClassOverlap(
                    _typed(de, int), _typed(dn, int), _count(ei), _count(ni)
                )
                for cls, (de, dn, ei, ni) in side["classes"].items()
            },
        )
        for name, side in data["sides"].items()
    }
    return SplitOverlap(
        _typed(data["dataset"], str),
        _typed(data["split"], str),
        _typed(data["seed"], int),
        _typed(data["group"], str),
        _typed(data["mirror_group"], str),
        sides,
        float(_typed(data["seconds"], (int, float))),
        _typed(data["comparisons"], int),
    )


def _typed(value: Any, types: type | tuple[type, ...]) -> Any:
    if not isinstance(value, types) or isinstance(value, bool):
        raise TypeError(f"overlap cache field {value!r} is not {types}")
    return value


def _count(value: Any) -> int | None:
    return None if value is None else _typed(value, int)
