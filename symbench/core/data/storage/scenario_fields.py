"""A trajectory's scenario as a dataset stores it, validated: every field optional (imported
logs may not know their slope), each of the right type and finite when given, so that splits
never meet a heading of "north" or NaN."""

from __future__ import annotations

import math
from typing import Annotated

from pydantic import BaseModel, BeforeValidator, ConfigDict, Field, PlainValidator
from pydantic_core import PydanticCustomError

from symbench.core.sim.scene.scenario import DIRECTIONS

_NAMES = ", ".join(repr(name) for name in DIRECTIONS)


def _exact(value: object) -> object:
    """An integer a float cannot hold exactly (beyond 2**53) is refused: stored as a float it
    would become another number than the one the log gave."""
    if isinstance(value, int) and not isinstance(value, bool) and not _float_holds(value):
        shown = str(value) if len(str(value)) <= 24 else f"an integer of {len(str(value))} digits"
        raise PydanticCustomError(
            "inexact", f"{shown} has more digits than a float holds: give it as a float"
        )
    return value


def _float_holds(value: int) -> bool:
    try:
        return int(float(value)) == value
    except OverflowError:
        return False


Exact = BeforeValidator(_exact)
Finite = Annotated[float, Field(allow_inf_nan=False), Exact]


def _direction(value: object) -> str | float:
    """A named body direction, or degrees (finite): one error naming both, not one per kind."""
    if isinstance(value, str) and value in DIRECTIONS:
        return value
    if isinstance(value, int | float) and not isinstance(value, bool) and math.isfinite(value):
        return float(_exact(value))  # type: ignore[arg-type]
    raise PydanticCustomError(
        "direction", f"Input should be one of {_NAMES} or a finite number of degrees"
    )


Direction = Annotated[str | float, PlainValidator(_direction)]


class ScenarioFields(BaseModel):
    """The fields of `symbench.core.sim.scene.scenario.Scenario` but the robot."""

    model_config = ConfigDict(extra="forbid", strict=True, frozen=True)

    inclination_deg: Annotated[float, Field(ge=0, le=180, allow_inf_nan=False), Exact] | None = None
    heading_deg: Finite | None = None
    yaw_deg: Finite | None = None
    # a named body direction, or (data drawn from continuous distributions) degrees
    direction: Direction | None = None
    leg_order: list[Annotated[int, Field(ge=0)]] | None = None
    seed: Annotated[int, Field(ge=0)] | None = None
    seconds: Annotated[float, Field(gt=0, allow_inf_nan=False), Exact] | None = None
    # N m, only in data for control (a noisy preset): absent means none
    torque_noise: Annotated[float, Field(ge=0, allow_inf_nan=False), Exact] | None = None
    # relative spread of each step's swing height and goal (dataset v7): absent means none
    gait_spread: Annotated[float, Field(ge=0, lt=1, allow_inf_nan=False), Exact] | None = None


class StoredScenario(ScenarioFields):
    """A scenario in a dataset's metadata: the robot too."""

    robot: str


SCENARIO_KEYS = tuple(ScenarioFields.model_fields)
