"""Model-ready arrays of one view: the contract between datasets, models and evaluators.

Every model, whatever its view, predicts torques shaped (N, n_legs, 3) (coxa, femur,
tibia per leg), so that metrics, the equivariance kit and the controller treat all models
alike. Inputs differ by view:

- leg_grouped: {"x": (N, n_legs, F)} with F from `schema.leg_grouped_input(variant)`;
- vector:      {"x": (N, D)} with columns from `schema.vector_input(n_legs, variant)`;
- body_graph:  {"nodes": (N, V, Fn), "edges": (N, E, Fe), "globals": (N, Fg)} laid out as
               `schema.body_graph(n_legs, variant)` (edge 3 i + j is joint j of leg i).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from symbench.core.common.errors import SymbenchError


@dataclass(frozen=True)
class ViewArrays:
    view: str
    variant: str
    n_legs: int
    inputs: dict[str, np.ndarray]
    target: np.ndarray  # (N, n_legs, 3) joint torques, N m
    trajectory: np.ndarray  # (N,) index of the trajectory each sample comes from
    # column names of each input's last axis (per-leg features for leg_grouped)
    feature_names: dict[str, tuple[str, ...]] = field(default_factory=dict)

    def __post_init__(self) -> None:
        n = len(self.target)
        if self.target.shape[1:] != (self.n_legs, 3):
            raise SymbenchError(
                f"{self.view}: target shape {self.target.shape}, expected (N, {self.n_legs}, 3)"
            )
        for key, a in self.inputs.items():
            if len(a) != n:
                raise SymbenchError(
                    f"{self.view}: input '{key}' has {len(a)} samples, target has {n}"
                )
        if len(self.trajectory) != n:
            raise SymbenchError(
                f"{self.view}: {len(self.trajectory)} trajectory ids for {n} samples"
            )

    def __len__(self) -> int:
        return len(self.target)

    def take(self, index: np.ndarray) -> ViewArrays:
        """The samples at `index` (a boolean mask or integer indices)."""
        return ViewArrays(
            self.view,
            self.variant,
            self.n_legs,
            {k: v[index] for k, v in self.inputs.items()},
            self.target[index],
            self.trajectory[index],
            self.feature_names,
        )
