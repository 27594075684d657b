"""Robot specs: read `robots/<name>/robot.toml` into a frozen, validated `RobotSpec`.

The spec is the single source of a robot's geometry, masses, limits, magnet, gait defaults
and symmetry; the MJCF (symbench.core.sim.scene.mjcf) and the leg frames used by the views are
both derived from it, so they cannot disagree. Legs are numbered counter-clockwise seen from
above; leg frame i sits at the coxa joint in the zero configuration, z along the base z, x
along the coxa's zero direction.

Approximately symmetric variants: `<robot>-asym-<A>` (e.g. `hexa-asym-0.05`) is `<robot>`
with leg 0's links and ankle (1 + A) times as heavy, masses and inertias alike, a single
parameter that breaks the symmetry the robot still declares (an `[asymmetry]` table with
`leg0_heavier = A` in a robot.toml does the same). Its data is only approximately
symmetric; `symbench data symmetry` measures how far.
"""

from __future__ import annotations

import hashlib
import json
import re
import tomllib
from dataclasses import dataclass
from functools import cached_property
from pathlib import Path
from typing import Any

import numpy as np

from symbench.core.common.errors import SymbenchError
from symbench.core.common.jsonfile import one_line
from symbench.core.robot import spec_values as v
from symbench.core.symmetry.groups import LegGroup, from_spec
from symbench.core.symmetry.legs import check_geometry, geometry_group

JOINT_NAMES = ("coxa", "femur", "tibia")


Vec3 = tuple[float, ...]  # three numbers: the parser checks the count


@dataclass(frozen=True)
class LegSpec:
    """One leg (all legs are identical): links, masses, inertias and joint ranges."""

    lengths: dict[str, float]  # coxa, femur, tibia, foot (m)
    masses: dict[str, float]  # coxa, femur, tibia (kg)
    inertias: dict[str, Vec3]  # principal, x along the link
    joint_lower: Vec3
    joint_upper: Vec3
    joint_damping: float
    ankle_masses: Vec3
    ankle_inertias: tuple[Vec3, ...]
    ankle_lower: Vec3
    ankle_upper: Vec3
    ankle_damping: float
    ankle_stiffness: float
    sole_radius: float
    stance: tuple[float, float, float]  # nominal (coxa, femur, tibia) angles


@dataclass(frozen=True)
class MagnetSpec:
    force: float  # N
    friction: float
    contact_distance: float  # m


@dataclass(frozen=True)
class ControlSpec:
    torque_limit: float  # N m, the same for the three joints
    kp: float
    kd: float
    timestep: float  # s, simulation and control period


@dataclass(frozen=True)
class GaitSpec:
    release: float  # s, magnet off, foot still down
    swing: float  # s
    touchdown: float  # s, magnet on, foot settling
    swing_height: float  # m
    step_length: float  # m

    @property
    def step_duration(self) -> float:
        return self.release + self.swing + self.touchdown


@dataclass(frozen=True)
class RobotSpec:
    name: str
    n_legs: int
    description: str
    base_mass: float
    base_inertia: Vec3
    base_semi_axes: Vec3
    mount_radius: float
    mount_z: float
    mount_angles_deg: tuple[float, ...]
    coxa_yaw_deg: tuple[float, ...]
    leg: LegSpec
    magnet: MagnetSpec
    control: ControlSpec
    gait: GaitSpec
    symmetry_kind: str
    symmetry_shift: int
    symmetry_mirror_offset: int
    canonical: str  # canonical JSON of the parsed toml, the source of spec_hash
    asymmetry: float = 0.0  # leg 0 is (1 + asymmetry) times as heavy (0: symmetric)

    @cached_property
    def group(self) -> LegGroup:
        return from_spec(
            self.n_legs, self.symmetry_kind, self.symmetry_shift, self.symmetry_mirror_offset
        )

    @cached_property
    def geometry_group(self) -> LegGroup:
        """The declared group and the mirrors the geometry also has (dihedral or Klein-4
        for the built-in robots): what `symbench sim check` verifies in simulation."""
        return geometry_group(
            self.leg_rotations(), self.leg_origins(), self.group, self.base_tensors()
        )

    def base_tensors(self) -> tuple[np.ndarray, np.ndarray]:
        """The base's principal inertia and ellipsoid semi-axes as diagonal 3x3 tensors: a
        symmetry of the robot must map both onto themselves."""
        return np.diag(self.base_inertia), np.diag(self.base_semi_axes)

    @property
    def symmetry_angle_deg(self) -> float:
        """Base rotation that a shift by `symmetry_shift` legs corresponds to."""
        return 360.0 * self.symmetry_shift / self.n_legs

    def leg_rotations(self) -> np.ndarray:
        """(n_legs, 3, 3) R_b_li: columns are the leg-frame axes in the base frame."""
        yaw = np.radians(np.asarray(self.coxa_yaw_deg))
        c, s = np.cos(yaw), np.sin(yaw)
        rot = np.zeros((self.n_legs, 3, 3))
        rot[:, 0, 0], rot[:, 0, 1], rot[:, 1, 0], rot[:, 1, 1] = c, -s, s, c
        rot[:, 2, 2] = 1.0
        return rot

    def leg_origins(self) -> np.ndarray:
        """(n_legs, 3) coxa joints (leg-frame origins) in the base frame."""
        ang = np.radians(np.asarray(self.mount_angles_deg))
        r = self.mount_radius
        return np.stack([r * np.cos(ang), r * np.sin(ang), np.full(self.n_legs, self.mount_z)], 1)

    def torque_limits(self) -> np.ndarray:
        """(3,) N m for coxa, femur, tibia."""
        return np.full(3, self.control.torque_limit)

    def joint_limits(self) -> tuple[np.ndarray, np.ndarray]:
        return np.asarray(self.leg.joint_lower), np.asarray(self.leg.joint_upper)

    def spec_hash(self) -> str:
        return hashlib.sha256(self.canonical.encode()).hexdigest()

    def leg_mass_scale(self, i: int) -> float:
        """How many times the spec's leg masses and inertias leg `i` carries."""
        return 1.0 + self.asymmetry if i == 0 else 1.0

    @property
    def total_mass(self) -> float:
        per_leg = sum(self.leg.masses.values()) + sum(self.leg.ankle_masses)
        return self.base_mass + per_leg * sum(map(self.leg_mass_scale, range(self.n_legs)))


def _parse_leg(raw: dict[str, Any], src: str) -> LegSpec:
    leg, ankle, stance = (v.table(raw, k, src) for k in ("leg", "ankle", "stance"))
    w = f"{src} [leg]"
    lengths = {
        k: v.positive(v.get(v.table(leg, "lengths", w), k, w + " lengths"), f"{w} lengths.{k}")
        for k in (*JOINT_NAMES, "foot")
    }
    masses = {
        k: v.positive(v.get(v.table(leg, "masses", w), k, w + " masses"), f"{w} masses.{k}")
        for k in JOINT_NAMES
    }
    inertias = {
        k: v.positive_floats(
            v.get(v.table(leg, "inertias", w), k, w + " inertias"), 3, f"{w} inertias.{k}"
        )
        for k in JOINT_NAMES
    }
    joint = f"{w} joint"
    lower, upper = v.limits(v.get(leg, "joint_lower", w), v.get(leg, "joint_upper", w), joint)
    a = f"{src} [ankle]"
    ankle_lower, ankle_upper = v.limits(v.get(ankle, "lower", a), v.get(ankle, "upper", a), a)
    ankle_inertias = v.get(ankle, "inertias", a)
    if not isinstance(ankle_inertias, list) or len(ankle_inertias) != 3:
        raise SymbenchError(f"{a}: inertias needs 3 rows (one per gimbal link)")
    femur, tibia = (v.number(v.get(stance, k, src), f"{src} [stance] {k}") for k in JOINT_NAMES[1:])
    pose = (0.0, femur, tibia)
    if any(not lo <= p <= hi for p, lo, hi in zip(pose, lower, upper)):
        raise SymbenchError(f"{src} [stance]: {pose} lies outside the joint limits")
    return LegSpec(
        lengths=lengths,
        masses=masses,
        inertias=inertias,
        joint_lower=lower,
        joint_upper=upper,
        joint_damping=v.non_negative(leg.get("joint_damping", 0.0), w + " joint_damping"),
        ankle_masses=v.positive_floats(v.get(ankle, "masses", a), 3, a + " masses"),
        ankle_inertias=tuple(v.positive_floats(r, 3, a + " inertias") for r in ankle_inertias),
        ankle_lower=ankle_lower,
        ankle_upper=ankle_upper,
        ankle_damping=v.non_negative(v.get(ankle, "damping", a), a + " damping"),
        ankle_stiffness=v.non_negative(v.get(ankle, "stiffness", a), a + " stiffness"),
        sole_radius=v.positive(v.get(ankle, "sole_radius", a), a + " sole_radius"),
        stance=pose,
    )


def parse_spec(raw: dict[str, Any], source: str = "robot.toml") -> RobotSpec:
    """Validate a parsed robot.toml; every error names the file and the entry."""
    name = v.text(v.get(raw, "name", source), f"{source} name")
    n_legs = v.count(v.get(raw, "n_legs", source), f"{source} n_legs")
    if n_legs < 1:
        raise SymbenchError(f"{source}: n_legs must be positive, got {n_legs}")
    base, mounts, sym = (v.table(raw, k, source) for k in ("base", "mounts", "symmetry"))
    magnet, control, gait = (v.table(raw, k, source) for k in ("magnet", "control", "gait"))
    m, y = f"{source} [mounts]", f"{source} [symmetry]"
    spec = RobotSpec(
        name=name,
        n_legs=n_legs,
        description=v.text(raw.get("description", ""), f"{source} description"),
        base_mass=v.positive(v.get(base, "mass", source), f"{source} base.mass"),
        base_inertia=v.floats(v.get(base, "inertia", source), 3, f"{source} base.inertia"),
        base_semi_axes=v.floats(v.get(base, "semi_axes", source), 3, f"{source} base.semi_axes"),
        mount_radius=v.positive(v.get(mounts, "radius", m), m + " radius"),
        mount_z=v.number(v.get(mounts, "z", m), m + " z"),
        mount_angles_deg=v.floats(v.get(mounts, "angles_deg", m), n_legs, m + " angles_deg"),
        coxa_yaw_deg=v.floats(v.get(mounts, "coxa_yaw_deg", m), n_legs, m + " coxa_yaw_deg"),
        leg=_parse_leg(raw, source),
        magnet=MagnetSpec(
            *v.positives(magnet, ("force", "friction", "contact_distance"), f"{source} [magnet]")
        ),
        control=ControlSpec(
            *v.positives(control, ("torque_limit", "kp", "kd", "timestep"), f"{source} [control]")
        ),
        gait=GaitSpec(
            *v.positives(
                gait,
                ("release", "swing", "touchdown", "swing_height", "step_length"),
                f"{source} [gait]",
            )
        ),
        symmetry_kind=v.text(v.get(sym, "kind", y), f"{y} kind"),
        symmetry_shift=v.count(sym.get("shift", 1), f"{y} shift"),
        symmetry_mirror_offset=v.count(sym.get("mirror_offset", 0), f"{y} mirror_offset"),
        canonical=json.dumps(raw, sort_keys=True, separators=(",", ":")),
        asymmetry=_asymmetry(raw.get("asymmetry", {}), source),
    )
    try:
        group = spec.group
    except SymbenchError as error:  # the group's own words, without the file
        raise SymbenchError(f"{y}: {error}") from None
    unwrapped = np.unwrap(np.radians(spec.mount_angles_deg))
    if n_legs > 1 and (
        np.any(np.diff(unwrapped) <= 0) or unwrapped[-1] - unwrapped[0] >= 2 * np.pi
    ):
        raise SymbenchError(
            f"{m}: legs must be numbered counter-clockwise, once around "
            "(increasing angles_deg spanning less than 360 degrees)"
        )
    if spec.symmetry_shift * group.rotation_order != n_legs:
        raise SymbenchError(
            f"{source} [symmetry]: shift must be the legs per smallest rotation "
            f"of the group ({n_legs // group.rotation_order} for {group.name}), "
            f"got {spec.symmetry_shift}"
        )
    in_plane = (
        spec.base_inertia[0] == spec.base_inertia[1],
        spec.base_semi_axes[0] == spec.base_semi_axes[1],
    )
    if group.rotation_order > 2 and not all(in_plane):
        raise SymbenchError(
            f"{source}: a base with rotations of order {group.rotation_order} needs "
            "equal x and y base.inertia and base.semi_axes, or it breaks the symmetry"
        )
    check_geometry(spec.leg_rotations(), spec.leg_origins(), group, source, spec.base_tensors())
    return spec


def _asymmetry(table: Any, source: str) -> float:
    """The optional `[asymmetry]` table's `leg0_heavier` (0 without one)."""
    where = f"{source} [asymmetry]"
    if not isinstance(table, dict) or set(table) - {"leg0_heavier"}:
        raise SymbenchError(f"{where}: the only key is leg0_heavier, got {table}")
    return v.non_negative(table.get("leg0_heavier", 0.0), where + " leg0_heavier")


def _read_toml(spec_dir: Path) -> tuple[dict[str, Any], Path]:
    path = Path(spec_dir) / "robot.toml"
    if not path.is_file():
        raise SymbenchError(f"robot spec {path} does not exist")
    try:
        return tomllib.loads(path.read_text(encoding="utf-8")), path
    except (ValueError, RecursionError) as exc:  # TOMLDecodeError, UnicodeDecodeError, nesting
        raise SymbenchError(
            f"{path}: not valid TOML ({one_line(exc) or 'nested too deep'})"
        ) from None


def load_spec(spec_dir: Path) -> RobotSpec:
    """The spec in `spec_dir/robot.toml`."""
    raw, path = _read_toml(spec_dir)
    return parse_spec(raw, str(path))


VARIANT = re.compile(r"(?P<robot>.+)-asym-(?P<asymmetry>\d+(\.\d+)?)")


def split_variant(name: str) -> tuple[str, float]:
    """(robot, asymmetry) named by `name`: `hexa` -> ("hexa", 0.0), `hexa-asym-0.05` ->
    ("hexa", 0.05); the name only, nothing is looked up (a record may name a plugin's robot
    that is not installed here)."""
    match = VARIANT.fullmatch(name)
    return (match["robot"], float(match["asymmetry"])) if match else (name, 0.0)


def registered_robot(name: str) -> tuple[str, float]:
    """`split_variant(name)`, refused (naming the known robots) unless its robot is
    registered."""
    from symbench.core.plugin import registry

    base, asymmetry = split_variant(name)
    registry.robot(base)
    return base, asymmetry


def load_robot(name: str) -> RobotSpec:
    """The registered robot `name` (through the symbench_robots hook), or an approximately
    symmetric variant of one (`<robot>-asym-<A>`)."""
    from symbench.core.plugin import registry
    from symbench.core.robot.shipped import unshipped

    base, asymmetry = split_variant(name)
    problem = unshipped(base)
    if problem:
        raise SymbenchError(problem)
    raw, path = _read_toml(registry.robot(base).spec_dir)
    if asymmetry:
        raw = {**raw, "name": name, "asymmetry": {"leg0_heavier": asymmetry}}
    spec = parse_spec(raw, str(path))
    if spec.name != name:
        raise SymbenchError(f"robot '{name}' points at a spec named '{spec.name}'")
    return spec
