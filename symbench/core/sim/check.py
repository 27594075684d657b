"""`symbench sim check`: does the controller climb? One rollout, judged and summarised."""

from __future__ import annotations

import math
from dataclasses import dataclass

from symbench.core.common.errors import SymbenchError
from symbench.core.sim.rollout import run_climb
from symbench.core.sim.scenario import Scenario
from symbench.core.sim.setup import Climb


@dataclass(frozen=True)
class CheckReport:
    scenario: dict
    attached: bool
    failure: str | None
    metrics: dict[str, float]

    @property
    def torque_within_limit(self) -> bool:
        """No torque demand reached the limit. The applied torque is clipped, so its peak can
        never exceed the limit; what can fail is needing the clip at all."""
        return self.metrics["clipped_fraction"] == 0.0

    def to_dict(self) -> dict:
        return {
            "scenario": self.scenario,
            "attached": self.attached,
            "failure": self.failure,
            "torque_within_limit": self.torque_within_limit,
            **self.metrics,
        }


def check(scenario: Scenario, control_period: float | None = None) -> CheckReport:
    """Run `scenario` with the whole-body controller."""
    if control_period is not None and not (math.isfinite(control_period) and control_period > 0):
        raise SymbenchError(
            f"control period must be a positive number of seconds, got {control_period}"
        )
    rollout = run_climb(
        Climb.from_scenario(scenario), scenario.seconds, control_period=control_period
    )
    return CheckReport(scenario.to_dict(), rollout.attached, rollout.failure, rollout.metrics)
