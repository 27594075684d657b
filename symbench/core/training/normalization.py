"""Normalization statistics that commute with the robot's symmetry group.

Statistics come from the training split only and are shared across legs (and across nodes
and edges of a graph): one mean and one standard deviation per feature column, reduced over
samples and every other axis. Columns that a mirror flips (coxa angles, lateral components)
get mean zero, so normalizing commutes with reflections too. Targets are normalized per
joint type, shared across legs. The model wrapper applies them, so the network sees
normalized data and the caller sees N m.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from symbench.core.common.arrays import ViewArrays
from symbench.core.common.errors import SymbenchError
from symbench.core.data.views import schema
from symbench.core.data.views.model_dims import ModelDims

MIN_STD = 1e-8
TARGET_KEY = "target"


@dataclass(frozen=True)
class Normalizer:
    stats: dict[str, tuple[np.ndarray, np.ndarray]]  # key -> (mean, std) over the last axis

    @classmethod
    def fit(cls, data: ViewArrays) -> Normalizer:
        stats = {
            k: _mean_std(v, _zero_mean_columns(data.view, data.variant, k, v.shape[-1]), k)
            for k, v in data.inputs.items()
        }
        stats[TARGET_KEY] = _mean_std(data.target, _TARGET_ZERO_MEAN, TARGET_KEY)
        return cls(stats)

    @classmethod
    def random(cls, dims: ModelDims, rng: np.random.Generator) -> Normalizer:
        """Arbitrary statistics of the right structure, for the equivariance kit."""
        stats = {}
        for key, shape in (*dims.inputs, (TARGET_KEY, (3,))):
            n = shape[-1]
            zero = (
                _TARGET_ZERO_MEAN
                if key == TARGET_KEY
                else _zero_mean_columns(dims.view, dims.variant, key, n)
            )
            mean = np.where(zero, 0.0, rng.normal(size=n))
            stats[key] = (mean, rng.uniform(0.5, 2.0, size=n))
        return cls(stats)

    def normalize(self, key: str, x: np.ndarray) -> np.ndarray:
        mean, std = self.stats[key]
        return (x - mean) / std

    def normalize_inputs(self, inputs: dict[str, np.ndarray]) -> dict[str, np.ndarray]:
        return {k: self.normalize(k, v) for k, v in inputs.items()}

    def denormalize_target(self, y: np.ndarray) -> np.ndarray:
        mean, std = self.stats[TARGET_KEY]
        return y * std + mean

    def to_arrays(self) -> dict[str, np.ndarray]:
        out = {}
        for key, (mean, std) in self.stats.items():
            out[f"normalization/{key}/mean"] = mean
            out[f"normalization/{key}/std"] = std
        return out

    @classmethod
    def from_arrays(cls, arrays: dict[str, np.ndarray]) -> Normalizer:
        keys = {k.split("/")[1] for k in arrays if k.startswith("normalization/")}
        if TARGET_KEY not in keys:
            raise SymbenchError("checkpoint holds no target normalization statistics")
        incomplete = sorted(
            k
            for k in keys
            if f"normalization/{k}/mean" not in arrays or f"normalization/{k}/std" not in arrays
        )
        if incomplete:
            raise SymbenchError(
                "checkpoint lacks the mean or standard deviation of " + ", ".join(incomplete)
            )
        return cls(
            {
                k: (arrays[f"normalization/{k}/mean"], arrays[f"normalization/{k}/std"])
                for k in sorted(keys)
            }
        )


_TARGET_ZERO_MEAN = schema.TARGET.reflection_signs < 0


def _zero_mean_columns(view: str, variant: str, key: str, n: int) -> np.ndarray:
    if view == "leg_grouped" and key == "x":
        return schema.leg_grouped_input(variant).reflection_signs < 0
    return np.zeros(n, dtype=bool)


def _mean_std(x: np.ndarray, zero_mean: np.ndarray, key: str) -> tuple[np.ndarray, np.ndarray]:
    flat = np.asarray(x, dtype=np.float64).reshape(-1, x.shape[-1])
    if not np.isfinite(flat).all():
        raise SymbenchError("training data holds NaN or infinite values; cannot normalize")
    with np.errstate(over="ignore"):  # values near 1e300 overflow: refused just below
        mean = np.where(zero_mean, 0.0, flat.mean(axis=0))
        std = np.sqrt(((flat - mean) ** 2).mean(axis=0))
    if not (np.isfinite(mean).all() and np.isfinite(std).all()):
        raise SymbenchError(
            f"training data '{key}' is too large to normalize: its mean or "
            "standard deviation overflows float64"
        )
    return mean, np.where(std < MIN_STD, 1.0, std)
