"""The climbing gait: one leg at a time, Hermite-spline swings, magnet off only while lifted.

Time is cut into slots of `release + swing + touchdown`; slot s moves leg order[s mod n].
In its slot a leg releases its magnet (foot still down), swings along two cubic Hermite
segments (start -> raised mid point -> goal, zero velocity at both ends) and touches down
with the magnet on. Every step is `step_length` along the commanded direction; the base
follows by step_length / n per slot (minimum-jerk), so feet stay within +-step/2 of their
nominal place. Feet start staggered by their position in the order, so the first step is a
full step too; a swing starts where the foot really stood (the controller passes it in), so
landing errors never add up. All positions are world-frame; the base orientation reference
is its start.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property
from typing import NamedTuple

import numpy as np

from symbench.core.common.errors import SymbenchError
from symbench.core.robot.specs import RobotSpec
from symbench.core.sim.gait.kernel import (
    MAGNET_RAMP,
    RELEASE,
    SETTLE,
    STANCE,
    SWING,
    TOUCHDOWN,
    gait_targets,
    hermite_into,
)

__all__ = ["MAGNET_RAMP", "RELEASE", "SETTLE", "STANCE", "SWING", "TOUCHDOWN"]

ZERO3 = np.zeros(3)
ZERO3.flags.writeable = False


def default_order(n_legs: int) -> tuple[int, ...]:
    """Counter-clockwise, one leg after the other: equivariant under every rotation."""
    return tuple(range(n_legs))


def check_order(order: tuple[int, ...], n_legs: int) -> tuple[int, ...]:
    if sorted(order) != list(range(n_legs)):
        raise SymbenchError(f"leg order {order} is not a permutation of the {n_legs} legs")
    return tuple(order)


def hermite(p0, v0, p1, v1, u: float, duration: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Cubic Hermite segment at u in [0, 1]: position, velocity, acceleration."""
    p0, v0, p1, v1 = (np.asarray(p, dtype=float) for p in (p0, v0, p1, v1))
    out = np.empty((3, 3))
    hermite_into(p0, v0, p1, v1, u, duration, out)
    return out[0], out[1], out[2]


class GaitTargets(NamedTuple):
    """The plan at one time (a named tuple: made at every control step)."""

    phase: np.ndarray  # (n,) STANCE, RELEASE, SWING or TOUCHDOWN
    magnet: np.ndarray  # (n,) 0..1 (ramps up when engaging)
    base: np.ndarray  # (3, 3) world base position, velocity, acceleration
    slot: int  # the step slot; -1 while settling
    step_leg: int  # the leg in its step slot (release, swing, touchdown); -1 while settling
    sole: np.ndarray  # (3, 3) its sole target (world): start, spline, goal; zeros if none

    @property
    def base_pos(self) -> np.ndarray:
        return self.base[0]

    @property
    def base_vel(self) -> np.ndarray:
        return self.base[1]

    @property
    def base_acc(self) -> np.ndarray:
        return self.base[2]

    @property
    def sole_pos(self) -> np.ndarray:
        return self.sole[0]

    @property
    def sole_vel(self) -> np.ndarray:
        return self.sole[1]

    @property
    def sole_acc(self) -> np.ndarray:
        return self.sole[2]


@dataclass(frozen=True)
class GaitPlan:
    spec: RobotSpec
    order: tuple[int, ...]
    direction: np.ndarray  # (3,) unit step direction in the world (in the surface plane)
    normal: np.ndarray  # (3,) surface normal
    base_start: np.ndarray  # (3,)
    soles_start: np.ndarray  # (n, 3) sole contact points at t = 0 (world)
    # per step slot: swing height (m), and the goal's offset (m) along and across the step
    # direction from its nominal place (`Climb.step_draws`); None: the spec's fixed gait
    swing_heights: np.ndarray | None = None
    goal_offsets: np.ndarray | None = None

    @staticmethod
    def stagger(spec: RobotSpec, order: tuple[int, ...]) -> np.ndarray:
        """(n,) start offsets along the direction, in m: leg at order position k starts
        at -L (n-1) / 2n + k L / n so that every step is a full L and feet stay centred."""
        n, step = spec.n_legs, spec.gait.step_length
        position = np.empty(n)
        position[list(order)] = np.arange(n)
        return -step * (n - 1) / (2 * n) + position * step / n

    @property
    def slot(self) -> float:
        return self.spec.gait.step_duration

    def targets(
        self, t: float, liftoff: np.ndarray | None = None, liftoff_slot: int | None = None
    ) -> GaitTargets:
        """Targets at time t. `liftoff`, where the stepping foot really stood when it was
        released, starts its swing there (the goal stays on the plan), so that landing
        errors and creep never add up from step to step; given with `liftoff_slot`, it
        applies only while that slot lasts."""
        n = self.spec.n_legs
        phase, magnet = np.empty(n, dtype=np.int64), np.empty(n)
        base, sole = np.empty((3, 3)), np.empty((3, 3))
        known = -2 if liftoff is None else -1 if liftoff_slot is None else liftoff_slot
        outputs = (phase, magnet, base, sole)
        start = ZERO3 if liftoff is None else liftoff
        slot, leg = gait_targets(*(t, *self.kernel_args, start, known, *outputs))
        return GaitTargets(phase, magnet, base, slot, leg, sole)

    @cached_property
    def kernel_args(self) -> tuple:
        """The plan's arguments of `gait.kernel.gait_targets` after t: order, (release,
        swing, touchdown), step length, each slot's swing height, direction, normal, base
        start, soles at the start, each slot's goal offset, as the compiled code takes them."""
        g = self.spec.gait
        heights = self.swing_heights
        offsets = self.goal_offsets
        return (
            np.asarray(self.order, dtype=np.int64),
            np.array([g.release, g.swing, g.touchdown]),
            g.step_length,
            *(
                np.ascontiguousarray(a, dtype=float)
                for a in (
                    np.full(1, g.swing_height) if heights is None else heights,
                    self.direction,
                    self.normal,
                    self.base_start,
                    self.soles_start,
                    np.zeros((1, 2)) if offsets is None else offsets,
                )
            ),
        )
