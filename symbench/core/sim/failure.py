"""When a climb has failed: the one judgement shared by the expert and learned controllers."""

from __future__ import annotations

import numpy as np

COS_TILT_LIMIT = np.cos(np.radians(30.0))  # base normal vs surface normal: beyond, it fell


def detachment(
    stance: np.ndarray,
    contact: np.ndarray,
    data,
    base_body: int,
    normal: np.ndarray,
    height0: float,
) -> str | None:
    """Why the robot counts as fallen off the surface now, or None while it holds on."""
    if not np.isfinite(data.qacc).all():
        return "the physics diverged (non-finite accelerations)"
    lost = stance & ~contact
    if lost.any():
        return f"stance foot of leg(s) {', '.join(map(str, np.flatnonzero(lost)))} left the surface"
    base_z = data.xmat[base_body][2::3]  # third column of R_wb: the base normal
    if base_z @ normal < COS_TILT_LIMIT:
        return "base tilted more than 30 degrees from the surface normal"
    height = data.qpos[:3] @ normal
    if height < 0.3 * height0:
        return f"base dropped to {height:.3f} m above the surface"
    return None


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
