"""The climbing task in dm-control's suite style: `Physics`, `ClimbTask`, `load(...)`.

The action is the model's actuator vector, per leg [coxa, femur, tibia servo input u,
magnet 0..1]. Each joint servo applies clip(u - Kp q - Kd qd) to its joint (see
symbench.core.sim.scene.mjcf); the agent that acts here is the whole-body controller
(symbench.core.sim.climb.rollout), which sends u = tau_ff + Kp q_ref + Kd qd_ref. Observations
are what the raw schema records: base pose and twist (world), joint states, per-foot
contact and magnet.
"""

from __future__ import annotations

import collections
import os

import numpy as np

os.environ.setdefault("MUJOCO_GL", "disable")  # no rendering: never open a display

from dm_control import mujoco as dm_mujoco
from dm_control.mujoco import wrapper
from dm_control.rl import control
from dm_control.suite import base

from symbench.core.sim.gait.plan import GaitPlan
from symbench.core.sim.scene.arena import mat_to_quat
from symbench.core.sim.scene.layout import ModelLayout
from symbench.core.sim.scene.mjcf import compile_model
from symbench.core.sim.scene.setup import Climb


class Physics(dm_mujoco.Physics):
    """MuJoCo physics of one climbing scene, with per-leg readouts."""

    layout: ModelLayout

    def bind_layout(self, layout: ModelLayout, contact_distance: float) -> None:
        self.layout = layout
        self.contact_distance = contact_distance

    def joint_positions(self) -> np.ndarray:
        return self.data.qpos[self.layout.qpos].copy()

    def joint_velocities(self) -> np.ndarray:
        return self.data.qvel[self.layout.dof].copy()

    def base_angular_velocity(self) -> np.ndarray:
        """World frame (MuJoCo's free joint gives it in the base frame)."""
        r = self.data.xmat[self.layout.base_body].reshape(3, 3)
        return r @ self.data.qvel[3:6]

    def sole_distances(self) -> np.ndarray:
        return self.layout.sole_distances(self.model.ptr, self.data.ptr)

    def contact_flags(self) -> np.ndarray:
        """The foot is in contact when its sole is within the spec's contact distance."""
        return self.sole_distances() < self.contact_distance

    def magnet_controls(self) -> np.ndarray:
        return self.data.ctrl[self.layout.magnet].copy()


def make_physics(climb: Climb) -> Physics:
    model = compile_model(climb.spec, climb.arena)
    physics = Physics.from_model(wrapper.MjModel(model))
    layout = ModelLayout.of(physics.model.ptr, climb.spec)
    physics.bind_layout(layout, climb.spec.magnet.contact_distance)
    return physics


class ClimbTask(base.Task):
    """Stand on the slope with every magnet on, then walk the planned gait."""

    def __init__(self, climb: Climb, random=None):
        super().__init__(random=random if random is not None else climb.seed)
        self.climb = climb
        self.plan: GaitPlan = climb.plan()

    def initialize_episode(self, physics: Physics) -> None:
        pos, rot, linvel, angvel, q, ankle_pitch = self.climb.initial_state(self.plan)
        lay = physics.layout
        data = physics.data
        data.qpos[:3] = pos
        data.qpos[3:7] = mat_to_quat(rot)
        data.qpos[lay.qpos] = q
        data.qpos[lay.ankle_pitch] = ankle_pitch
        data.qvel[:3] = linvel
        data.qvel[3:6] = rot.T @ angvel
        data.ctrl[:] = 0.0  # magnets and servos wait for the first action
        super().initialize_episode(physics)

    def get_observation(self, physics: Physics) -> collections.OrderedDict:
        obs = collections.OrderedDict()
        obs["base_pos"] = physics.data.qpos[:3].copy()
        obs["base_quat"] = physics.data.qpos[3:7].copy()
        obs["base_linvel"] = physics.data.qvel[:3].copy()
        obs["base_angvel"] = physics.base_angular_velocity()
        obs["q"] = physics.joint_positions()
        obs["qd"] = physics.joint_velocities()
        obs["contact"] = physics.contact_flags().astype(np.float64)
        obs["magnet"] = physics.magnet_controls()
        return obs

    def get_reward(self, physics: Physics) -> float:
        """Speed along the commanded direction (m/s)."""
        return float(physics.data.qvel[:3] @ self.plan.direction)


def load_climb(
    climb: Climb, time_limit: float = 10.0, environment_kwargs: dict | None = None
) -> control.Environment:
    physics = make_physics(climb)
    task = ClimbTask(climb)
    return control.Environment(physics, task, time_limit=time_limit, **(environment_kwargs or {}))


def load(
    robot: str,
    inclination_deg: float = 0.0,
    heading_deg: float = 0.0,
    yaw_deg: float = 0.0,
    direction: str = "forward",
    leg_order: tuple[int, ...] | None = None,
    seed: int = 0,
    time_limit: float = 10.0,
    environment_kwargs: dict | None = None,
) -> control.Environment:
    """The suite-style loader: a `control.Environment` for `robot` on the given slope (the
    same climb as `Scenario` gives, gait carried along the symmetry)."""
    from symbench.core.sim.scene.scenario import Scenario

    scenario = Scenario(robot, inclination_deg, heading_deg, yaw_deg, direction, leg_order, seed)
    return load_climb(Climb.from_scenario(scenario), time_limit, environment_kwargs)
