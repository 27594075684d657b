"""Where each leg's joints, foot and actuators live in a compiled model, as index arrays.

Everything the controller and the recorder read per leg goes through these arrays, so that
per-leg work is vectorised and no code depends on the order legs appear in the model.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from symbench.core.robot.specs import JOINT_NAMES, RobotSpec
from symbench.core.sim.contact.kernel import surface_gaps
from symbench.core.sim.scene.mjcf import (
    BASE,
    PAD_SPHERE_RADIUS,
    PAD_SPHERES,
    SURFACE,
    joint_name,
    magnet_name,
    pad_sphere_name,
    sole_name,
)


@dataclass(frozen=True)
class ModelLayout:
    n_legs: int
    joint: np.ndarray  # (n, 3) joint ids of coxa, femur, tibia
    qpos: np.ndarray  # (n, 3) qpos addresses of coxa, femur, tibia
    dof: np.ndarray  # (n, 3) dof addresses
    motor: np.ndarray  # (n, 3) actuator ids of the joint motors
    magnet: np.ndarray  # (n,) actuator ids of the adhesion actuators
    ankle_pitch: np.ndarray  # (n,) qpos addresses of the first (pitch) gimbal joint
    ankle_body: np.ndarray  # (n,) body ids of the first gimbal link (origin = ankle)
    sole_geom: np.ndarray  # (n,) geom ids of the pads' envelopes (disks, not colliders)
    pad_geom: np.ndarray  # (n, PAD_SPHERES) geom ids of each pad's contact spheres
    surface_geom: int
    base_body: int
    reduced: np.ndarray  # (6 + 3n,) dofs the controller models: base, then actuated joints

    @classmethod
    def of(cls, model, spec: RobotSpec) -> ModelLayout:
        import mujoco

        def jid(i: int, j: str) -> int:
            return mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_JOINT, joint_name(i, j))

        def aid(name: str) -> int:
            return mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_ACTUATOR, name)

        n = spec.n_legs
        joints = np.array([[jid(i, j) for j in JOINT_NAMES] for i in range(n)])
        dof = model.jnt_dofadr[joints]
        base = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_BODY, BASE)
        base_dof = model.jnt_dofadr[model.body_jntadr[base]]
        return cls(
            n_legs=n,
            joint=joints,
            qpos=model.jnt_qposadr[joints],
            dof=dof,
            motor=np.array([[aid(joint_name(i, j)) for j in JOINT_NAMES] for i in range(n)]),
            magnet=np.array([aid(magnet_name(i)) for i in range(n)]),
            ankle_pitch=model.jnt_qposadr[[jid(i, "ankle0") for i in range(n)]],
            ankle_body=np.array(
                [
                    mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_BODY, f"leg{i}_ankle0")
                    for i in range(n)
                ]
            ),
            sole_geom=np.array(
                [mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_GEOM, sole_name(i)) for i in range(n)]
            ),
            pad_geom=np.array(
                [
                    [
                        mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_GEOM, pad_sphere_name(i, k))
                        for k in range(PAD_SPHERES)
                    ]
                    for i in range(n)
                ]
            ),
            surface_geom=mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_GEOM, SURFACE),
            base_body=base,
            reduced=np.concatenate([base_dof + np.arange(6), dof.reshape(-1)]),
        )

    def probe(self, model, data) -> SurfaceProbe:
        """The surface distance readouts bound to one MjData (see `SurfaceProbe`)."""
        return SurfaceProbe(self, model, data)

    def sole_distances(self, model, data) -> np.ndarray:
        """(n,) distance from each pad's envelope to the surface (`SurfaceProbe`)."""
        return self.probe(model, data).sole_distances()


class SurfaceProbe:
    """How far each foot is from the climbing surface, read from MuJoCo's geom poses.

    Bound to one MjData: its arrays and the pads' sizes are looked up once, since the
    rollout reads these at every control step (a MjData attribute read builds a new array
    object each time); the arithmetic is compiled (`contact_kernel.surface_gaps`).
    """

    def __init__(self, layout: ModelLayout, model, data):
        self.n = layout.n_legs
        # the arguments of `surface_gaps` before its outputs
        self.kernel_args = (
            data.geom_xpos,
            data.geom_xmat,
            int(layout.surface_geom),
            np.ascontiguousarray(layout.sole_geom, dtype=np.int64),
            np.ascontiguousarray(layout.pad_geom, dtype=np.int64),
            np.ascontiguousarray(model.geom_size[layout.sole_geom, 0]),
            np.ascontiguousarray(model.geom_size[layout.sole_geom, 1]),
            PAD_SPHERE_RADIUS,
        )

    def both(self) -> tuple[np.ndarray, np.ndarray]:
        """(`sole_distances`, and each pad's nearest contact sphere's distance to the surface:
        the magnet pulls when that is within the sphere's contact margin)."""
        distance, clearance = np.empty(self.n), np.empty(self.n)
        surface_gaps(*self.kernel_args, distance, clearance)
        return distance, clearance

    def sole_distances(self) -> np.ndarray:
        """(n,) distance from each pad's envelope (a disk around its contact spheres) to the
        climbing surface, the exact cylinder-plane distance from MuJoCo's geom poses: a
        foot is in contact when this is below the spec's 5 mm."""
        return self.both()[0]
