"""Vectorised raw-to-view transforms: raw trajectories in, model-ready `ViewArrays` out.

Every view and variant keeps the same samples: each step whose next step belongs to the same
trajectory (the last step of a trajectory has no "next" state and is dropped everywhere), so
that models of different views and variants are compared on identical samples.
"""

from __future__ import annotations

from collections.abc import Mapping

import numpy as np

from symbench.core.common.arrays import ViewArrays
from symbench.core.common.errors import SymbenchError, UnknownNameError
from symbench.core.data.views import schema
from symbench.core.data.views.frames import GRAVITY_WORLD, LegFrames, quat_to_matrix

Raw = Mapping[str, np.ndarray]


def sample_rows(trajectory: np.ndarray) -> np.ndarray:
    """Rows whose successor is the next step of the same trajectory."""
    trajectory = np.asarray(trajectory)
    return np.flatnonzero(trajectory[:-1] == trajectory[1:])


def _joint_sources(raw: Raw, rows: np.ndarray) -> dict[str, np.ndarray]:
    """Per-leg joint arrays (N, n_legs, 3) at `rows`, with the next step's state as *_next."""
    out = {name: np.asarray(raw[name], np.float64)[rows] for name in ("q", "qd", "qdd", "tau")}
    out["q_next"] = np.asarray(raw["q"], np.float64)[rows + 1]
    out["qd_next"] = np.asarray(raw["qd"], np.float64)[rows + 1]
    return out


def base_in_leg_frames(raw: Raw, rows: np.ndarray, frames: LegFrames) -> dict[str, np.ndarray]:
    """w_i, a_i, g_i (N, n_legs, 3): base angular velocity, acceleration and gravity in leg i.

    v_i = R_ib v_b with R_ib = R_b_li^T R_bw; world-frame raw columns are first rotated into
    the base frame, which makes the result invariant to rotating the scene about gravity.
    """
    r_wb = quat_to_matrix(np.asarray(raw["base_quat"], np.float64)[rows])

    def in_legs(world: np.ndarray) -> np.ndarray:
        base = np.einsum("nji,nj->ni", r_wb, world)  # R_bw v_w
        in_leg: np.ndarray = np.einsum("lji,nj->nli", frames.rotations, base)  # R_b_li^T v_b
        return in_leg

    gravity = np.broadcast_to(GRAVITY_WORLD, (len(rows), 3))
    return {
        "w": in_legs(np.asarray(raw["base_angvel"], np.float64)[rows]),
        "a": in_legs(np.asarray(raw["base_linacc"], np.float64)[rows]),
        "g": in_legs(gravity),
    }


def leg_grouped(raw: Raw, trajectory: np.ndarray, frames: LegFrames, variant: str) -> ViewArrays:
    """The paper's view: {"x": (N, n_legs, F)} in `schema.leg_grouped_input(variant)` order."""
    layout = schema.leg_grouped_input(variant)
    rows = sample_rows(trajectory)
    n = len(rows)
    features = _joint_sources(raw, rows)
    features.update(base_in_leg_frames(raw, rows, frames))
    features["p"] = np.broadcast_to(frames.base_origin_in_legs(), (n, frames.n_legs, 3))
    for flag in ("contact", "magnet"):
        features[flag] = np.asarray(raw[flag], np.float64)[rows][..., None]
    x = np.concatenate([features[name] for name in layout.feature_names], axis=-1)
    return ViewArrays(
        "leg_grouped",
        variant,
        frames.n_legs,
        {"x": x},
        features["tau"],
        np.asarray(trajectory)[rows],
        {"x": layout.column_names},
    )


def _flat_columns(
    raw: Raw, rows: np.ndarray, joints: Mapping[str, np.ndarray], columns: tuple[str, ...]
) -> np.ndarray:
    """(N, len(columns)) from names like base_pos.x, base_quat.w, leg2.q.coxa, leg2.contact."""
    out = np.empty((len(rows), len(columns)))
    for k, name in enumerate(columns):
        parts = name.split(".")
        if parts[0].startswith("leg") and parts[0][3:].isdigit():
            leg = int(parts[0][3:])
            if len(parts) == 3:
                out[:, k] = joints[parts[1]][:, leg, schema.JOINTS.index(parts[2])]
            else:
                out[:, k] = np.asarray(raw[parts[1]])[rows, leg]
        else:
            axes = "wxyz" if parts[0] == "base_quat" else "xyz"
            out[:, k] = np.asarray(raw[parts[0]], np.float64)[rows, axes.index(parts[1])]
    return out


def vector(raw: Raw, trajectory: np.ndarray, frames: LegFrames, variant: str) -> ViewArrays:
    """The stacked-vector baseline: {"x": (N, D)} in `schema.vector_input` column order."""
    layout = schema.vector_input(frames.n_legs, variant)
    rows = sample_rows(trajectory)
    joints = _joint_sources(raw, rows)
    x = _flat_columns(raw, rows, joints, layout.columns)
    return ViewArrays(
        "vector",
        variant,
        frames.n_legs,
        {"x": x},
        joints["tau"],
        np.asarray(trajectory)[rows],
        {"x": layout.columns},
    )


def body_graph(raw: Raw, trajectory: np.ndarray, frames: LegFrames, variant: str) -> ViewArrays:
    """Bodies as nodes, actuated joints as edges, world-frame base state as globals."""
    layout = schema.body_graph(frames.n_legs, variant)
    rows = sample_rows(trajectory)
    n, legs = len(rows), frames.n_legs
    joints = _joint_sources(raw, rows)
    edges = np.stack([joints[c].reshape(n, 3 * legs) for c in layout.edge_columns], axis=-1)
    foot_nodes = layout.edges()[2::3, 1]  # receiver of each leg's last joint
    node = {c: np.zeros((n, layout.n_nodes)) for c in layout.node_columns}
    node["is_base"][:, 0] = 1.0
    node["is_foot"][:, foot_nodes] = 1.0
    for flag in ("contact", "magnet"):
        node[flag][:, foot_nodes] = np.asarray(raw[flag], np.float64)[rows]
    nodes = np.stack([node[c] for c in layout.node_columns], axis=-1)
    globals_ = _flat_columns(raw, rows, joints, layout.global_columns)
    return ViewArrays(
        "body_graph",
        variant,
        legs,
        {"nodes": nodes, "edges": edges, "globals": globals_},
        joints["tau"],
        np.asarray(trajectory)[rows],
        {
            "nodes": layout.node_columns,
            "edges": layout.edge_columns,
            "globals": layout.global_columns,
        },
    )


BUILDERS = {"leg_grouped": leg_grouped, "vector": vector, "body_graph": body_graph}


def build_view(
    raw: Raw, trajectory: np.ndarray, frames: LegFrames, view: str, variant: str = "acc"
) -> ViewArrays:
    """`view` (leg_grouped, vector, body_graph) of raw columns stacked over trajectories.

    `trajectory` (T,) says which trajectory each raw row belongs to; rows of one trajectory
    are contiguous and in time order.
    """
    builder = BUILDERS.get(view)
    if builder is None:
        raise UnknownNameError("view", view, BUILDERS)
    if variant not in schema.VARIANTS:
        raise UnknownNameError("view variant", variant, schema.VARIANTS)
    if len(trajectory) != len(raw["t"]):
        raise SymbenchError(f"{len(trajectory)} trajectory ids for {len(raw['t'])} raw rows")
    return builder(raw, trajectory, frames, variant)


def require_known(metadata: Mapping[str, object], view: str) -> None:
    """Refuse a view of a dataset whose import declared a column it uses unknown (every view
    uses the contact and magnet flags: a model given zeros for them would learn nonsense)."""
    unknown = metadata.get("unknown_columns") or []
    if unknown:
        names = ", ".join(str(u) for u in unknown)  # type: ignore[attr-defined]
        raise SymbenchError(
            f"dataset '{metadata.get('id')}': its import declared {names} unknown, and the "
            f"{view} view uses {names}; views, training and evaluation need a log with "
            f"reliable {names}"
        )
