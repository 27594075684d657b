"""What `symbench data info` reports: sizes, failures, provenance, every registered split's
counts, the scenario values on each side of each split and its image overlap (how many
held-out climbs are images of training climbs, per symmetry class: symmetry/overlap.py)."""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import numpy as np

from symbench.core.common.errors import SymbenchError
from symbench.core.data.dataset import Dataset
from symbench.core.data.symmetry.overlap import DatasetOverlap
from symbench.core.plugin.registry import collect

SCENARIO_COLUMNS = ("inclination_deg", "heading_deg", "yaw_deg", "direction", "leg_order")


def _shown(scenario: dict[str, Any], column: str) -> Any:
    """A scenario's value of `column` as shown (None: it has none); the stepping sequence as
    `default`, `reversed` or the legs in order."""
    if column != "leg_order" or column not in scenario:
        return scenario.get(column)
    order = scenario[column]
    if order is None:
        return "default"
    if list(order) == sorted(order, reverse=True):
        return "reversed"
    return ",".join(map(str, order))


def scenario_values(ds: Dataset, ids: np.ndarray) -> dict[str, list[Any]]:
    """The distinct values of each scenario column among trajectories `ids` (a column none of
    them has is left out)."""
    by_id = dict(zip(ds.trajectory_ids.tolist(), ds.scenarios, strict=True))
    out: dict[str, list[Any]] = {}
    for column in SCENARIO_COLUMNS:
        values = {_shown(by_id[i], column) for i in ids.tolist()} - {None}
        if values:
            out[column] = sorted(values, key=lambda v: (isinstance(v, str), v))
    return out


def split_counts(ds: Dataset, split: str, seed: int) -> dict[str, Any]:
    """Trajectories, samples and scenario values per part, and whether the parts are
    disjoint."""
    try:
        parts = ds.split_indices(split, seed)
    except SymbenchError as exc:
        return {"error": str(exc)}
    samples = dict(zip(ds.trajectory_ids.tolist(), ds.n_samples.tolist(), strict=True))
    out: dict[str, Any] = {}
    for name in ("train", "val", "test"):
        ids = getattr(parts, name)
        out[name] = {
            "trajectories": len(ids),
            "samples": int(sum(samples[i] for i in ids)),
            "scenarios": scenario_values(ds, ids),
        }
    all_ids = np.concatenate([parts.train, parts.val, parts.test])
    out["unused"] = len(ds.trajectory_ids) - len(all_ids)
    out["disjoint"] = len(np.unique(all_ids)) == len(all_ids)
    return out


def split_image_overlap(overlap: DatasetOverlap, split: str, seed: int) -> dict[str, Any]:
    """The split's image overlap as JSON, or {"error": one line} when it cannot be measured."""
    try:
        return overlap.split(split, seed).to_dict()
    except SymbenchError as exc:
        return {"error": str(exc)}


def dataset_info(
    ds: Dataset, seed: int = 0, splits: Sequence[str] = (), overlap: bool = True
) -> dict[str, Any]:
    """Everything `data info` shows; `splits` adds column splits (or any split by name) to
    the registered ones; `overlap` measures each split's image overlap (seconds per split
    on a small dataset; the climbs are loaded and pairs compared once for all splits)."""
    meta = ds.metadata
    names = list(collect("splits")) + [s for s in splits if s not in collect("splits")]
    counts = {name: split_counts(ds, name, seed) for name in names}
    if overlap:
        measured = DatasetOverlap(ds)
        for name, part in counts.items():
            if "error" not in part:
                part["image_overlap"] = split_image_overlap(measured, name, seed)
    return {
        "id": ds.id,
        "robot": ds.robot,
        "source": meta["source"],
        "preset": meta.get("preset"),
        "content_hash": ds.content_hash,
        "trajectories": len(meta["trajectories"]),
        "failed": len(meta["failures"]),
        "failures": meta["failures"],
        "samples": int(ds.n_samples.sum()),
        "record_period_s": meta["record_period_s"],
        "size_bytes": sum((ds.root / r["file"]).stat().st_size for r in meta["trajectories"]),
        "versions": meta["versions"],
        "provenance": meta.get("provenance", {}),
        "unknown_columns": meta.get("unknown_columns", []),
        "import": meta.get("import"),
        "scenarios": scenario_values(ds, ds.trajectory_ids),
        "splits": counts,
        "split_seed": seed,
    }
