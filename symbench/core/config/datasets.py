"""What a standard dataset holds: a grid of scenarios (datasets up to v6, and `smoke`) or
climbs drawn from continuous distributions (dataset v7), each in a fixed order, so that
trajectory k of a preset is always the same scenario.

A grid is the product of inclinations, slope headings, initial base yaws (evenly covering
the full circle, an even whole number per fundamental sector of the robot's rotation group),
step directions, leg orders and seeds. On such a grid most climbs are exact rotated images of
others (hexa's v6 `small` grid holds 8 distinct motions up to the robot's rotations and the
heading), so an equivariant model meets few new motions in its test set.

A `ClimbDistribution` draws every climb's start instead (yaw, slope heading, inclination
within a band, body step direction, leg order) and makes each step its own (`gait_spread`:
each step's swing height and goal drawn around the robot's nominal ones, as the paper
sampled them). Every draw is uniform over a set that the robot's rotations and mirrors map
onto itself (the full circle of yaws, headings and directions; offsets symmetric about 0),
so the distribution of climbs is invariant under the symmetries and no model's prior is
wrong about the data, while no two climbs are images of each other (their continuous draws
differ).
"""

from __future__ import annotations

import itertools
import math
import zlib
from dataclasses import asdict, dataclass
from typing import Any

import numpy as np

from symbench.core.sim.scene.scenario import Scenario

LEG_ORDERS = ("default", "reversed")


def _leg_order(name: str, n_legs: int) -> tuple[int, ...] | None:
    return {"default": None, "reversed": tuple(range(n_legs - 1, -1, -1))}[name]


@dataclass(frozen=True)
class ScenarioGrid:
    """The dataset: one trajectory per combination of these axes, in this order."""

    inclinations_deg: tuple[float, ...]
    headings_deg: tuple[float, ...]
    yaws_per_turn: int  # at least this many, an even number per sector; 0: 0, 180, 250
    directions: tuple[str, ...]
    leg_orders: tuple[str, ...]
    seeds: tuple[int, ...]
    seconds: float  # length of each trajectory
    torque_noise: float = 0.0  # N m, std of the noise on the expert's executed command
    gait_spread: float = 0.0  # relative spread of each step's swing height and goal

    def yaws_deg(self, rotation_order: int) -> tuple[float, ...]:
        """Evenly spaced from 0, an even number per sector: every other one of a sector's yaws
        trains `unseen-rotation`, the ones between are its test yaws in the other sectors (even,
        so that both sets are closed under the robot's mirrors). 0, 180 and 250 (smoke): 180
        is an image of 0 for every even rotation order, 250 lies outside the first sector and
        off every image of 0 for every rotation order from 2 to 12."""
        if self.yaws_per_turn == 0:
            return (0.0, 180.0, 250.0)
        per_sector = 2 * math.ceil(self.yaws_per_turn / (2 * rotation_order))
        n = rotation_order * per_sector
        return tuple(round(360.0 * k / n, 9) for k in range(n))

    def scenarios(self, robot: str, n_legs: int, rotation_order: int) -> list[Scenario]:
        """The grid in its fixed order: the index in this list is the trajectory id."""
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
                leg_order=_leg_order(order, n_legs),
                seed=seed,
                seconds=self.seconds,
                torque_noise=self.torque_noise,
                gait_spread=self.gait_spread,
            )
            for inc, head, yaw, direction, order, seed in itertools.product(*axes)
        ]

    def describe(self, rotation_order: int) -> dict[str, Any]:
        """JSON-ready, as the dataset metadata stores it (part of the content hash: fields
        and order stay as they are; `torque_noise` only when there is noise)."""
        grid = asdict(self)
        for name in ("torque_noise", "gait_spread"):  # stored only when set
            if not grid[name]:
                del grid[name]
        return {**grid, "yaws_deg": list(self.yaws_deg(rotation_order))}


@dataclass(frozen=True)
class ClimbDistribution:
    """`climbs` climbs drawn from continuous distributions (dataset v7), in a fixed order.

    Climb k's start comes from a stream seeded by (`draw_seed`, k): yaw and slope heading
    uniform on the circle, inclination uniform in `inclinations_deg` (a band the expert
    climbs reliably), body step direction uniform on the circle, leg order uniform among
    `leg_orders`; its seed k drives the start perturbation and each step's swing height and
    goal (`gait_spread`). The draws do not depend on the robot, so the climbs of magneto,
    hexa and nona start alike.
    """

    climbs: int
    inclinations_deg: tuple[float, float]  # the band, lowest and steepest
    leg_orders: tuple[str, ...]
    gait_spread: float  # relative half-width of each step's swing height and goal draws
    seconds: float  # length of each trajectory
    draw_seed: int  # tells presets' draws apart
    torque_noise: float = 0.0  # N m, std of the noise on the expert's executed command

    def scenarios(self, robot: str, n_legs: int, rotation_order: int) -> list[Scenario]:
        """The climbs in their fixed order: the index in this list is the trajectory id."""
        low, high = self.inclinations_deg
        out = []
        for k in range(self.climbs):
            rng = np.random.default_rng([self.draw_seed, k])
            yaw, heading, direction = (round(float(a), 6) for a in rng.uniform(0, 360, 3))
            inclination = round(float(rng.uniform(low, high)), 6)
            order = self.leg_orders[int(rng.integers(len(self.leg_orders)))]
            out.append(
                Scenario(
                    robot=robot,
                    inclination_deg=inclination,
                    heading_deg=heading,
                    yaw_deg=yaw,
                    direction=direction,
                    leg_order=_leg_order(order, n_legs),
                    seed=k,
                    seconds=self.seconds,
                    torque_noise=self.torque_noise,
                    gait_spread=self.gait_spread,
                )
            )
        return out

    def describe(self, rotation_order: int) -> dict[str, Any]:
        """JSON-ready, as the dataset metadata stores it (part of the content hash)."""
        d = asdict(self)
        if not self.torque_noise:
            del d["torque_noise"]
        return {"distribution": "continuous", **d}


def draw_seed(name: str) -> int:
    """A preset's draw seed from its name: presets draw different climbs, every machine the
    same ones."""
    return zlib.crc32(name.encode())


Dataset = ScenarioGrid | ClimbDistribution
