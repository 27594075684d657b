"""Scenario grids of the dataset presets, and the dataset ids they produce.

A grid is the product of inclinations, slope headings, initial base yaws (evenly covering
the full circle, a whole number per fundamental sector of the robot's rotation group, so
that `unseen-rotation` has training data), step directions, leg orders and seeds; its order
is fixed, so trajectory k of a preset is always the same scenario. Bump DATASET_VERSION
whenever a grid or the recorded content changes.
"""

from __future__ import annotations

import itertools
import math
from dataclasses import asdict, dataclass
from typing import Any

from symbench.core.common.errors import UnknownNameError
from symbench.core.sim.scenario import Scenario

# 2: yaws beyond a symmetry step carry the gait along; 3: small grid; 4: simulated with pinned
# numerics (symbench.core.data.determinism), identical on every x86-64 CPU
DATASET_VERSION = 4
RECORD_PERIOD = 0.006  # s between recorded samples (the paper kept every 6th 1 kHz step)
LEG_ORDERS = ("default", "reversed")


@dataclass(frozen=True)
class Preset:
    name: str
    description: str
    inclinations_deg: tuple[float, ...]
    headings_deg: tuple[float, ...]
    yaws_per_turn: int  # at least this many, a whole number per sector; 0: just 0 and 180
    directions: tuple[str, ...]
    leg_orders: tuple[str, ...]
    seeds: tuple[int, ...]
    seconds: float

    def yaws_deg(self, rotation_order: int) -> tuple[float, ...]:
        """Evenly spaced from 0; (0, 180) lies on both sides of every robot's sector."""
        if self.yaws_per_turn == 0:
            return (0.0, 180.0)
        n = rotation_order * math.ceil(self.yaws_per_turn / rotation_order)
        return tuple(round(360.0 * k / n, 9) for k in range(n))

    def scenarios(self, robot: str, n_legs: int, rotation_order: int) -> list[Scenario]:
        """The grid in its fixed order: the index in this list is the trajectory id."""
        orders = {"default": None, "reversed": tuple(range(n_legs - 1, -1, -1))}
        axes = (
            self.inclinations_deg,
            self.headings_deg,
            self.yaws_deg(rotation_order),
            self.directions,
            self.leg_orders,
            self.seeds,
        )
        return [
            Scenario(
                robot=robot,
                inclination_deg=inc,
                heading_deg=head,
                yaw_deg=yaw,
                direction=direction,
                leg_order=orders[order],
                seed=seed,
                seconds=self.seconds,
            )
            for inc, head, yaw, direction, order, seed in itertools.product(*axes)
        ]

    def grid(self, rotation_order: int) -> dict[str, Any]:
        """JSON-ready description of the grid, stored in the dataset metadata."""
        d = asdict(self)
        d["yaws_deg"] = list(self.yaws_deg(rotation_order))
        return d


PRESETS: dict[str, Preset] = {
    p.name: p
    for p in (
        Preset(
            "smoke",
            "a few one-second trajectories, for tests (seconds)",
            inclinations_deg=(90.0,),
            headings_deg=(0.0, 180.0),
            yaws_per_turn=0,
            directions=("forward",),
            leg_orders=("default",),
            seeds=(0,),
            seconds=1.0,
        ),
        # Two headings suffice for the invariance split (on a wall they are exact images);
        # 12 yaws give every robot at least two distinct yaws per symmetry sector.
        Preset(
            "small",
            "the default of `symbench run`: minutes on a laptop",
            inclinations_deg=(90.0,),
            headings_deg=(0.0, 180.0),
            yaws_per_turn=12,
            directions=("forward", "left"),
            leg_orders=("default",),
            seeds=(0,),
            seconds=2.6,
        ),
        Preset(
            "paper",
            "the full replication: slopes, headings, yaws, gaits and seeds",
            inclinations_deg=(57.29577951308232, 90.0),
            headings_deg=(0.0, 90.0, 180.0, 270.0),
            yaws_per_turn=6,
            directions=("forward", "backward", "left", "right"),
            leg_orders=LEG_ORDERS,
            seeds=(0,),
            seconds=10.0,
        ),
    )
}


def preset(name: str) -> Preset:
    if name not in PRESETS:
        raise UnknownNameError("preset", name, PRESETS)
    return PRESETS[name]


def dataset_id(robot: str, preset_name: str) -> str:
    """e.g. hexa-climb-small-v4."""
    preset(preset_name)
    return f"{robot}-climb-{preset_name}-v{DATASET_VERSION}"


def parse_dataset_id(dataset_id_: str) -> tuple[str, str] | None:
    """(robot, preset) of a generated dataset id, or None for other ids (imports)."""
    parts = dataset_id_.split("-")
    if len(parts) == 4 and parts[1] == "climb" and parts[2] in PRESETS and parts[3].startswith("v"):
        return parts[0], parts[2]
    return None
