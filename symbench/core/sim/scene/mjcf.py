"""MJCF of a robot on its climbing surface, generated from the spec with `mujoco.MjSpec`.

Per leg: coxa (yaw), femur and tibia (pitch) hinges driven by torque servos, a passive
3-axis ankle gimbal (spring and damper) carrying the magnetic foot, and an `<adhesion>`
actuator whose full control (1) pulls the foot with the spec's magnet force. Only the base
ellipsoid and the foot soles collide, and only with the surface. Settings that keep the
simulator symmetric (docs/concepts.md): Newton solver, no noslip iterations, a base that touches
the plane in one point, a raised impratio so that feet do not creep down a wall.
"""

from __future__ import annotations

import numpy as np

from symbench.core.robot.specs import JOINT_NAMES, RobotSpec
from symbench.core.sim.control.kinematics import leg_fk
from symbench.core.sim.scene.arena import Arena, mat_to_quat

SURFACE = "surface"
BASE = "base"
IMPRATIO = 10.0
ANKLE_AXES = ((0.0, 1.0, 0.0), (0.0, 0.0, 1.0), (1.0, 0.0, 0.0))  # in the tibia frame
# Pitch joints turn about -y so that a positive femur angle lifts the leg (each robot's README).
JOINT_AXES = ((0.0, 0.0, 1.0), (0.0, -1.0, 0.0), (0.0, -1.0, 0.0))
# Collision bits: the surface touches robot geoms, robot geoms never touch each other.
SURFACE_BITS, ROBOT_BITS = (1, 2), (2, 1)
# The magnet presses a light foot with 147 N: MuJoCo's default soft contact would let it sink
# about 6 mm, so the soles get the stiffest stable contact (time constant of two steps; under
# 2 mm). The adhesion acts only on contacts MuJoCo detects, so the soles get a 2 mm margin:
# the magnet attracts a pad within 2 mm of the surface and, under the full pull, presses it
# back onto the surface (a released pad rests about 2 mm off it).
SOLE_SOLREF = (0.002, 1.0)
SOLE_SOLIMP = (0.95, 0.99, 0.001, 0.5, 2.0)
SOLE_MARGIN = 0.002  # m
# The pad is four small spheres on a ring, not a flat cylinder: a flat face resting on a
# plane makes MuJoCo switch between one and several contacts on rounding noise, which breaks
# the exact symmetry of a rotated run; a sphere always makes exactly one contact. Four of
# them keep the pad from rolling on the passive gimbal (a single sphere let ankles creep).
PAD_SPHERES = 4
PAD_SPHERE_RADIUS = 0.003  # m
PAD_HALF_THICKNESS = 0.004  # m, of the pad's envelope (the disk the contact flag measures)


def joint_name(leg: int, joint: str) -> str:
    return f"leg{leg}_{joint}"


def foot_name(leg: int) -> str:
    return f"leg{leg}_foot"


def sole_name(leg: int) -> str:
    """The magnet pad's envelope (a disk, not a collider): contact is measured from it."""
    return f"leg{leg}_sole"


def pad_sphere_name(leg: int, k: int) -> str:
    """One of the spheres that the pad touches the surface with."""
    return f"leg{leg}_pad{k}"


def pad_points(spec: RobotSpec) -> np.ndarray:
    """(PAD_SPHERES, 2) pad sphere centres across the foot axis (foot y, z), on a square."""
    ring = spec.leg.sole_radius - PAD_SPHERE_RADIUS
    angles = np.pi / 4 + np.arange(PAD_SPHERES) * 2 * np.pi / PAD_SPHERES
    return ring * np.stack([np.cos(angles), np.sin(angles)], axis=1)


def magnet_name(leg: int) -> str:
    return f"leg{leg}_magnet"


def ankle_to_sole(spec: RobotSpec) -> float:
    """Distance from the ankle to the bottom of the sole along the foot axis."""
    return spec.leg.lengths["foot"]


def stance_height(spec: RobotSpec) -> float:
    """Base-origin height above the surface in the nominal stance (gimbal centred)."""
    ankle = leg_fk(spec, np.asarray(spec.leg.stance)[None, :])[0]
    return -(spec.mount_z + ankle[2] - ankle_to_sole(spec))


def _inertial(body, mass: float, inertia, com=(0.0, 0.0, 0.0)) -> None:
    body.mass = mass
    body.inertia = list(inertia)
    body.ipos = list(com)
    body.explicitinertial = True


def _hinge(
    body, name: str, axis, lower: float, upper: float, damping: float = 0.0, stiffness: float = 0.0
):
    import mujoco

    joint = body.add_joint(
        name=name,
        type=mujoco.mjtJoint.mjJNT_HINGE,
        axis=list(axis),
        range=[lower, upper],
        limited=mujoco.mjtLimited.mjLIMITED_TRUE,
    )
    joint.damping = np.array([damping, 0.0, 0.0])
    joint.stiffness = np.array([stiffness, 0.0, 0.0])
    return joint


def _visual_capsule(body, length: float, radius: float) -> None:
    import mujoco

    body.add_geom(
        type=mujoco.mjtGeom.mjGEOM_CAPSULE,
        fromto=[0, 0, 0, length, 0, 0],
        size=[radius, 0, 0],
        contype=0,
        conaffinity=0,
        group=1,
    )


def _add_joint_servo(spec_mj, joint: str, spec: RobotSpec) -> None:
    """Torque motor with the joint feedback built in: force = u - Kp q - Kd qd, clipped to
    the limit, where the controller sends u = tau_ff + Kp q_ref + Kd qd_ref. Putting the
    feedback in the actuator lets the implicit integrator treat its damping implicitly; an
    explicit Kd of 3 N m s/rad oscillates at 1 kHz against the stiff magnetic contacts."""
    import mujoco

    act = spec_mj.add_actuator(name=joint, target=joint, trntype=mujoco.mjtTrn.mjTRN_JOINT)
    act.gaintype = mujoco.mjtGain.mjGAIN_FIXED
    act.gainprm[0] = 1.0
    act.biastype = mujoco.mjtBias.mjBIAS_AFFINE
    act.biasprm[1] = -spec.control.kp
    act.biasprm[2] = -spec.control.kd
    act.ctrllimited = mujoco.mjtLimited.mjLIMITED_FALSE
    act.forcelimited = mujoco.mjtLimited.mjLIMITED_TRUE
    act.forcerange = [-spec.control.torque_limit, spec.control.torque_limit]


def _add_leg(spec_mj, base, spec: RobotSpec, i: int) -> None:
    import mujoco

    leg = spec.leg
    lo, hi = leg.joint_lower, leg.joint_upper
    origin, rot = spec.leg_origins()[i], spec.leg_rotations()[i]
    scale = spec.leg_mass_scale(i)  # 1 but for an asymmetric variant's leg 0
    parent, pos, quat = base, origin, tuple(mat_to_quat(rot))
    for k, joint in enumerate(JOINT_NAMES):
        length = leg.lengths[joint]
        body = parent.add_body(name=f"leg{i}_{joint}", pos=list(pos), quat=list(quat))
        inertia = tuple(scale * v for v in leg.inertias[joint])
        _inertial(body, scale * leg.masses[joint], inertia, (length / 2, 0.0, 0.0))
        _hinge(body, joint_name(i, joint), JOINT_AXES[k], lo[k], hi[k], leg.joint_damping)
        _visual_capsule(body, length, 0.012)
        parent, pos, quat = body, (length, 0.0, 0.0), (1.0, 0.0, 0.0, 0.0)
    for k in range(3):  # passive gimbal; its last link is the foot with the magnet
        name = foot_name(i) if k == 2 else f"leg{i}_ankle{k}"
        body = parent.add_body(name=name, pos=list(pos), quat=list(quat))
        _inertial(
            body, scale * leg.ankle_masses[k], tuple(scale * v for v in leg.ankle_inertias[k])
        )
        _hinge(
            body,
            f"leg{i}_ankle{k}",
            ANKLE_AXES[k],
            leg.ankle_lower[k],
            leg.ankle_upper[k],
            leg.ankle_damping,
            leg.ankle_stiffness,
        )
        parent, pos = body, (0.0, 0.0, 0.0)
    reach = ankle_to_sole(spec)
    for k, (y, z) in enumerate(pad_points(spec)):  # the magnet pad, facing along the foot x
        parent.add_geom(
            name=pad_sphere_name(i, k),
            type=mujoco.mjtGeom.mjGEOM_SPHERE,
            size=[PAD_SPHERE_RADIUS, 0, 0],
            pos=[reach - PAD_SPHERE_RADIUS, y, z],
            contype=ROBOT_BITS[0],
            conaffinity=ROBOT_BITS[1],
            friction=[spec.magnet.friction, 0.0, 0.0],
            condim=3,
            solref=list(SOLE_SOLREF),
            solimp=list(SOLE_SOLIMP),
            margin=SOLE_MARGIN,
        )
    # the pad's envelope: a disk whose axis is the foot axis, enclosing the spheres
    parent.add_geom(
        name=sole_name(i),
        type=mujoco.mjtGeom.mjGEOM_CYLINDER,
        size=[spec.leg.sole_radius, PAD_HALF_THICKNESS, 0],
        pos=[reach - PAD_HALF_THICKNESS, 0, 0],
        quat=[np.sqrt(0.5), 0, np.sqrt(0.5), 0],
        contype=0,
        conaffinity=0,
        group=1,
    )
    _visual_capsule(parent, reach - 2 * PAD_HALF_THICKNESS, 0.02)
    for joint in JOINT_NAMES:
        _add_joint_servo(spec_mj, joint_name(i, joint), spec)
    magnet = spec_mj.add_actuator(
        name=magnet_name(i), target=foot_name(i), trntype=mujoco.mjtTrn.mjTRN_BODY
    )
    magnet.set_to_adhesion(gain=spec.magnet.force)
    magnet.ctrlrange = [0.0, 1.0]


def build_spec(spec: RobotSpec, arena: Arena):
    """The `mujoco.MjSpec` of the robot on the arena (base placed later, by the task)."""
    import mujoco

    m = mujoco.MjSpec()
    m.modelname = f"{spec.name}_climb"
    m.compiler.inertiafromgeom = mujoco.mjtInertiaFromGeom.mjINERTIAFROMGEOM_FALSE
    m.compiler.degree = False  # every angle in the spec is in radians
    opt = m.option
    opt.timestep = spec.control.timestep
    opt.solver = mujoco.mjtSolver.mjSOL_NEWTON
    opt.noslip_iterations = 0
    opt.impratio = IMPRATIO
    opt.cone = mujoco.mjtCone.mjCONE_ELLIPTIC
    opt.integrator = mujoco.mjtIntegrator.mjINT_IMPLICITFAST
    opt.iterations = 100
    opt.tolerance = 1e-12
    opt.gravity = [0.0, 0.0, -9.81]
    m.worldbody.add_geom(
        name=SURFACE,
        type=mujoco.mjtGeom.mjGEOM_PLANE,
        size=[0, 0, 0.05],
        quat=list(mat_to_quat(arena.rotation)),
        contype=SURFACE_BITS[0],
        conaffinity=SURFACE_BITS[1],
        friction=[spec.magnet.friction, 0, 0],
    )
    base = m.worldbody.add_body(name=BASE)
    base.add_freejoint(name="root")
    _inertial(base, spec.base_mass, spec.base_inertia)
    base.add_geom(
        name="base_shell",
        type=mujoco.mjtGeom.mjGEOM_ELLIPSOID,
        size=list(spec.base_semi_axes),
        contype=ROBOT_BITS[0],
        conaffinity=ROBOT_BITS[1],
        friction=[spec.magnet.friction, 0, 0],
    )
    for i in range(spec.n_legs):
        _add_leg(m, base, spec, i)
    return m


def compile_model(spec: RobotSpec, arena: Arena):
    """The compiled `mujoco.MjModel`, straight from the MjSpec (no XML round trip, whose
    printed digits would break the exact symmetry of the leg mounts)."""
    return build_spec(spec, arena).compile()
