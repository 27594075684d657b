"""The symmetry of the whole loop, measured: a run and its turned, relabelled twin.

Rotating the base by the group's angle (360 k / n degrees) while relabelling legs by k puts
every body of the robot exactly where it was, so physics, planner and controller must
reproduce the original run leg for leg. The twin steps in the body direction rotated back
by the same angle (the same direction in the world) with the leg order relabelled.

`check_generators` does this for every generator of the robot's declared group (what
`symbench sim check` reports): a group is verified when its generators are, since every
element is a product of them.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from symbench.core.sim.rollout import Rollout, run_climb
from symbench.core.sim.setup import Climb
from symbench.core.symmetry.groups import GroupElement

PER_LEG = ("q", "qd", "qdd", "tau", "contact", "magnet")
WORLD = ("base_pos", "base_linvel", "base_angvel", "base_linacc")
# The largest error a generator may show, relative: per column, the largest difference
# between twin and run divided by the column's largest magnitude in the run (accelerations in
# stiff magnetic contacts reach 1e3 rad/s^2, positions a few tenths of a metre). Twins of the
# built-in robots agree to 1e-11 over a second and 1e-7 over ten (rounding differences grow
# through contact switches); a broken symmetry (a mislabelled leg, an asymmetric part) shows
# 1e-3 and more.
TOLERANCE = 1e-5


def rotated_twin(climb: Climb) -> Climb:
    """The same climb with the base turned by one group step and the legs relabelled."""
    return climb.turned(1)


def column_errors(a: Rollout, b: Rollout, source: np.ndarray) -> dict[str, float]:
    """Max abs difference per column between run `a` and twin `b` (twin leg j = leg
    source[j] of `a`), over the rows both have."""
    rows = min(len(a.arrays["t"]), len(b.arrays["t"]))
    errors = {}
    for col in PER_LEG:
        errors[col] = float(np.abs(b.arrays[col][:rows] - a.arrays[col][:rows, source]).max())
    for col in WORLD:
        errors[col] = float(np.abs(b.arrays[col][:rows] - a.arrays[col][:rows]).max())
    return errors


def symmetry_error(climb: Climb, seconds: float) -> tuple[float, dict[str, float], Rollout]:
    """Max abs difference between a run and its relabelled twin, overall and per column."""
    a = run_climb(climb, seconds)
    b = run_climb(rotated_twin(climb), seconds)
    spec = climb.spec
    source = (np.arange(spec.n_legs) + spec.symmetry_shift) % spec.n_legs  # twin leg j = leg j+k
    errors = column_errors(a, b, source)
    return max(errors.values()), errors, a


@dataclass(frozen=True)
class GeneratorCheck:
    """One generator of the robot's group, simulated: `error` is the largest relative column
    error, None when the generator could not be simulated (`note`)."""

    generator: str
    error: float | None
    worst_column: str | None = None
    columns: dict[str, float] = field(default_factory=dict)
    note: str = ""

    @property
    def ok(self) -> bool:
        """Within the tolerance (a generator that was not simulated is not a failure)."""
        return self.error is None or self.error <= TOLERANCE

    def to_dict(self) -> dict:
        return {
            "generator": self.generator,
            "error": self.error,
            "worst_column": self.worst_column,
            "simulated": self.error is not None,
            "within_tolerance": self.ok,
            "columns": self.columns,
            "note": self.note,
        }


def _rotation_check(
    climb: Climb, g: GroupElement, original: Rollout, seconds: float, control_period: float | None
) -> GeneratorCheck:
    spec = climb.spec
    k = g.perm[0]  # g carries leg i to leg i + k: a rotation by k legs
    steps = k // spec.symmetry_shift
    twin = run_climb(climb.turned(steps), seconds, control_period=control_period)
    source = (np.arange(spec.n_legs) + k) % spec.n_legs  # twin leg j is leg j + k
    rows = min(len(original.arrays["t"]), len(twin.arrays["t"]))
    errors = {
        c: e / max(float(np.abs(original.arrays[c][:rows]).max()), 1e-12)
        for c, e in column_errors(original, twin, source).items()
    }
    worst = max(errors, key=lambda c: errors[c])
    return GeneratorCheck(g.name, errors[worst], worst, errors)


def check_generators(
    climb: Climb,
    seconds: float,
    original: Rollout | None = None,
    control_period: float | None = None,
) -> list[GeneratorCheck]:
    """Each generator of `climb`'s robot group: the climb turned (or mirrored) by it and
    relabelled, compared with the climb over `seconds` (`original`, a run of `climb` at least
    that long, is reused when given)."""
    if original is None:
        original = run_climb(climb, seconds, control_period=control_period)
    found = []
    for g in climb.spec.group.generators:
        if g.reflect:
            found.append(
                GeneratorCheck(
                    g.name,
                    None,
                    note="mirror twins are not simulated yet: checked on the geometry only",
                )
            )
        else:
            found.append(_rotation_check(climb, g, original, seconds, control_period))
    return found
