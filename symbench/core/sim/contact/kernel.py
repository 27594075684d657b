"""Compiled per-step contact arithmetic: how far each foot is from the climbing surface,
and whether the robot has come off it. Both run at every 1 kHz control step, where numpy's
per-call cost on a few 3-vectors exceeded the arithmetic many times over (see
`control_kernel` on why compiled code gives the same bits on every CPU).
"""

from __future__ import annotations

import math

from numba import njit

HOLDING, DIVERGED, FOOT_LOST, TILTED, DROPPED = 0, 1, 2, 3, 4
QP_FAILED = 5  # not a fall: the controller had no command (see `control_step`)


@njit(cache=True)
def surface_gaps(
    geom_xpos, geom_xmat, surface, soles, pads, radius, half, pad_radius, distance, clearance
):
    """distance[i]: from foot i's pad envelope (a disk around its contact spheres) to the
    surface plane, the exact cylinder-plane distance; clearance[i]: from its nearest
    contact sphere to the plane. Positions from MuJoCo's geom poses."""
    normal = geom_xmat[surface].reshape((3, 3))[:, 2]  # the plane's z axis
    origin = geom_xpos[surface]
    for i in range(soles.shape[0]):
        g = soles[i]
        height = 0.0
        axis = 0.0
        for k in range(3):
            height += (geom_xpos[g, k] - origin[k]) * normal[k]
            axis += geom_xmat[g, 3 * k + 2] * normal[k]  # the disk's axis against the normal
        axis = abs(axis)
        distance[i] = height - half[i] * axis - radius[i] * math.sqrt(max(0.0, 1.0 - axis * axis))
        lowest = math.inf
        for j in range(pads.shape[1]):
            p = pads[i, j]
            h = 0.0
            for k in range(3):
                h += (geom_xpos[p, k] - origin[k]) * normal[k]
            lowest = min(lowest, h)
        clearance[i] = lowest - pad_radius


@njit(cache=True)
def hold_state(qacc, qpos, xmat, base_body, stance, contact, normal, min_height, cos_tilt):
    """HOLDING, or why the robot counts as fallen off the surface (the first that applies):
    DIVERGED (non-finite accelerations), FOOT_LOST (a stance foot out of contact), TILTED
    (base normal beyond the tilt limit), DROPPED (base origin below `min_height`)."""
    for v in qacc:
        if not math.isfinite(v):
            return DIVERGED
    for i in range(stance.shape[0]):
        if stance[i] and not contact[i]:
            return FOOT_LOST
    r = xmat[base_body]
    if r[2] * normal[0] + r[5] * normal[1] + r[8] * normal[2] < cos_tilt:
        return TILTED
    if qpos[0] * normal[0] + qpos[1] * normal[1] + qpos[2] * normal[2] < min_height:
        return DROPPED
    return HOLDING
