"""The climbing loop: contact flags, recorded columns, symmetry, the dm-control API, the CLI."""

from __future__ import annotations

import json
import re
from dataclasses import replace

import numpy as np
import pytest
from cli_invoke import error_line
from click.testing import CliRunner

from symbench.core.cli import build_cli
from symbench.core.common.errors import SymbenchError
from symbench.core.plugin import registry
from symbench.core.robot.specs import load_robot
from symbench.core.sim.climb.rollout import run_climb, simulate
from symbench.core.sim.gait.plan import SETTLE
from symbench.core.sim.raw import COLUMN_NAMES
from symbench.core.sim.scene.arena import Arena
from symbench.core.sim.scene.scenario import Scenario
from symbench.core.sim.scene.setup import Climb
from symbench.core.sim.symmetry import check_element
from symbench.core.symmetry.groups import mirror, shift


def test_contact_flag_follows_a_lifted_foot_on_a_wall():
    """Leg 0 swings first: its flag is true while down, false in the air, true once landed."""
    spec = load_robot("hexa")
    rollout = run_climb(Climb(spec, Arena(90.0, 0.0)), 1.15)
    assert rollout.attached, rollout.failure
    a, g = rollout.arrays, spec.gait
    t, contact = a["t"], a["contact"][:, 0].astype(bool)
    lift = SETTLE + g.release
    land = lift + g.swing
    assert contact[t < lift].all()
    mid_swing = (t > lift + 0.1) & (t < land - 0.1)
    assert mid_swing.any() and not contact[mid_swing].any()
    assert contact[t > land + g.touchdown].all()
    assert a["contact"][:, 1:].all()  # the other feet never leave
    assert a["magnet"][t < SETTLE, 0].all()
    assert not a["magnet"][(t >= SETTLE) & (t < land), 0].any()  # released, then swinging
    assert a["magnet"][t > land, 0].all()


def test_recorded_columns_are_consistent():
    """Raw schema columns, rows aligned: positions integrate with the next velocities
    (semi-implicit Euler), velocities with the recorded accelerations."""
    spec = load_robot("magneto")
    rollout = run_climb(Climb(spec, Arena(30.0, 45.0), yaw_deg=20.0), 0.3, record_period=0.001)
    a = rollout.arrays
    assert set(a) == set(COLUMN_NAMES)
    dt = spec.control.timestep
    np.testing.assert_allclose(np.diff(a["q"], axis=0), dt * a["qd"][1:], atol=1e-12)
    np.testing.assert_allclose(
        np.diff(a["base_pos"], axis=0), dt * a["base_linvel"][1:], atol=1e-12
    )
    np.testing.assert_allclose(np.diff(a["qd"], axis=0), dt * a["qdd"][:-1], atol=1e-9)
    np.testing.assert_allclose(
        np.diff(a["base_linvel"], axis=0), dt * a["base_linacc"][:-1], atol=1e-9
    )
    assert np.abs(a["tau"]).max() < spec.control.torque_limit - 1e-6  # never needed the clip


def test_slower_controller_still_climbs_and_records_applied_torques():
    """QP every 3 ms, servos every 1 ms: attached, and the recorded torque is the servo's."""
    spec = load_robot("hexa")
    rollout = run_climb(
        Climb(spec, Arena(90.0, 0.0)), 0.6, record_period=0.001, control_period=0.003
    )
    assert rollout.attached and rollout.metrics["control_period"] == pytest.approx(0.003)
    tau = rollout.arrays["tau"]
    assert np.abs(tau).max() < spec.control.torque_limit - 1e-6  # never needed the clip
    assert np.abs(np.diff(tau, axis=0)).max() > 0  # servo feedback acts between QP solves
    with pytest.raises(SymbenchError, match="control_period"):
        run_climb(Climb(spec, Arena()), 0.01, control_period=0.0015)


def test_simulate_records_every_six_milliseconds():
    rollout = simulate(Scenario("nona", inclination_deg=60, seconds=0.3))
    assert rollout.attached
    np.testing.assert_allclose(np.diff(rollout.arrays["t"]), 0.006, atol=1e-12)
    assert rollout.arrays["q"].shape == (50, 9, 3)


def test_hexa_rotated_relabelled_run_reproduces_the_original():
    """60 degrees of base yaw + relabelling by one leg: the same run over 1 s, every column
    within 1e-9 of its largest value (accelerations in stiff contacts reach 1e3 rad/s^2)."""
    climb = Climb(load_robot("hexa"), Arena(60.0, 30.0), yaw_deg=10.0, seed=1)
    check = check_element(climb, shift(6, 1), 1.0)
    assert set(check.columns) == {*COLUMN_NAMES} - {"t", "base_quat"} | {"base_rotation"}
    assert check.declared and check.error < 1e-9, check.columns


@pytest.mark.parametrize("robot, offset", [("magneto", 3), ("hexa", 1), ("nona", 4)])
def test_a_mirrored_relabelled_run_reproduces_the_original(robot, offset):
    """The scene mirrored across the slope line on a tilted, turned arena: the robot's
    mirror image (legs relabelled, coxa angles flipped) runs the mirror image of the climb."""
    spec = load_robot(robot)
    climb = Climb(spec, Arena(60.0, 30.0), yaw_deg=7.0, seed=1)
    check = check_element(climb, mirror(spec.n_legs, offset), 0.6)
    assert not check.declared and check.error < 1e-9, check.columns


@pytest.mark.parametrize("robot, offset", [("magneto", 3), ("hexa", 1), ("nona", 4)])
def test_twins_with_drawn_steps_reproduce_the_original(robot, offset):
    """Dataset v7's climbs step with drawn swing heights and goals: a rotated and a mirrored
    twin (legs relabelled) still run the same climb, over more than one step, so the data's
    distribution keeps the robot's symmetry while no two climbs share their draws."""
    spec = load_robot(robot)
    climb = Climb(spec, Arena(60.0, 30.0), yaw_deg=7.0, seed=3, gait_spread=0.2)
    seconds = 0.3 + 2 * spec.gait.step_duration
    turned = check_element(climb, shift(spec.n_legs, spec.symmetry_shift), seconds)
    mirrored = check_element(climb, mirror(spec.n_legs, offset), seconds)
    assert turned.declared and turned.error < 1e-9, turned.columns
    assert mirrored.error < 1e-9, mirrored.columns


def test_drawn_steps_differ_from_the_fixed_gait_and_stay_within_their_spread():
    spec = load_robot("hexa")
    fixed = Climb(spec, Arena(90.0, 0.0), seed=3)
    drawn = replace(fixed, gait_spread=0.2)
    assert fixed.step_draws() == (None, None)
    heights, offsets = drawn.step_draws()
    assert heights is not None and offsets is not None
    g = spec.gait
    assert np.all(np.abs(heights / g.swing_height - 1) <= 0.2) and heights.std() > 0
    assert np.all(np.abs(offsets) <= 0.2 * g.step_length) and offsets.std() > 0
    t = 0.2 + g.release + 0.5 * g.swing  # the first step's apex
    a, b = fixed.plan().targets(t), drawn.plan().targets(t)
    assert a.step_leg == b.step_leg and not np.allclose(a.sole_pos, b.sole_pos)
    other = replace(drawn, seed=4).step_draws()[0]
    assert other is not None and not np.allclose(other, heights)  # each climb its own


def test_symmetry_check_can_fail(monkeypatch):
    """A twin that is rotated but not relabelled must not match: the test has teeth."""
    from dataclasses import replace

    from symbench.core.sim import symmetry

    monkeypatch.setattr(symmetry, "twin_climb", lambda c, g: replace(c, yaw_deg=c.yaw_deg + 90))
    check = check_element(Climb(load_robot("magneto"), Arena(0.0, 0.0)), shift(4, 2), 0.3)
    assert check.error > 1e-3 and not check.ok


def test_dm_control_environment():
    from dm_control.rl import control

    from symbench.core.sim.scene.task import load

    env = load("magneto", inclination_deg=90, heading_deg=30, yaw_deg=15, seed=3, time_limit=0.01)
    assert isinstance(env, control.Environment)
    assert env.action_spec().shape == (16,)
    step = env.reset()
    assert step.observation["q"].shape == (4, 3)
    assert step.observation["contact"].all()
    while not step.last():
        step = env.step(np.zeros(16))
    assert env.physics.data.time == pytest.approx(0.01)


def test_bad_input_is_named():
    with pytest.raises(SymbenchError, match="record_period"):
        run_climb(Climb(load_robot("hexa"), Arena()), 0.01, record_period=0.0025)
    with pytest.raises(SymbenchError, match="leg order"):
        run_climb(Climb(load_robot("hexa"), Arena(), order=(0, 1, 2)), 0.01)
    with pytest.raises(SymbenchError, match="inclination"):
        Arena(190.0)


def test_sim_check_and_bench_commands():
    runner = CliRunner()
    cli = build_cli()
    result = runner.invoke(
        cli,
        ["sim", "check", "--robot", "hexa", "--inclination", "30", "--seconds", "0.4", "--json"],
    )
    assert result.exit_code == 0, result.output
    report = json.loads(result.output)
    assert report["attached"] and report["torque_within_limit"]
    assert report["peak_torque_femur"] <= report["torque_limit"]
    result = runner.invoke(
        cli, ["bench", "sim", "--robot", "magneto", "--seconds", "0.3", "--json"]
    )
    assert result.exit_code == 0, result.output
    bench = json.loads(result.output)
    assert bench["ratio"] == pytest.approx(
        bench["control_steps_per_s"] / bench["raw_mj_step_per_s"]
    )
    result = runner.invoke(cli, ["sim", "check", "--robot", "hexx"])
    known = ", ".join(sorted(registry.collect("robots")))
    assert error_line(result, 1) == (
        f"Error: unknown robot 'hexx'; did you mean hexa? (known: {known})"
    )
    result = runner.invoke(cli, ["sim", "mjcf", "--robot", "nona", "--inclination", "90"])
    assert result.exit_code == 0 and result.output.count('_magnet" body="leg') == 9


def test_a_plugin_robot_that_falls_makes_sim_check_fail(tmp_path):
    """A robot added by a plugin (a spec folder) is simulated like the built-ins; with
    magnets too weak for a wall it detaches, and `sim check` exits non-zero."""
    import tomllib

    from symbench.core.plugin.entries import RobotEntry
    from symbench.core.plugin.hookspecs import hookimpl
    from symbench.core.plugin.host import PluginHost, set_host
    from symbench.plugins.robots import ROBOTS_DIR

    text = (ROBOTS_DIR / "hexa" / "robot.toml").read_text()
    text = text.replace('name = "hexa"', 'name = "weakling"').replace(
        "force = 147.0", "force = 3.0"
    )
    assert tomllib.loads(text)["magnet"]["force"] == 3.0
    (tmp_path / "weakling").mkdir()
    (tmp_path / "weakling" / "robot.toml").write_text(text)

    class Plugin:
        @hookimpl
        def symbench_robots(self):
            return [RobotEntry("weakling", tmp_path / "weakling", "hexa with weak magnets")]

    host = PluginHost()
    host.load_entry_points("none")
    host.register(Plugin(), "weak-robots")
    set_host(host)
    try:
        result = CliRunner().invoke(
            build_cli(),
            ["sim", "check", "--robot", "weakling", "--inclination", "90", "--seconds", "1"],
        )
    finally:
        set_host(None)
    assert result.exit_code == 1, result.output
    status = result.output.splitlines()[0]  # the rest: distances, errors, torques
    detached = (
        r"stance foot of leg\(s\) \d+(, \d+)* left the surface"
        r"|base tilted more than 30 degrees from the surface normal"
        r"|base dropped to \d+\.\d{3} m above the surface"
    )
    scenario = r"weakling at 90 deg \(heading 0, yaw 0, forward\)"
    assert re.fullmatch(
        rf"{scenario}, 0\.\d\d s: DETACHED \(t=0\.\d{{3}} s: ({detached})\)", status
    ), status
