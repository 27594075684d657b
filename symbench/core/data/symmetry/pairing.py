"""Which trajectories of a dataset are images of each other, and which are repeats.

`symbench data symmetry` (report.py, whose docstring states the rule) first pairs a
dataset's scenarios: two are images under a rotation g when one's gait (yaw, body direction,
leg order), read as the simulator's input or as recorded, is the other's turned by g and the
rest of the scenario is equal; two are repeats when their scenarios are equal. This module
holds that pairing (scenario keys, the rotation angles of the group, the gait a stored
scenario says) apart from the measure, which only consumes its pairs.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from itertools import combinations
from typing import Any

import numpy as np

from symbench.core.common.errors import SymbenchError
from symbench.core.data.symmetry.raw_action import base_map
from symbench.core.data.views.frames import LegFrames
from symbench.core.robot.specs import RobotSpec
from symbench.core.sim.scene.scenario import DIRECTIONS
from symbench.core.sim.scene.setup import Gait, scenario_gait, turn_gait
from symbench.core.symmetry.groups import GroupElement, LegGroup

ANGLE_TOLERANCE_DEG = 1e-6
READINGS = ("simulator", "recorded")
READING_NAMES = {  # how `symbench data symmetry` names each reading of the scenarios
    "simulator": "the simulator's input",
    "recorded": "recorded (leg order and direction as stepped)",
}


def _scenario_key(scenario: Mapping[str, Any], drop: Sequence[str] = ()) -> str:
    return repr(sorted((k, v) for k, v in scenario.items() if k not in drop))


def rotation_angles(group: LegGroup, frames: LegFrames) -> list[tuple[GroupElement, float]]:
    """Each rotation of the group with the angle (degrees, in [0, 360)) by which a
    trajectory's yaw must grow for `act_on_raw(g, .)` to map it onto its image."""
    out = []
    for g in group:
        if g.reflect or g == group.identity:
            continue
        gb = base_map(frames, g)
        angle = float(np.degrees(np.arctan2(gb[1, 0], gb[0, 0])))
        out.append((g, (-angle) % 360.0))
    return out


def _same_angle(a: float, b: float) -> bool:
    d = (a - b) % 360.0
    return min(d, 360.0 - d) < ANGLE_TOLERANCE_DEG


GAIT_FIELDS = ("yaw_deg", "direction", "leg_order")


def scenario_gait_of(
    scenario: Mapping[str, Any], reading: str, spec: RobotSpec | None = None
) -> Gait | None:
    """The gait (yaw, body direction, swing order) a stored scenario says the robot performed,
    read as the simulator's input or as recorded; None when it cannot be paired (no yaw, or a
    leg order that is not a permutation of the legs)."""
    yaw = scenario.get("yaw_deg")
    if yaw is None:
        return None
    named = scenario.get("direction")  # a name, or degrees (climbs drawn continuously)
    direction = (
        None if named is None else DIRECTIONS[named] if isinstance(named, str) else float(named)
    )
    order = scenario.get("leg_order")
    order = None if order is None else tuple(int(leg) for leg in order)
    if reading == "recorded":
        return (float(yaw), direction, order)
    if spec is None:
        raise SymbenchError("reading scenarios as the simulator's input needs the robot's spec")
    if order is not None and sorted(order) != list(range(spec.n_legs)):
        return None
    return scenario_gait(spec, float(yaw), direction, order)


def _same_gait(x: Gait, y: Gait) -> bool:
    (yaw_x, dir_x, order_x), (yaw_y, dir_y, order_y) = x, y
    assert yaw_x is not None and yaw_y is not None
    if (dir_x is None) != (dir_y is None) or order_x != order_y:
        return False
    return _same_angle(yaw_x, yaw_y) and (dir_x is None or _same_angle(dir_x, dir_y))  # type: ignore[arg-type]


@dataclass(frozen=True)
class Pairing:
    """Image pairs (a, b, g) with b = g . a, repeat pairs (a, b) of one scenario, and how the
    scenarios were read."""

    images: list[tuple[int, int, GroupElement]]
    repeats: list[tuple[int, int]]
    reading: str


def pair_up(
    scenarios: Sequence[Mapping[str, Any]],
    ids: Sequence[int],
    group: LegGroup,
    frames: LegFrames,
    reading: str = "auto",
    spec: RobotSpec | None = None,
) -> Pairing:
    """The image and repeat pairs of a dataset's scenarios, read as `reading`: "simulator"
    (a generated dataset), "recorded" (imported logs) or "auto" (recorded, unless that finds
    no image pair and the simulator's reading, possible with `spec`, finds some)."""
    if reading == "auto":
        recorded = pair_up(scenarios, ids, group, frames, "recorded", spec)
        if recorded.images or spec is None:
            return recorded
        simulated = pair_up(scenarios, ids, group, frames, "simulator", spec)
        return simulated if simulated.images else recorded
    if reading not in READINGS:
        raise SymbenchError(f"scenario reading must be one of {', '.join(READINGS)}: {reading}")
    rotations = rotation_angles(group, frames)
    n_legs = group.n_legs
    by_rest: dict[str, list[int]] = {}
    by_all: dict[str, list[int]] = {}
    gaits: dict[int, Gait] = {}
    for i, scenario in zip(ids, scenarios):
        by_all.setdefault(_scenario_key(scenario), []).append(int(i))
        gait = scenario_gait_of(scenario, reading, spec)
        if gait is not None:
            gaits[int(i)] = gait
            by_rest.setdefault(_scenario_key(scenario, GAIT_FIELDS), []).append(int(i))
    images = []
    for members in by_rest.values():
        for a, b in combinations(members, 2):
            for g, angle in rotations:
                # b = act_on_raw(g, a) is the simulator's twin of a under g's inverse: leg i
                # of a is leg g.perm[i] of b
                order = gaits[a][2]
                if order is not None and max(order, default=0) >= n_legs:
                    break
                if _same_gait(turn_gait(gaits[a], angle, g.perm), gaits[b]):
                    images.append((a, b, g))
                    break
    # in the order of the scenarios but for their yaw, then of the ids: the order in which
    # pairs were taken before leg orders and directions were mapped (the same sums, bit for bit)
    rest = {int(i): _scenario_key(s, ("yaw_deg",)) for i, s in zip(ids, scenarios)}
    rank: dict[str, int] = {}
    for key in rest.values():
        rank.setdefault(key, len(rank))
    position = {int(i): n for n, i in enumerate(ids)}
    images.sort(key=lambda p: (rank[rest[p[0]]], position[p[0]], position[p[1]]))
    repeats = [pair for members in by_all.values() for pair in combinations(members, 2)]
    return Pairing(images, repeats, reading)


def find_pairs(
    scenarios: Sequence[Mapping[str, Any]],
    ids: Sequence[int],
    group: LegGroup,
    frames: LegFrames,
    reading: str = "auto",
    spec: RobotSpec | None = None,
) -> tuple[list[tuple[int, int, GroupElement]], list[tuple[int, int]]]:
    """Image pairs (a, b, g) with b = g . a, and repeat pairs (a, b) of one scenario."""
    pairing = pair_up(scenarios, ids, group, frames, reading, spec)
    return pairing.images, pairing.repeats
