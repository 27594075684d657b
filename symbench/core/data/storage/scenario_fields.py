"""A trajectory's scenario as a dataset stores it, validated: every field optional (imported
logs may not know their slope), each of the right type and finite when given, so that splits
never meet a heading of "north" or NaN."""

from __future__ import annotations

import math
from typing import Annotated

from pydantic import BaseModel, ConfigDict, Field, PlainValidator
from pydantic_core import PydanticCustomError

from symbench.core.sim.scene.scenario import DIRECTIONS

Finite = Annotated[float, Field(allow_inf_nan=False)]
_NAMES = ", ".join(repr(name) for name in DIRECTIONS)


def _direction(value: object) -> str | float:
    """A named body direction, or degrees (finite): one error naming both, not one per kind."""
    if isinstance(value, str) and value in DIRECTIONS:
        return value
    if isinstance(value, int | float) and not isinstance(value, bool) and math.isfinite(value):
        return float(value)
    raise PydanticCustomError(
        "direction", f"Input should be one of {_NAMES} or a finite number of degrees"
    )


Direction = Annotated[str | float, PlainValidator(_direction)]


class ScenarioFields(BaseModel):
    """The fields of `symbench.core.sim.scene.scenario.Scenario` but the robot."""

    model_config = ConfigDict(extra="forbid", strict=True, frozen=True)

    inclination_deg: Annotated[float, Field(ge=0, le=180, allow_inf_nan=False)] | None = None
    heading_deg: Finite | None = None
    yaw_deg: Finite | None = None
    # a named body direction, or (data drawn from continuous distributions) degrees
    direction: Direction | None = None
    leg_order: list[Annotated[int, Field(ge=0)]] | None = None
    seed: Annotated[int, Field(ge=0)] | None = None
    seconds: Annotated[float, Field(gt=0, allow_inf_nan=False)] | None = None
    # N m, only in data for control (a noisy preset): absent means none
    torque_noise: Annotated[float, Field(ge=0, allow_inf_nan=False)] | None = None
    # relative spread of each step's swing height and goal (dataset v7): absent means none
    gait_spread: Annotated[float, Field(ge=0, lt=1, allow_inf_nan=False)] | None = None


class StoredScenario(ScenarioFields):
    """A scenario in a dataset's metadata: the robot too."""

    robot: str


SCENARIO_KEYS = tuple(ScenarioFields.model_fields)
