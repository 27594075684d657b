"""Feature layouts of the three views, each feature with a declared geometric type.

The type says how a group element acts inside a leg. Rotations about the base z relabel
legs and leave leg-frame quantities alone; a reflection in the leg's x-z plane (the mirror
that carries a leg onto its mirror image) acts as diag(1, -1, 1) on vectors, as
-diag(1, -1, 1) = diag(-1, 1, -1) on pseudo-vectors, and on joint scalars as on the
pseudo-vector component along the joint axis: the coxa (yaw, axis z) flips, the femur and
tibia (pitch, axis y) do not. Joint torques are joint scalars too.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from enum import Enum

import numpy as np

from symbench.core.common.errors import SymbenchError, UnknownNameError
from symbench.core.data.storage.columns import JOINTS as JOINTS  # re-exported: joint names
from symbench.core.plugin.entries import VARIANTS as VARIANTS  # re-exported: the variants
from symbench.core.plugin.entries import (
    VIEWS as VIEWS,  # re-exported: the views a model may consume
)
from symbench.core.symmetry.legs import JOINT_MIRROR_SIGNS

AXES = ("x", "y", "z")


class FeatureType(Enum):
    """Geometric type of a feature, with its components' signs under a leg mirror."""

    JOINT = "joint scalar"
    VECTOR = "vector"
    PSEUDOVECTOR = "pseudo-vector"
    FLAG = "flag"

    @property
    def reflection_signs(self) -> tuple[float, ...]:
        return _REFLECTION_SIGNS[self]

    @property
    def components(self) -> tuple[str, ...]:
        return _COMPONENTS[self]


_REFLECTION_SIGNS = {
    FeatureType.JOINT: JOINT_MIRROR_SIGNS,  # coxa yaw flips; femur, tibia pitch do not
    FeatureType.VECTOR: (1.0, -1.0, 1.0),
    FeatureType.PSEUDOVECTOR: (-1.0, 1.0, -1.0),
    FeatureType.FLAG: (1.0,),
}
_COMPONENTS = {
    FeatureType.JOINT: JOINTS,
    FeatureType.VECTOR: AXES,
    FeatureType.PSEUDOVECTOR: AXES,
    FeatureType.FLAG: ("",),
}


@dataclass(frozen=True)
class Feature:
    """A named per-leg feature; `doc` says what it is, in which frame."""

    name: str
    type: FeatureType
    doc: str

    @property
    def size(self) -> int:
        return len(self.type.components)

    @property
    def column_names(self) -> tuple[str, ...]:
        return tuple(f"{self.name}.{c}" if c else self.name for c in self.type.components)


@dataclass(frozen=True)
class Layout:
    """An ordered list of features: the last axis of a leg-grouped array."""

    name: str
    features: tuple[Feature, ...]

    def __post_init__(self) -> None:
        names = [f.name for f in self.features]
        if len(set(names)) != len(names):
            raise SymbenchError(f"layout {self.name} repeats a feature name: {names}")

    @property
    def size(self) -> int:
        return sum(f.size for f in self.features)

    @property
    def feature_names(self) -> tuple[str, ...]:
        return tuple(f.name for f in self.features)

    @property
    def column_names(self) -> tuple[str, ...]:
        return tuple(c for f in self.features for c in f.column_names)

    @property
    def reflection_signs(self) -> np.ndarray:
        return np.array([s for f in self.features for s in f.type.reflection_signs])

    def feature(self, name: str) -> Feature:
        for f in self.features:
            if f.name == name:
                return f
        raise UnknownNameError(f"feature of layout {self.name}", name, self.feature_names)

    def slice(self, name: str) -> slice:
        """Columns of feature `name` on the last axis."""
        start = 0
        for f in self.features:
            if f.name == name:
                return slice(start, start + f.size)
            start += f.size
        raise UnknownNameError(f"feature of layout {self.name}", name, self.feature_names)

    def select(self, x: np.ndarray, names: Sequence[str]) -> np.ndarray:
        """The columns of the named features, concatenated in the order given."""
        idx = np.concatenate([np.arange(self.size)[self.slice(n)] for n in names])
        return x[..., idx]


def _f(name: str, type_: FeatureType, doc: str) -> Feature:
    return Feature(name, type_, doc)


J, V, P, FL = FeatureType.JOINT, FeatureType.VECTOR, FeatureType.PSEUDOVECTOR, FeatureType.FLAG

_JOINT_STATE = (
    _f("q", J, "joint positions (rad)"),
    _f("qd", J, "joint velocities (rad/s)"),
)
_BASE_IN_LEG_FRAME = (
    _f("w", P, "base angular velocity in the leg frame (rad/s)"),
    _f("a", V, "base linear acceleration in the leg frame, gravity excluded (m/s^2)"),
    _f("g", V, "gravity in the leg frame (m/s^2)"),
    _f("p", V, "base origin in the leg frame (m)"),
    _f("contact", FL, "foot in contact with the surface (0/1)"),
    _f("magnet", FL, "magnet engaged (0/1)"),
)

LEG_GROUPED_INPUTS: dict[str, Layout] = {  # keyed by the VARIANTS model entries may name
    "acc": Layout(
        "leg_grouped/acc",
        _JOINT_STATE + (_f("qdd", J, "joint accelerations (rad/s^2)"),) + _BASE_IN_LEG_FRAME,
    ),
    "next": Layout(
        "leg_grouped/next",
        _JOINT_STATE
        + (
            _f("q_next", J, "joint positions at the next recorded sample (rad)"),
            _f("qd_next", J, "joint velocities at the next recorded sample (rad/s)"),
        )
        + _BASE_IN_LEG_FRAME,
    ),
}
TARGET = Layout("leg_grouped/target", (_f("tau", J, "applied joint torques (N m)"),))
assert tuple(LEG_GROUPED_INPUTS) == VARIANTS


def leg_grouped_input(variant: str) -> Layout:
    """Input layout of the leg-grouped view for variant 'acc' or 'next'."""
    if variant not in LEG_GROUPED_INPUTS:
        raise UnknownNameError("leg-grouped variant", variant, VARIANTS)
    return LEG_GROUPED_INPUTS[variant]


# --- the other views: flat layouts declared here, filled by the dataset code ---------------
@dataclass(frozen=True)
class FlatLayout:
    """Named columns of a flat vector (the `vector` view and graph node/edge features)."""

    name: str
    columns: tuple[str, ...]

    @property
    def size(self) -> int:
        return len(self.columns)


def _leg_joint_columns(n_legs: int, names: Sequence[str]) -> tuple[str, ...]:
    return tuple(f"leg{i}.{n}.{j}" for n in names for i in range(n_legs) for j in JOINTS)


_BASE_WORLD = tuple(
    [f"base_pos.{a}" for a in AXES]
    + [f"base_quat.{c}" for c in "wxyz"]
    + [f"base_linvel.{a}" for a in AXES]
    + [f"base_angvel.{a}" for a in AXES]
    + [f"base_linacc.{a}" for a in AXES]
)
_VECTOR_JOINTS = {"acc": ("q", "qd", "qdd"), "next": ("q", "qd", "q_next", "qd_next")}


def vector_input(n_legs: int, variant: str) -> FlatLayout:
    """The usual stacked vector: base pose and velocities in the world frame, then all joints.

    Not invariant to rotations about gravity, on purpose: it is the baseline representation.
    """
    if variant not in _VECTOR_JOINTS:
        raise UnknownNameError("vector variant", variant, _VECTOR_JOINTS)
    flags = tuple(f"leg{i}.{f}" for f in ("contact", "magnet") for i in range(n_legs))
    return FlatLayout(
        f"vector/{variant}",
        _BASE_WORLD + _leg_joint_columns(n_legs, _VECTOR_JOINTS[variant]) + flags,
    )


def vector_target(n_legs: int) -> FlatLayout:
    return FlatLayout("vector/target", _leg_joint_columns(n_legs, ("tau",)))


@dataclass(frozen=True)
class GraphLayout:
    """The `body_graph` view: bodies as nodes, joints as edges, base state as global.

    Nodes: the base, then per leg the coxa, femur and tibia links (1 + 3 n nodes; the foot
    and its passive ankle belong to the tibia node, which carries the contact and magnet
    flags). Edges: the three actuated joints of each leg, parent -> child (3 n edges). The
    target is one torque per edge.
    """

    n_legs: int
    variant: str
    node_columns: tuple[str, ...] = ("is_base", "is_foot", "contact", "magnet")
    global_columns: tuple[str, ...] = _BASE_WORLD

    @property
    def n_nodes(self) -> int:
        return 1 + 3 * self.n_legs

    @property
    def n_edges(self) -> int:
        return 3 * self.n_legs

    @property
    def edge_columns(self) -> tuple[str, ...]:
        return _VECTOR_JOINTS[self.variant]

    def edges(self) -> np.ndarray:
        """(n_edges, 2) sender, receiver node indices; edge 3 i + j is joint j of leg i."""
        pairs = []
        for i in range(self.n_legs):
            chain = [0] + [1 + 3 * i + k for k in range(3)]
            pairs += [(chain[j], chain[j + 1]) for j in range(3)]
        return np.array(pairs, dtype=np.int64)


def body_graph(n_legs: int, variant: str) -> GraphLayout:
    if variant not in _VECTOR_JOINTS:
        raise UnknownNameError("body_graph variant", variant, _VECTOR_JOINTS)
    return GraphLayout(n_legs, variant)
