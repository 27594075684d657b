"""What `symbench data info` reports: sizes, failures and every registered split's counts."""

from __future__ import annotations

from typing import Any

import numpy as np

from symbench.core.common.errors import SymbenchError
from symbench.core.data.dataset import Dataset
from symbench.core.plugin.registry import collect


def split_counts(ds: Dataset, split: str, seed: int) -> dict[str, Any]:
    """Trajectories and samples per part, and whether the parts are disjoint."""
    try:
        parts = ds.split_indices(split, seed)
    except SymbenchError as exc:
        return {"error": str(exc)}
    samples = dict(zip(ds.trajectory_ids.tolist(), ds.n_samples.tolist()))
    out: dict[str, Any] = {}
    for name in ("train", "val", "test"):
        ids = getattr(parts, name)
        out[name] = {"trajectories": len(ids), "samples": int(sum(samples[i] for i in ids))}
    all_ids = np.concatenate([parts.train, parts.val, parts.test])
    out["disjoint"] = len(np.unique(all_ids)) == len(all_ids)
    return out


def dataset_info(ds: Dataset, seed: int = 0) -> dict[str, Any]:
    meta = ds.metadata
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
        "splits": {name: split_counts(ds, name, seed) for name in collect("splits")},
        "split_seed": seed,
    }
