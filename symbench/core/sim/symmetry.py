"""The symmetry of the whole loop, measured: a run and its rotated, relabelled twin.

Rotating the base by the group's angle (360 k / n degrees) while relabelling legs by k puts
every body of the robot exactly where it was, so physics, planner and controller must
reproduce the original run leg for leg. The twin steps in the body direction rotated back
by the same angle (the same direction in the world) with the leg order relabelled.
"""

from __future__ import annotations

import numpy as np

from symbench.core.sim.rollout import Rollout, run_climb
from symbench.core.sim.setup import Climb

PER_LEG = ("q", "qd", "qdd", "tau", "contact", "magnet")
WORLD = ("base_pos", "base_linvel", "base_angvel", "base_linacc")


def rotated_twin(climb: Climb) -> Climb:
    """The same climb with the base turned by one group step and the legs relabelled."""
    return climb.turned(1)


def symmetry_error(climb: Climb, seconds: float) -> tuple[float, dict[str, float], Rollout]:
    """Max abs difference between a run and its relabelled twin, overall and per column."""
    a = run_climb(climb, seconds)
    b = run_climb(rotated_twin(climb), seconds)
    spec = climb.spec
    rows = min(len(a.arrays["t"]), len(b.arrays["t"]))
    source = (np.arange(spec.n_legs) + spec.symmetry_shift) % spec.n_legs  # twin leg j = leg j+k
    errors = {}
    for col in PER_LEG:
        errors[col] = float(np.abs(b.arrays[col][:rows] - a.arrays[col][:rows, source]).max())
    for col in WORLD:
        errors[col] = float(np.abs(b.arrays[col][:rows] - a.arrays[col][:rows]).max())
    return max(errors.values()), errors, a
