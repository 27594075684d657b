"""Synthetic data in all three views with a known equivariant target, for tests and benches.

Per-leg joint states and flags are random; the target of leg i is a fixed random smooth
function of leg i's joint states and flags and of their mean over all legs, so it is exactly
equivariant to every permutation of legs and every view carries what is needed to learn it.
The function depends on `TARGET_SEED` only, so data drawn with different seeds (training,
validation) share one target function.
"""

from __future__ import annotations

import numpy as np

from symbench.core.common.arrays import ViewArrays
from symbench.core.data.views import schema

TARGET_SEED = 20240531
_HIDDEN = 16
_FLAGS = ("contact", "magnet")


def synthetic_views(
    n_legs: int, n_samples: int, variant: str = "acc", seed: int = 0, n_trajectories: int = 8
) -> dict[str, ViewArrays]:
    """{view name: ViewArrays} of the same samples in the leg_grouped, vector and body_graph
    views."""
    rng = np.random.default_rng(seed)
    layout = schema.leg_grouped_input(variant)
    x = rng.normal(size=(n_samples, n_legs, layout.size))
    for flag in _FLAGS:
        x[..., layout.slice(flag)] = rng.integers(0, 2, size=(n_samples, n_legs, 1))
    joints = {name: x[..., layout.slice(name)] for name in _joint_names(variant)}
    flags = {name: x[..., layout.slice(name)][..., 0] for name in _FLAGS}
    base = rng.normal(size=(n_samples, len(schema.body_graph(n_legs, variant).global_columns)))
    target = equivariant_target(
        np.concatenate([*joints.values(), *(f[..., None] for f in flags.values())], -1)
    )
    trajectory = np.arange(n_samples) * n_trajectories // max(n_samples, 1)
    inputs = {
        "leg_grouped": {"x": x},
        "vector": {"x": _vector(base, joints, flags)},
        "body_graph": _body_graph(base, joints, flags, n_legs, variant),
    }
    return {
        view: ViewArrays(view, variant, n_legs, inp, target, trajectory)
        for view, inp in inputs.items()
    }


def equivariant_target(z: np.ndarray) -> np.ndarray:
    """(N, legs, 3) from per-leg features z (N, legs, F): tanh features of each leg and their
    mean."""
    rng = np.random.default_rng([TARGET_SEED, z.shape[-1]])
    w_own, w_all = rng.normal(size=(2, z.shape[-1], _HIDDEN)) / np.sqrt(z.shape[-1])
    out = rng.normal(size=(2 * _HIDDEN, 3)) / np.sqrt(_HIDDEN)
    own = np.tanh(z @ w_own)
    shared = np.broadcast_to(np.tanh(z @ w_all).mean(axis=1, keepdims=True), own.shape)
    return np.concatenate([own, shared], -1) @ out


def _joint_names(variant: str) -> tuple[str, ...]:
    return schema.body_graph(1, variant).edge_columns


def _vector(
    base: np.ndarray, joints: dict[str, np.ndarray], flags: dict[str, np.ndarray]
) -> np.ndarray:
    """Columns as `schema.vector_input`: base, then per name, leg and joint, then flags per leg."""
    n = len(base)
    joint_cols = np.stack(list(joints.values()), axis=1).reshape(n, -1)
    flag_cols = np.stack([flags[f] for f in _FLAGS], axis=1).reshape(n, -1)
    return np.concatenate([base, joint_cols, flag_cols], axis=1)


def _body_graph(base, joints, flags, n_legs: int, variant: str) -> dict[str, np.ndarray]:
    """Nodes [is_base, is_foot, contact, magnet]; edge 3 i + j is joint j of leg i."""
    layout = schema.body_graph(n_legs, variant)
    n = len(base)
    nodes = np.zeros((n, layout.n_nodes, len(layout.node_columns)))
    nodes[:, 0, 0] = 1.0
    feet = layout.edges()[2::3, 1]  # the node the tibia joint of each leg drives
    nodes[:, feet, 1] = 1.0
    nodes[:, feet, 2], nodes[:, feet, 3] = flags["contact"], flags["magnet"]
    edges = np.stack([joints[name] for name in layout.edge_columns], axis=-1).reshape(
        n, 3 * n_legs, -1
    )
    return {"nodes": nodes, "edges": edges, "globals": base}
