"""`symbench sim check`: does the controller climb, and does the simulation have the robot's
symmetry? One rollout, judged and summarised, and its twin under each group generator."""

from __future__ import annotations

import math
from dataclasses import dataclass

from symbench.core.common.errors import SymbenchError
from symbench.core.sim.climb.rollout import run_climb
from symbench.core.sim.scene.scenario import Scenario
from symbench.core.sim.scene.setup import Climb
from symbench.core.sim.symmetry import TOLERANCE, GeneratorCheck, check_generators


@dataclass(frozen=True)
class CheckReport:
    scenario: dict
    attached: bool
    failure: str | None
    metrics: dict[str, float]
    symmetry: tuple[GeneratorCheck, ...] | None = None  # None: not checked
    symmetry_seconds: float = 0.0
    declared_group: str = ""  # the robot's group as its spec declares it, e.g. C5
    geometry_group: str = ""  # the group verified: the declared one with the geometry's mirrors

    @property
    def groups(self) -> str:
        """The group verified, in words: "C5 declared, D5 from geometry"."""
        if self.geometry_group == self.declared_group:
            return f"{self.declared_group} declared, no mirror in the geometry"
        return f"{self.declared_group} declared, {self.geometry_group} from geometry"

    @property
    def torque_within_limit(self) -> bool:
        """No torque demand reached the limit. The applied torque is clipped, so its peak can
        never exceed the limit; what can fail is needing the clip at all."""
        return self.metrics["clipped_fraction"] == 0.0

    @property
    def symmetric(self) -> bool:
        """Every generator within the tolerance (True when not checked)."""
        return all(g.ok for g in self.symmetry or ())

    def to_dict(self) -> dict:
        out = {
            "scenario": self.scenario,
            "attached": self.attached,
            "failure": self.failure,
            "torque_within_limit": self.torque_within_limit,
            **self.metrics,
        }
        if self.symmetry is not None:
            out["symmetry"] = {
                "seconds": self.symmetry_seconds,
                "tolerance": TOLERANCE,
                "symmetric": self.symmetric,
                "declared_group": self.declared_group,
                "geometry_group": self.geometry_group,
                "groups": self.groups,
                "generators": [g.to_dict() for g in self.symmetry],
            }
        return out


def check(
    scenario: Scenario, control_period: float | None = None, symmetry_seconds: float = 0.0
) -> CheckReport:
    """Run `scenario` with the whole-body controller; with `symmetry_seconds` > 0, also its
    twin under each generator of the robot's geometry group (declared rotations and mirrors)
    over the first `symmetry_seconds` (at most the scenario's), compared with the run after
    relabelling."""
    if control_period is not None and not (math.isfinite(control_period) and control_period > 0):
        raise SymbenchError(
            f"control period must be a positive number of seconds, got {control_period}"
        )
    if not (math.isfinite(symmetry_seconds) and symmetry_seconds >= 0):
        raise SymbenchError(
            f"symmetry seconds must be a non-negative number, got {symmetry_seconds}"
        )
    climb = Climb.from_scenario(scenario)
    rollout = run_climb(climb, scenario.seconds, control_period=control_period)
    symmetry, seconds = None, min(symmetry_seconds, scenario.seconds)
    if seconds > 0:
        symmetry = tuple(check_generators(climb, seconds, rollout, control_period))
    return CheckReport(
        scenario.to_dict(),
        rollout.attached,
        rollout.failure,
        rollout.metrics,
        symmetry,
        seconds,
        climb.spec.group.name,
        climb.spec.geometry_group.name,
    )
