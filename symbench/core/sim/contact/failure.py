"""When a climb has failed: the one judgement shared by the expert and learned controllers."""

from __future__ import annotations

import numpy as np

from symbench.core.sim.contact.kernel import (
    DIVERGED,
    DROPPED,
    FOOT_LOST,
    HOLDING,
    TILTED,
    hold_state,
)

COS_TILT_LIMIT = float(np.cos(np.radians(30.0)))  # base normal vs surface normal: beyond, it fell
DROP_FRACTION = 0.3  # base height below this share of its start: it fell


class Detachment:
    """Why the robot counts as fallen off the surface now (None while it holds on), bound
    to one MjData: its arrays are looked up once, since this runs at every control step."""

    def __init__(self, data, base_body: int, normal: np.ndarray, height0: float):
        self._arrays = (data.qacc, data.qpos, data.xmat)
        self._base_body, self._normal = int(base_body), np.ascontiguousarray(normal, dtype=float)
        # the last arguments of `hold_state`: normal, lowest base height, cos tilt limit
        self.limits = (self._normal, DROP_FRACTION * height0, COS_TILT_LIMIT)

    def __call__(self, stance: np.ndarray, contact: np.ndarray) -> str | None:
        state = hold_state(*self._arrays, self._base_body, stance, contact, *self.limits)
        if state == HOLDING:
            return None
        return describe_fall(state, stance, contact, self._arrays[1], self._normal)


def describe_fall(
    state: int, stance: np.ndarray, contact: np.ndarray, qpos: np.ndarray, normal: np.ndarray
) -> str:
    """The words for a `contact.kernel` status other than HOLDING."""
    if state == DIVERGED:
        return "the physics diverged (non-finite accelerations)"
    if state == FOOT_LOST:
        lost = np.flatnonzero(stance & ~contact)
        return f"stance foot of leg(s) {', '.join(map(str, lost))} left the surface"
    if state == TILTED:
        return "base tilted more than 30 degrees from the surface normal"
    if state == DROPPED:
        return f"base dropped to {qpos[:3] @ normal:.3f} m above the surface"
    return "the whole-body QP had no solution, even without torque limits"


PATH_LIMIT_STEPS = 0.5  # base further than this many step lengths from its reference: lost


def off_path(base_pos: np.ndarray, reference_pos: np.ndarray, step_length: float) -> str | None:
    """Why a controller tracking a reference climb has lost it, or None while it follows:
    its base is more than half a step length from where the reference's base is at the same
    time (its feet would then land a half step off their planned places). Only learned
    controllers are judged by it; the expert has no reference but its plan."""
    drift = float(np.linalg.norm(base_pos - reference_pos))
    if drift > PATH_LIMIT_STEPS * step_length:
        return f"base left its path ({drift:.3f} m from the reference, over half a step)"
    return None
