"""The views and the raw action on simulated data, and the recorded flags against MuJoCo."""

from __future__ import annotations

import numpy as np
import pytest

from symbench.core.data.symmetry.raw_action import act_on_raw, rotate_scene_about_gravity
from symbench.core.data.views import schema
from symbench.core.data.views.frames import LegFrames
from symbench.core.data.views.transforms import build_view
from symbench.core.robot.specs import load_robot
from symbench.core.sim.climb import rollout as sim
from symbench.core.sim.scene.scenario import Scenario

SECONDS = 0.3


@pytest.fixture(scope="module")
def rollouts():
    """A short wall climb per robot (the arrays are usable whether or not it stayed on)."""
    return {
        r: sim.simulate(Scenario(r, inclination_deg=90.0, yaw_deg=20.0, seconds=SECONDS))
        for r in ("magneto", "hexa", "nona")
    }


def _leg_grouped(arrays, frames, variant="next"):
    return build_view(arrays, np.zeros(len(arrays["t"]), int), frames, "leg_grouped", variant)


@pytest.mark.parametrize("robot", ["magneto", "hexa", "nona"])
def test_simulated_views_commute_with_every_group_element(rollouts, robot):
    spec = load_robot(robot)
    frames = LegFrames.from_spec(spec)
    raw = rollouts[robot].arrays
    assert len(raw["t"]) == round(SECONDS / 0.006) or not rollouts[robot].attached
    for variant in schema.VARIANTS:
        layout = schema.leg_grouped_input(variant)
        base = _leg_grouped(raw, frames, variant)
        for g in spec.group:
            moved = _leg_grouped(act_on_raw(g, raw, frames), frames, variant)
            np.testing.assert_allclose(
                moved.inputs["x"],
                spec.group.act(g, base.inputs["x"], layout.reflection_signs),
                atol=1e-10,
                rtol=0,
            )
            np.testing.assert_allclose(
                moved.target, spec.group.act(g, base.target), atol=1e-10, rtol=0
            )


def test_simulated_leg_grouped_is_invariant_to_turning_the_scene_about_gravity(rollouts):
    frames = LegFrames.from_spec(load_robot("hexa"))
    raw = rollouts["hexa"].arrays
    base = _leg_grouped(raw, frames)
    turned = _leg_grouped(rotate_scene_about_gravity(raw, 1.1), frames)
    np.testing.assert_allclose(turned.inputs["x"], base.inputs["x"], atol=1e-10, rtol=0)


def test_a_scene_simulated_at_another_heading_gives_the_same_leg_grouped_data(rollouts):
    """The simulator itself is gravity-axis symmetric: a real rotated run, not a transform."""
    frames = LegFrames.from_spec(load_robot("hexa"))
    turned = sim.simulate(
        Scenario("hexa", inclination_deg=90.0, heading_deg=33.0, yaw_deg=20.0, seconds=SECONDS)
    )
    a, b = _leg_grouped(rollouts["hexa"].arrays, frames), _leg_grouped(turned.arrays, frames)
    assert a.inputs["x"].shape == b.inputs["x"].shape
    # measured ~1e-10 over a second (accelerations); the view itself adds nothing
    np.testing.assert_allclose(b.inputs["x"], a.inputs["x"], atol=1e-8, rtol=0)
    np.testing.assert_allclose(b.target, a.target, atol=1e-8, rtol=0)
    vec_a = build_view(
        rollouts["hexa"].arrays, np.zeros(len(a.target) + 1, int), frames, "vector", "acc"
    )
    vec_b = build_view(turned.arrays, np.zeros(len(b.target) + 1, int), frames, "vector", "acc")
    assert np.abs(vec_a.inputs["x"] - vec_b.inputs["x"]).max() > 1e-2  # the world frame moved


def _reach(m, d, geom: int, normal: np.ndarray) -> float:
    """How far a sphere or cylinder sole reaches from its centre towards the surface."""
    import mujoco

    size = m.geom_size[geom]
    if m.geom_type[geom] == mujoco.mjtGeom.mjGEOM_SPHERE:
        return float(size[0])
    assert m.geom_type[geom] == mujoco.mjtGeom.mjGEOM_CYLINDER, "a sole shape this test lacks"
    along = abs(d.geom_xmat[geom].reshape(3, 3)[:, 2] @ normal)  # cylinder axis vs normal
    return float(size[1] * along + size[0] * np.sqrt(max(0.0, 1.0 - along**2)))


@pytest.mark.parametrize("robot, inclination", [("magneto", 0.0), ("hexa", 0.0), ("hexa", 90.0)])
def test_recorded_contact_and_magnet_flags_match_the_physics(robot, inclination):
    """Recomputed from MuJoCo's state by name and geometry, not through the recorder."""
    import mujoco

    from symbench.core.sim.scene.mjcf import SURFACE, magnet_name, sole_name
    from symbench.core.sim.scene.setup import Climb

    spec = load_robot(robot)
    scenario = Scenario(robot, inclination_deg=inclination, seconds=1.2)
    seen = {}

    def on_step(out, physics):
        m, d = physics.model.ptr, physics.data.ptr
        step = int(round(d.time / m.opt.timestep))  # the state the next row records
        surface = mujoco.mj_name2id(m, mujoco.mjtObj.mjOBJ_GEOM, SURFACE)
        normal, origin = d.geom_xmat[surface].reshape(3, 3)[:, 2], d.geom_xpos[surface]
        soles = [
            mujoco.mj_name2id(m, mujoco.mjtObj.mjOBJ_GEOM, sole_name(i)) for i in range(spec.n_legs)
        ]
        gap = (d.geom_xpos[soles] - origin) @ normal - [_reach(m, d, g, normal) for g in soles]
        magnets = [
            mujoco.mj_name2id(m, mujoco.mjtObj.mjOBJ_ACTUATOR, magnet_name(i))
            for i in range(spec.n_legs)
        ]
        base = d.xmat[mujoco.mj_name2id(m, mujoco.mjtObj.mjOBJ_BODY, "base")].reshape(3, 3)
        soles_in_base = (
            d.geom_xpos[soles] - d.xpos[mujoco.mj_name2id(m, mujoco.mjtObj.mjOBJ_BODY, "base")]
        ) @ base
        seen[step] = (gap, d.ctrl[magnets].copy(), soles_in_base)

    rollout = sim.run_climb(Climb.from_scenario(scenario), scenario.seconds, 0.006, on_step)
    raw = rollout.arrays
    mounts = np.radians(spec.mount_angles_deg)
    checked = 0
    for row in range(1, len(raw["t"])):
        step = int(round(raw["t"][row] / spec.control.timestep))
        if step not in seen or step + 1 not in seen:
            continue
        gap, _, soles_in_base = seen[step]  # the state row `row` was recorded from
        ctrl = seen[step + 1][1]  # the magnet command applied from that state on
        margin = spec.magnet.contact_distance
        clear = np.abs(gap - margin) > 1e-4
        np.testing.assert_array_equal(raw["contact"][row][clear], (gap < margin)[clear])
        np.testing.assert_array_equal(raw["magnet"][row], ctrl > 0)  # engaged: any pull at all
        # leg i's foot lies in the direction of leg i's mount: the flags are indexed right
        angle = np.arctan2(soles_in_base[:, 1], soles_in_base[:, 0])
        assert np.all(np.abs(np.angle(np.exp(1j * (angle - mounts)))) < np.radians(45))
        checked += 1
    assert checked > 100
    assert raw["contact"].min() == 0 and raw["magnet"].min() == 0  # a foot did swing
    assert raw["contact"].max() == 1 and raw["magnet"].max() == 1


@pytest.mark.slow  # two generations (each robot's hash: test_same_data_on_every_cpu)
def test_generating_the_smoke_preset_twice_gives_the_same_hash(tmp_path, monkeypatch):
    """`symbench data generate --robot hexa --preset smoke`, twice, with 1 and 2 workers."""
    from symbench.core.data.generation.generate import generate

    reports = []
    for workers in (1, 2):
        monkeypatch.setenv("SYMBENCH_HOME", str(tmp_path / f"w{workers}"))
        reports.append(generate("hexa", "smoke", workers=workers, show_progress=False))
    a, b = reports
    assert a.content_hash == b.content_hash and a.n_trajectories + a.n_failed == 6
    for path in sorted((a.root / "trajectories").iterdir()):
        assert path.read_bytes() == (b.root / "trajectories" / path.name).read_bytes()


@pytest.mark.slow
def test_ctrl_c_during_generation_keeps_finished_work_and_resumes(tmp_path):
    """The real thing: Ctrl-C (SIGINT to the process group) with 2 workers, then resume."""
    import os
    import signal
    import subprocess
    import sys
    import time
    from pathlib import Path

    from symbench.core.config.presets import dataset_id

    env = dict(os.environ, MUJOCO_GL="disable", SYMBENCH_HOME=str(tmp_path))
    command = [
        str(Path(sys.executable).with_name("symbench")),
        "data",
        "generate",
        "--robot",
        "magneto",
        "--preset",
        "small",
        "--no-progress",
    ]
    proc = subprocess.Popen(
        command,
        env=env,
        start_new_session=True,
        stdout=subprocess.PIPE,
        stderr=subprocess.STDOUT,
        preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL),
    )
    folder = tmp_path / "datasets" / dataset_id("magneto", "small") / "records"
    while not folder.is_dir() or len(list(folder.glob("*.json"))) < 3:
        time.sleep(0.2)
    os.killpg(proc.pid, signal.SIGINT)
    out = proc.communicate(timeout=60)[0].decode()
    assert proc.returncode == 1 and "run the same command again to resume" in out
    kept = len(list(folder.glob("*.json")))
    resumed = subprocess.run(command, env=env, capture_output=True, text=True, timeout=600)
    assert resumed.returncode == 0, resumed.stderr
    assert f"{kept} kept" in resumed.stdout.replace("\n", " ")
