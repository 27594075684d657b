"""Plausible raw states of any registered robot, without simulating: what the kit's physical
checks transform (turn the base, relabel the legs) before recomputing a model's own view.

Each sample is a two-row trajectory (the state and the state one record period later), so
every view and variant, `next` included, holds exactly `n_samples` samples. Joint angles lie
inside the robot's joint limits; the base is tilted a little from upright, at any yaw, as on
a floor, wall or ceiling scene turned about gravity; velocities, accelerations and torques
are of the robot's order; contact and magnet flags are random.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from symbench.core.data.views.frames import LegFrames, quat_multiply, yaw_quat

RECORD_PERIOD = 0.006


@dataclass(frozen=True)
class RawStates:
    """Raw columns (`symbench.core.sim.raw`) and the trajectory id of every row."""

    raw: dict[str, np.ndarray]
    trajectory: np.ndarray
    frames: LegFrames

    @property
    def n_samples(self) -> int:
        return len(np.unique(self.trajectory))


def robot_frames(name: str) -> LegFrames:
    """The leg frames of the registered robot `name`, read from its spec."""
    from symbench.core.robot.specs import load_robot

    return LegFrames.from_spec(load_robot(name))


def regular_frames(n_legs: int, radius: float = 0.2) -> LegFrames:
    """A regular n-legged robot (leg i at 360 i / n degrees, pointing outwards): symmetric
    under every rotation and mirror of its legs, the frames used for a bare group."""
    angles = 2 * np.pi * np.arange(n_legs) / n_legs
    c, s = np.cos(angles), np.sin(angles)
    rot = np.zeros((n_legs, 3, 3))
    rot[:, 0, 0], rot[:, 0, 1], rot[:, 1, 0], rot[:, 1, 1] = c, -s, s, c
    rot[:, 2, 2] = 1.0
    origins = np.stack([radius * c, radius * s, np.zeros(n_legs)], 1)
    return LegFrames(rot, origins)


def synthetic_raw_states(robot: str | LegFrames, n_samples: int = 32, seed: int = 0) -> RawStates:
    """`n_samples` plausible raw states of `robot` (a registered name, or leg frames)."""
    if isinstance(robot, str):
        from symbench.core.robot.specs import load_robot

        spec = load_robot(robot)
        frames = LegFrames.from_spec(spec)
        lower, upper = (np.asarray(b, np.float64) for b in spec.joint_limits())
        torque = float(spec.control.torque_limit)
    else:
        frames = robot
        lower, upper = np.full(3, -1.5), np.full(3, 1.5)
        torque = 5.0
    rng = np.random.default_rng([seed, 19])
    n_legs, rows = frames.n_legs, 2 * n_samples
    tilt_axis = rng.normal(size=(rows, 2))
    tilt_axis /= np.linalg.norm(tilt_axis, axis=1, keepdims=True)
    tilt = rng.uniform(0.0, 0.3, size=rows)  # rad from upright
    tilt_quat = np.stack(
        [np.cos(tilt / 2), *(np.sin(tilt / 2) * tilt_axis.T), np.zeros(rows)], axis=1
    )
    yaw = np.stack([yaw_quat(a) for a in rng.uniform(0.0, 2 * np.pi, size=rows)])
    raw = {
        "t": np.tile([0.0, RECORD_PERIOD], n_samples),
        "base_pos": rng.normal(scale=0.5, size=(rows, 3)),
        "base_quat": quat_multiply(tilt_quat, yaw),
        "base_linvel": rng.normal(scale=0.1, size=(rows, 3)),
        "base_angvel": rng.normal(scale=0.5, size=(rows, 3)),
        "base_linacc": rng.normal(scale=2.0, size=(rows, 3)),
        "q": rng.uniform(lower, upper, size=(rows, n_legs, 3)),
        "qd": rng.normal(scale=1.0, size=(rows, n_legs, 3)),
        "qdd": rng.normal(scale=20.0, size=(rows, n_legs, 3)),
        "tau": rng.uniform(-torque, torque, size=(rows, n_legs, 3)),
        "contact": rng.integers(0, 2, size=(rows, n_legs)).astype(np.uint8),
        "magnet": rng.integers(0, 2, size=(rows, n_legs)).astype(np.uint8),
    }
    return RawStates(raw, np.repeat(np.arange(n_samples), 2), frames)
