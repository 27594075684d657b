"""The gait plan's per-step arithmetic, compiled: which leg steps, its magnet, the planned
base motion and the stepping sole's target at time t. It runs at every 1 kHz control step
(see `control.kernel` on why compiled code gives the same bits on every CPU); the plan's
meaning is documented in `gait.plan`.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

STANCE, RELEASE, SWING, TOUCHDOWN = 0, 1, 2, 3
SETTLE = 0.2  # s of standing still before the first step
# A touching-down magnet engages over this time instead of in one step: 147 N switched on
# at once yanks a 0.3 kg foot into the stiff contact. At the start all magnets are on.
MAGNET_RAMP = 0.05  # s


@njit(cache=True)
def min_jerk(u):
    """Position, velocity and acceleration (per unit duration) of 10u^3 - 15u^4 + 6u^5."""
    u = min(max(u, 0.0), 1.0)
    return (
        u**3 * (10 - 15 * u + 6 * u**2),
        30 * u**2 * (1 - u) ** 2,
        60 * u * (1 - u) * (1 - 2 * u),
    )


@njit(cache=True)
def hermite_into(p0, v0, p1, v1, u, duration, out):
    """Cubic Hermite segment at u in [0, 1]: out rows = position, velocity, acceleration."""
    u2, u3, T = u * u, u * u * u, duration
    basis = (
        (2 * u3 - 3 * u2 + 1, u3 - 2 * u2 + u, -2 * u3 + 3 * u2, u3 - u2),
        (
            (6 * u2 - 6 * u) / T,
            (3 * u2 - 4 * u + 1) / T,
            (-6 * u2 + 6 * u) / T,
            (3 * u2 - 2 * u) / T,
        ),
        ((12 * u - 6) / T**2, (6 * u - 4) / T**2, (-12 * u + 6) / T**2, (6 * u - 2) / T**2),
    )
    for r in range(3):
        b = basis[r]
        for k in range(3):
            out[r, k] = b[0] * p0[k] + b[1] * (T * v0[k]) + b[2] * p1[k] + b[3] * (T * v1[k])


@njit(cache=True)
def gait_targets(
    t,
    order,
    timing,
    step_length,
    swing_heights,
    direction,
    normal,
    base_start,
    soles_start,
    goal_offsets,
    liftoff,
    liftoff_slot,
    phase,
    magnet,
    base,
    sole,
):
    """Fill phase, magnet (n,), base and sole (rows: position, velocity, acceleration) for
    time t; returns (slot, stepping leg), both -1 while settling. timing = (release, swing,
    touchdown) in s; `liftoff` is where the stepping foot really stood when released: its
    swing starts there (the goal stays on the plan) when `liftoff_slot` is the current slot
    or -1 (any slot); -2: no liftoff. Slot s swings `swing_heights[s]` high to its nominal goal
    moved by `goal_offsets[s]` (along, across the direction); slots past the arrays take
    their last entry."""
    n = order.shape[0]
    release, swing, slot_time = timing[0], timing[1], timing[0] + timing[1] + timing[2]
    s = math.floor((t - SETTLE) / slot_time) if t >= SETTLE else -1
    tau = t - SETTLE - s * slot_time if s >= 0 else 0.0  # time into the slot
    phase[:] = STANCE
    magnet[:] = 1.0
    shift = step_length / n
    u, du, ddu = min_jerk(tau / slot_time) if s >= 0 else (0.0, 0.0, 0.0)
    for k in range(3):
        base[0, k] = base_start[k] + ((max(s, 0) + u) * shift) * direction[k]
        base[1, k] = (du * shift / slot_time) * direction[k]
        base[2, k] = (ddu * shift / slot_time**2) * direction[k]
    sole[:, :] = 0.0
    if s < 0:
        return s, -1
    leg = order[s % n]
    start = soles_start[leg] + ((s // n) * step_length) * direction
    goal = start + step_length * direction
    if goal_offsets.shape[0] > 1:  # each step its own goal (`Climb.step_draws`)
        last = goal_offsets.shape[0] - 1
        across = np.empty(3)  # normal x direction: in the surface, left of the direction
        across[0] = normal[1] * direction[2] - normal[2] * direction[1]
        across[1] = normal[2] * direction[0] - normal[0] * direction[2]
        across[2] = normal[0] * direction[1] - normal[1] * direction[0]
        here = goal_offsets[min(s, last)]
        goal = goal + here[0] * direction + here[1] * across
        if s >= n:  # the swing starts where this leg's previous step put it
            before = goal_offsets[min(s - n, last)]
            start = start + before[0] * direction + before[1] * across
    swing_height = swing_heights[min(s, swing_heights.shape[0] - 1)]
    if tau < release:
        phase[leg], magnet[leg] = RELEASE, 0.0
        sole[0] = start
    elif tau < release + swing:
        phase[leg], magnet[leg] = SWING, 0.0
        origin = liftoff if liftoff_slot in (s, -1) else start
        # two Hermite segments through a raised mid point, at swing fraction v
        half = swing / 2
        mid = 0.5 * (origin + goal) + swing_height * normal
        mid_vel = (goal - origin) / swing * 1.5  # matches a cubic's peak speed
        still = 0.0 * mid
        v = (tau - release) / swing
        if v < 0.5:
            hermite_into(origin, still, mid, mid_vel, v / 0.5, half, sole)
        else:
            hermite_into(mid, mid_vel, goal, still, (v - 0.5) / 0.5, half, sole)
    else:
        phase[leg] = TOUCHDOWN
        sole[0] = goal
        magnet[leg] = min_jerk((tau - release - swing) / MAGNET_RAMP)[0]
    return s, leg
