"""One climb, fully specified in numbers: the robot on its arena, start pose and gait.

`Climb.from_scenario` maps a `Scenario` (direction by name) onto it; the symmetry check uses
`Climb` directly because a turned (or mirrored) and relabelled run steps in another body
direction.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, replace

import numpy as np

from symbench.core.common.errors import SymbenchError
from symbench.core.robot.specs import RobotSpec, load_robot
from symbench.core.sim.control.kinematics import leg_fk, leg_ik
from symbench.core.sim.gait.plan import GaitPlan, check_order, default_order
from symbench.core.sim.scene.arena import Arena, rot_z
from symbench.core.sim.scene.mjcf import ankle_to_sole, stance_height
from symbench.core.sim.scene.scenario import Scenario
from symbench.core.symmetry.groups import GroupElement
from symbench.core.symmetry.legs import MIRROR_Y, base_map

# Seeded start perturbation: a translation in the surface plane and a small base twist,
# both world-frame, so that they commute with the robot's rotation symmetry (a mirrored climb
# mirrors them: the cross-slope components and the twist change sign).
SEED_OFFSET = 0.01  # m
SEED_LINVEL = 0.02  # m/s
SEED_ANGVEL = 0.05  # rad/s
# Each step's own swing height and goal (`Scenario.gait_spread`): drawn for this many step
# slots, whatever the climb's length, so a climb's draws do not depend on its duration (a
# 10 s climb has at most 27 slots; later slots repeat the last draw).
GAIT_SLOTS = 64


Gait = tuple[float | None, float | None, tuple[int, ...] | None]
"""A climb's base yaw (degrees about the surface normal, 0: base x up the slope), body step
direction (degrees from the base x axis) and swing order (leg labels, in stepping order), as
the robot performs them; None where unknown (an imported log need not say)."""


def turn_gait(gait: Gait, angle_deg: float, new_label: Sequence[int]) -> Gait:
    """`gait` with the base turned by `angle_deg` about the surface normal and the legs
    relabelled, leg i's part played by leg `new_label[i]`: the yaw grows by the angle, the body
    direction turns back by it (the same direction in the world) and the swing order follows
    the labels; heading, slope and seed stay. The one map of a climb's gait under a rotation
    of the robot: `Climb.turned` (the simulator's twins) and the image pairs of `symbench data
    symmetry` both use it. None (unknown) stays None."""
    yaw, direction, order = gait
    return (
        None if yaw is None else yaw + angle_deg,
        None if direction is None else direction - angle_deg,
        None if order is None else tuple(new_label[leg] for leg in order),
    )


def _steps(spec: RobotSpec, steps: int) -> tuple[float, list[int]]:
    """The angle and relabelling of `steps` symmetry steps (the base turned counter-clockwise,
    leg i's part played by leg i - steps x shift)."""
    k = spec.symmetry_shift * steps
    return spec.symmetry_angle_deg * steps, [(leg - k) % spec.n_legs for leg in range(spec.n_legs)]


def scenario_gait(
    spec: RobotSpec,
    yaw_deg: float,
    direction_deg: float | None,
    order: Sequence[int] | None,
) -> Gait:
    """The gait the simulator performs for a scenario's yaw, direction and leg order
    (`Climb.from_scenario`): a yaw of k whole symmetry steps plus a remainder is the
    remainder's gait turned k times, so the scenario's direction and leg order are those of
    the yaw's first sector, turned back with the base. No leg order is the default one."""
    step = spec.symmetry_angle_deg
    k = int(np.floor(round(yaw_deg % 360.0, 9) / step))
    resolved = (
        default_order(spec.n_legs) if order is None else check_order(tuple(order), spec.n_legs)
    )
    gait = (yaw_deg - k * step, direction_deg, resolved)
    _, direction, turned = turn_gait(gait, *_steps(spec, k))
    return yaw_deg, direction, turned


@dataclass(frozen=True)
class Climb:
    spec: RobotSpec
    arena: Arena
    yaw_deg: float = 0.0
    direction_deg: float = 0.0  # body frame, counter-clockwise from the base x axis
    order: tuple[int, ...] | None = None
    seed: int = 0
    mirrored: bool = False  # the seeded perturbation mirrored across the slope line
    gait_spread: float = 0.0  # relative spread of each step's swing height and goal

    @classmethod
    def from_scenario(cls, scenario: Scenario, spec: RobotSpec | None = None) -> Climb:
        """The climb of `scenario`, its gait carried along by the robot's rotation symmetry.

        A yaw of k whole symmetry steps plus a remainder is the remainder's climb turned k
        times (`turned`): the step direction turns back and the swing order is relabelled
        with the legs, so scenarios whose yaws differ by a symmetry rotation are exact
        symmetric images of each other (what the `unseen-rotation` split tests). Within the
        first step the direction is the body frame's.
        """
        spec = spec or load_robot(scenario.robot)
        _, direction, order = scenario_gait(
            spec, scenario.yaw_deg, scenario.direction_deg, scenario.leg_order
        )
        assert direction is not None  # a scenario always names its direction
        arena = Arena(scenario.inclination_deg, scenario.heading_deg)
        return cls(
            spec,
            arena,
            scenario.yaw_deg,
            direction,
            order,
            scenario.seed,
            gait_spread=scenario.gait_spread,
        )

    def turned(self, steps: int = 1) -> Climb:
        """The same climb with the base turned by `steps` symmetry steps and the legs
        relabelled: the body direction turns back by the same angle (the same direction in
        the world) and the leg order follows the labels."""
        yaw, direction, order = turn_gait(
            (self.yaw_deg, self.direction_deg, self.leg_order), *_steps(self.spec, steps)
        )
        assert yaw is not None and direction is not None  # known in, known out
        return replace(self, yaw_deg=yaw, direction_deg=direction, order=order)

    def reflected(self, g: GroupElement) -> Climb:
        """The mirror image of this climb under the reflection element `g`, legs relabelled.

        The scene is mirrored in the plane through the surface normal and the slope line,
        which keeps the surface and gravity; the robot's image is the robot again with leg i
        as leg g.perm[i] (refused when its legs lack that symmetry). So the base yaw and the
        body step direction reflect about the element's mirror line, the swing order follows
        the labels and the seeded start perturbation is mirrored.
        """
        if not g.reflect:
            raise SymbenchError(f"{g.name} is a rotation; turn the climb instead")
        gb = base_map(self.spec.leg_rotations(), self.spec.leg_origins(), g)
        twice_axis = float(np.degrees(np.arctan2(*(gb @ MIRROR_Y)[[1, 0], 0])))
        return replace(
            self,
            yaw_deg=-self.yaw_deg - twice_axis,
            direction_deg=twice_axis - self.direction_deg,
            order=tuple(g.perm[leg] for leg in self.leg_order),
            mirrored=not self.mirrored,
        )

    @property
    def leg_order(self) -> tuple[int, ...]:
        n = self.spec.n_legs
        return check_order(self.order, n) if self.order is not None else default_order(n)

    @property
    def base_rotation(self) -> np.ndarray:
        """R_wb at the start, also the orientation the controller holds."""
        return self.arena.rotation @ rot_z(np.radians(self.yaw_deg))

    def _seeded(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        rng = np.random.default_rng(self.seed)
        surface = self.arena.rotation
        side = np.array([1.0, -1.0]) if self.mirrored else np.ones(2)
        offset = surface[:, :2] @ (side * rng.uniform(-SEED_OFFSET, SEED_OFFSET, 2))
        linvel = surface[:, :2] @ (side * rng.uniform(-SEED_LINVEL, SEED_LINVEL, 2))
        angvel = self.arena.normal * (side[1] * rng.uniform(-SEED_ANGVEL, SEED_ANGVEL))
        return offset, linvel, angvel

    def step_draws(self) -> tuple[np.ndarray | None, np.ndarray | None]:
        """Each step slot's swing height (m) and goal offset (m, along and across the step
        direction): uniform within +-`gait_spread` of the nominal swing height and step length,
        from a stream of the climb's seed apart from the start perturbation's. Rotated twins
        share them (the slots, not the legs, draw); a mirrored climb steps to the other side.
        Without spread: the nominal height and no offset, the fixed gait of earlier data."""
        gait, spread = self.spec.gait, self.gait_spread
        if not spread:
            return None, None
        rng = np.random.default_rng([self.seed, 1])
        heights = gait.swing_height * (1.0 + rng.uniform(-spread, spread, GAIT_SLOTS))
        offsets = gait.step_length * rng.uniform(-spread, spread, (GAIT_SLOTS, 2))
        if self.mirrored:
            offsets[:, 1] = -offsets[:, 1]
        return heights, offsets

    def plan(self) -> GaitPlan:
        spec, r_wb = self.spec, self.base_rotation
        beta = np.radians(self.direction_deg)
        dir_body = np.array([np.cos(beta), np.sin(beta), 0.0])
        offset, _, _ = self._seeded()
        base = stance_height(spec) * self.arena.normal + offset
        soles = self._nominal_soles_body() + np.outer(
            GaitPlan.stagger(spec, self.leg_order), dir_body
        )
        heights, offsets = self.step_draws()
        return GaitPlan(
            spec,
            self.leg_order,
            r_wb @ dir_body,
            self.arena.normal,
            base,
            base + soles @ r_wb.T,
            heights,
            offsets,
        )

    def _nominal_soles_body(self) -> np.ndarray:
        spec = self.spec
        ankle = leg_fk(spec, np.asarray(spec.leg.stance))
        ankles = np.einsum("nij,j->ni", spec.leg_rotations(), ankle) + spec.leg_origins()
        return ankles - np.array([0.0, 0.0, ankle_to_sole(spec)])

    def initial_state(self, plan: GaitPlan) -> tuple[np.ndarray, ...]:
        """Base position, R_wb, world linear and angular velocity, joint angles (n, 3) and
        ankle pitch angles (n,) that put every sole on its start point, the foot axis along
        the surface normal."""
        spec, r_wb = self.spec, self.base_rotation
        lift = np.array([0.0, 0.0, ankle_to_sole(spec)])
        ankles_body = (plan.soles_start - plan.base_start) @ r_wb + lift
        in_leg = np.einsum("nji,nj->ni", spec.leg_rotations(), ankles_body - spec.leg_origins())
        q = leg_ik(spec, in_leg)
        ankle_pitch = q[:, 1] + q[:, 2] + np.pi / 2  # turns the tibia axis onto -normal
        _, linvel, angvel = self._seeded()
        return plan.base_start, r_wb, linvel, angvel, q, ankle_pitch
