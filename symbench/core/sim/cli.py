"""`symbench sim ...`: simulator commands (imported only when invoked)."""

from __future__ import annotations

import json
import sys

import click

from symbench.core.common.cli_types import INCLINATION, POSITIVE, SEED, FiniteFloat
from symbench.core.sim.scene.scenario import DIRECTIONS


@click.group("sim")
def sim() -> None:
    """The climbing simulator: MuJoCo + dm-control, gait planner, whole-body controller."""


@sim.command("check")
@click.option("--robot", required=True, help="Registered robot, e.g. hexa.")
@click.option(
    "--inclination",
    type=INCLINATION,
    default=90.0,
    show_default=True,
    help="Surface inclination in degrees: 0 floor, 90 wall, 180 ceiling.",
)
@click.option(
    "--heading",
    type=FiniteFloat(),
    default=0.0,
    show_default=True,
    help="Slope heading: rotation of the scene about gravity, degrees.",
)
@click.option(
    "--yaw",
    type=FiniteFloat(),
    default=0.0,
    show_default=True,
    help="Initial base yaw relative to the slope, degrees.",
)
@click.option(
    "--direction",
    type=click.Choice(list(DIRECTIONS)),
    default="forward",
    show_default=True,
    help="Step direction in the body frame.",
)
@click.option("--seconds", type=POSITIVE, default=10.0, show_default=True)
@click.option("--seed", type=SEED, default=0, show_default=True)
@click.option(
    "--control-period",
    type=POSITIVE,
    default=None,
    help="Seconds between whole-body QP solves [default: every physics step, 1 ms].",
)
@click.option(
    "--symmetry-seconds",
    type=FiniteFloat(),
    default=None,
    help="Seconds over which each symmetry twin is compared with the run "
    "[default: the whole run]; 0 skips the symmetry check.",
)
@click.option("--json", "as_json", is_flag=True, help="Print JSON.")
def check_command(
    robot: str,
    inclination: float,
    heading: float,
    yaw: float,
    direction: str,
    seconds: float,
    seed: int,
    control_period: float | None,
    symmetry_seconds: float | None,
    as_json: bool,
) -> None:
    """Run the controller, and its twin under each generator of the robot's symmetry group
    and of the mirrors its geometry has (turned, or mirrored, and relabelled); exit status 1
    when the robot detached or a twin differs from the run by more than the tolerance."""
    from symbench.core.sim.check import check
    from symbench.core.sim.scene.scenario import Scenario

    scenario = Scenario(robot, inclination, heading, yaw, direction, None, seed, seconds)
    symmetry = seconds if symmetry_seconds is None else symmetry_seconds
    report = check(scenario, control_period, symmetry)
    if as_json:
        click.echo(json.dumps(report.to_dict(), indent=2))
    else:
        _print_report(report)
        _print_symmetry(report)
    if not (report.attached and report.symmetric):
        sys.exit(1)


def _print_report(report) -> None:
    m, s = report.metrics, report.scenario
    state = "attached" if report.attached else f"DETACHED ({report.failure})"
    click.echo(
        f"{s['robot']} at {s['inclination_deg']:g} deg (heading {s['heading_deg']:g}, "
        f"yaw {s['yaw_deg']:g}, {s['direction']}), {m['sim_seconds']:.2f} s: {state}"
    )
    click.echo(f"  walked {m['distance_walked'] * 100:.1f} cm along the commanded direction")
    click.echo(
        f"  base tracking error: rms {m['base_error_rms'] * 1000:.1f} mm, "
        f"max {m['base_error_max'] * 1000:.1f} mm"
    )
    click.echo(
        f"  swing ankle error:   rms {m['swing_error_rms'] * 1000:.1f} mm, "
        f"max {m['swing_error_max'] * 1000:.1f} mm"
    )
    click.echo(
        f"  peak torque (coxa/femur/tibia): {m['peak_torque_coxa']:.2f} / "
        f"{m['peak_torque_femur']:.2f} / {m['peak_torque_tibia']:.2f} N m, "
        f"limit {m['torque_limit']:g} N m ({m['clipped_fraction']:.1%} of torques at the clip)"
    )
    click.echo(
        f"  real-time factor: {m['real_time_factor']:.2f} "
        f"(controller every {m['control_period'] * 1000:g} ms)"
    )


def _print_symmetry(report) -> None:
    from symbench.core.sim.symmetry import TOLERANCE

    if report.symmetry is None:
        return
    click.echo(
        f"  symmetry over {report.symmetry_seconds:g} s of {report.groups}: twin under each "
        f"generator (largest relative error per column, tolerance {TOLERANCE:g}):"
    )
    for g in report.symmetry:
        verdict = "ok" if g.ok else "BROKEN"
        origin = "" if g.declared else " (geometry, not declared)"
        click.echo(f"    {g.generator}{origin}: error {g.error:.1e} ({g.worst_column}) {verdict}")


@sim.command("mjcf")
@click.option("--robot", required=True, help="Registered robot, e.g. hexa.")
@click.option("--inclination", type=INCLINATION, default=0.0, show_default=True)
@click.option("--heading", type=FiniteFloat(), default=0.0, show_default=True)
def mjcf_command(robot: str, inclination: float, heading: float) -> None:
    """Print the generated MJCF of ROBOT on its arena (for inspection; never stored)."""
    from symbench.core.robot.specs import load_robot
    from symbench.core.sim.scene.arena import Arena
    from symbench.core.sim.scene.mjcf import build_spec

    spec = build_spec(load_robot(robot), Arena(inclination, heading))
    spec.compile()
    click.echo(spec.to_xml())
