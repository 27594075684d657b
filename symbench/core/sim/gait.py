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

import math
from dataclasses import dataclass, field

import numpy as np

from symbench.core.common.errors import SymbenchError
from symbench.core.robot.specs import RobotSpec

STANCE, RELEASE, SWING, TOUCHDOWN = 0, 1, 2, 3
ZERO3 = np.zeros(3)
ZERO3.flags.writeable = False
SETTLE = 0.2  # s of standing still before the first step
# A touching-down magnet engages over this time instead of in one step: 147 N switched on
# at once yanks a 0.3 kg foot into the stiff contact. At the start all magnets are on.
MAGNET_RAMP = 0.05  # s


def default_order(n_legs: int) -> tuple[int, ...]:
    """Counter-clockwise, one leg after the other: equivariant under every rotation."""
    return tuple(range(n_legs))


def check_order(order: tuple[int, ...], n_legs: int) -> tuple[int, ...]:
    if sorted(order) != list(range(n_legs)):
        raise SymbenchError(f"leg order {order} is not a permutation of the {n_legs} legs")
    return tuple(order)


def min_jerk(u: float) -> tuple[float, float, float]:
    """Position, velocity and acceleration (per unit duration) of 10u^3 - 15u^4 + 6u^5."""
    u = min(max(u, 0.0), 1.0)
    return (
        u**3 * (10 - 15 * u + 6 * u**2),
        30 * u**2 * (1 - u) ** 2,
        60 * u * (1 - u) * (1 - 2 * u),
    )


def hermite(p0, v0, p1, v1, u: float, duration: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Cubic Hermite segment at u in [0, 1]: position, velocity, acceleration."""
    return hermite_at(hermite_points(p0, v0, p1, v1, duration), u, duration)


def hermite_points(p0, v0, p1, v1, duration: float) -> np.ndarray:
    """(4, 3) control rows of a Hermite segment, the part of `hermite` that does not depend
    on u: a swing builds them once per segment instead of at every control step."""
    return np.array([p0, duration * v0, p1, duration * v1])


def hermite_at(points: np.ndarray, u: float, duration: float):
    """Position, velocity and acceleration at u of the segment with `points`."""
    u2, u3, T = u * u, u * u * u, duration
    basis = np.array(
        [
            [2 * u3 - 3 * u2 + 1, u3 - 2 * u2 + u, -2 * u3 + 3 * u2, u3 - u2],
            [
                (6 * u2 - 6 * u) / T,
                (3 * u2 - 4 * u + 1) / T,
                (-6 * u2 + 6 * u) / T,
                (3 * u2 - 2 * u) / T,
            ],
            [(12 * u - 6) / T**2, (6 * u - 4) / T**2, (-12 * u + 6) / T**2, (6 * u - 2) / T**2],
        ]
    )
    pos, vel, acc = basis @ points
    return pos, vel, acc


@dataclass(frozen=True)
class GaitTargets:
    phase: np.ndarray  # (n,) STANCE, RELEASE, SWING or TOUCHDOWN
    magnet: np.ndarray  # (n,) 0..1 (ramps up when engaging)
    base_pos: np.ndarray  # (3,) world
    base_vel: np.ndarray
    base_acc: np.ndarray
    slot: int  # the step slot; -1 while settling
    step_leg: int  # the leg in its step slot (release, swing, touchdown); -1 while settling
    sole_pos: np.ndarray  # (3,) its sole target (world): start, spline, goal; zeros if none
    sole_vel: np.ndarray
    sole_acc: np.ndarray


@dataclass(frozen=True)
class GaitPlan:
    spec: RobotSpec
    order: tuple[int, ...]
    direction: np.ndarray  # (3,) unit step direction in the world (in the surface plane)
    normal: np.ndarray  # (3,) surface normal
    base_start: np.ndarray  # (3,)
    soles_start: np.ndarray  # (n, 3) sole contact points at t = 0 (world)
    # the current slot's step ends and swing segments: `targets` runs at every control step
    # and these change once per slot (read-only arrays, handed out as targets)
    _memo: dict = field(default_factory=dict, init=False, repr=False, compare=False)

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

    def slot_index(self, t: float) -> int:
        """The step slot at time t; -1 while settling."""
        return math.floor((t - SETTLE) / self.slot) if t >= SETTLE else -1

    def targets(self, t: float, liftoff: np.ndarray | None = None) -> GaitTargets:
        """Targets at time t. `liftoff`, where the stepping foot really stood when it was
        released, starts its swing there (the goal stays on the plan), so that landing
        errors and creep never add up from step to step."""
        g, n = self.spec.gait, self.spec.n_legs
        s = self.slot_index(t)
        slot = g.step_duration
        tau = t - SETTLE - s * slot if s >= 0 else 0.0  # time into the slot
        phase = np.zeros(n, dtype=int)  # all STANCE (0); np.full costs several times more
        magnet = np.empty(n)
        magnet.fill(1.0)  # np.ones is a Python function: several times slower
        # base: s full slots plus the minimum-jerk share of the current one
        shift = g.step_length / n
        u, du, ddu = min_jerk(tau / slot) if s >= 0 else (0.0, 0.0, 0.0)
        base_pos = self.base_start + ((max(s, 0) + u) * shift) * self.direction
        base_vel = (du * shift / slot) * self.direction
        base_acc = (ddu * shift / slot**2) * self.direction
        leg, pos, vel, acc = -1, ZERO3, ZERO3, ZERO3
        if s >= 0:
            leg = self.order[s % n]
            start, goal = self._step_ends(s)
            if tau < g.release:
                phase[leg], magnet[leg], pos = RELEASE, 0.0, start
            elif tau < g.release + g.swing:
                phase[leg], magnet[leg] = SWING, 0.0
                origin = start if liftoff is None else liftoff
                pos, vel, acc = self._swing(origin, goal, (tau - g.release) / g.swing)
            else:
                phase[leg], pos = TOUCHDOWN, goal
                magnet[leg] = min_jerk((tau - g.release - g.swing) / MAGNET_RAMP)[0]
        return GaitTargets(phase, magnet, base_pos, base_vel, base_acc, s, leg, pos, vel, acc)

    def _step_ends(self, s: int) -> tuple[np.ndarray, np.ndarray]:
        """Start and goal (world) of the sole stepping in slot s, computed once per slot."""
        memo = self._memo
        if memo.get("slot") != s:
            step = self.spec.gait.step_length
            start = (
                self.soles_start[self.order[s % self.spec.n_legs]]
                + ((s // self.spec.n_legs) * step) * self.direction
            )
            goal = start + step * self.direction
            start.flags.writeable = goal.flags.writeable = False
            memo["slot"], memo["ends"] = s, (start, goal)
        return memo["ends"]

    def _swing(self, start: np.ndarray, goal: np.ndarray, u: float):
        """Two Hermite segments through the raised mid point, at swing fraction u."""
        half = self.spec.gait.swing / 2
        first, second = self._swing_segments(start, goal)
        if u < 0.5:
            return hermite_at(first, u / 0.5, half)
        return hermite_at(second, (u - 0.5) / 0.5, half)

    def _swing_segments(self, start: np.ndarray, goal: np.ndarray) -> tuple[np.ndarray, ...]:
        """The two segments' Hermite points for a swing from `start` to `goal`, kept while
        the same two arrays come back (a swing passes the same liftoff and goal at every
        step; the objects are held here, so their identity is not reused)."""
        memo = self._memo
        key = memo.get("swing_ends")
        if key is None or key[0] is not start or key[1] is not goal:
            g = self.spec.gait
            half = g.swing / 2
            mid = 0.5 * (start + goal) + g.swing_height * self.normal
            mid_vel = (goal - start) / g.swing * 1.5  # matches a cubic's peak speed
            memo["swing_ends"] = (start, goal)
            memo["swing"] = (
                hermite_points(start, ZERO3, mid, mid_vel, half),
                hermite_points(mid, mid_vel, goal, ZERO3, half),
            )
        return memo["swing"]
