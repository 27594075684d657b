"""`symbench data symmetry`: image pairs compared after relabelling, against a noise floor.

A generated dataset is symmetric to float precision; data with one leg's torques 10 % larger
shows a gap far above the floor, and so do climbs simulated with a robot whose leg 0 really
is 10 % heavier (robot.toml has one set of link masses for every leg, so the test scales
leg 0's links in the MuJoCo model it builds).
"""

from __future__ import annotations

import json

import numpy as np
import pytest
from cli_invoke import error_line, invoke

from symbench.core.common.errors import SymbenchError
from symbench.core.data.symmetry.measure import measure
from symbench.core.data.symmetry.pairing import find_pairs, rotation_angles
from symbench.core.data.symmetry.raw_action import act_on_raw
from symbench.core.data.views.frames import LegFrames
from symbench.core.robot.specs import load_robot

HEAVIER = 1.1


def _smooth_raw(n_legs: int, n_steps: int = 200, seed: int = 0) -> dict[str, np.ndarray]:
    """Slow sinusoids in every raw column (sampled every 6 ms, like a climb)."""
    rng = np.random.default_rng(seed)
    t = np.arange(n_steps) * 0.006

    def wave(*shape: int) -> np.ndarray:
        amp = rng.uniform(0.5, 2.0, shape)
        freq = rng.uniform(0.3, 1.5, shape)
        phase = rng.uniform(0, 2 * np.pi, shape)
        return amp * np.sin(2 * np.pi * freq * t.reshape(-1, *[1] * len(shape)) + phase)

    quat = np.array([1.0, 0.0, 0.0, 0.0]) + 0.1 * wave(4)
    return {
        "t": t,
        "base_pos": wave(3),
        "base_quat": quat / np.linalg.norm(quat, axis=1, keepdims=True),
        "base_linvel": wave(3),
        "base_angvel": wave(3),
        "base_linacc": wave(3),
        "q": wave(n_legs, 3),
        "qd": wave(n_legs, 3),
        "qdd": wave(n_legs, 3),
        "tau": wave(n_legs, 3),
        "contact": np.ones((n_steps, n_legs), np.uint8),
        "magnet": np.ones((n_steps, n_legs), np.uint8),
    }


def _twins(robot: str = "hexa"):
    """Trajectory 0 and its images under every rotation, with matching yaws."""
    spec = load_robot(robot)
    frames = LegFrames.from_spec(spec)
    base = _smooth_raw(spec.n_legs)
    trajectories, scenarios = {0: base}, [{"yaw_deg": 0.0, "heading_deg": 0.0}]
    for i, (g, angle) in enumerate(rotation_angles(spec.group, frames), start=1):
        trajectories[i] = act_on_raw(g, base, frames)
        scenarios.append({"yaw_deg": angle, "heading_deg": 0.0})
    return spec, frames, trajectories, scenarios


def test_exact_images_are_found_and_agree_to_float_precision():
    spec, frames, trajectories, scenarios = _twins()
    images, repeats = find_pairs(scenarios, list(trajectories), spec.group, frames)
    assert len(images) == 15 and repeats == []  # every pair of the 6 yaws 60 degrees apart
    report = measure(trajectories, scenarios, spec.group, frames, "twins", "hexa")
    assert report.floor_source == "high-frequency"
    for row in report.groups.values():
        assert row["relative_error"] < 1e-12
        assert row["verdict"] == "exact (float precision)"
    assert report.flags == {"contact": 0.0, "magnet": 0.0}


def test_one_heavier_leg_shows_a_gap_above_the_floor():
    spec, frames, trajectories, scenarios = _twins()
    for raw in trajectories.values():  # leg 0 of every recording is the heavier one
        raw["tau"] = raw["tau"].copy()
        raw["tau"][:, 0] *= HEAVIER
    report = measure(trajectories, scenarios, spec.group, frames, "heavy", "hexa")
    torques = report.groups["torques"]
    assert 0.02 < torques["relative_error"] < 0.2
    assert torques["ratio"] > 10 and torques["verdict"].startswith("asymmetric")
    assert report.groups["joint states"]["verdict"] == "exact (float precision)"


def test_repeats_give_the_floor_when_there_are_some():
    spec, frames, trajectories, scenarios = _twins("magneto")
    rng = np.random.default_rng(1)
    repeat = {k: v + rng.normal(scale=1e-3, size=v.shape) for k, v in trajectories[0].items()}
    repeat["contact"], repeat["magnet"] = trajectories[0]["contact"], trajectories[0]["magnet"]
    trajectories[2], scenarios = repeat, [*scenarios, scenarios[0]]
    report = measure(trajectories, scenarios, spec.group, frames, "repeats", "magneto")
    assert report.floor_source == "repeats" and report.repeats == 1
    assert len(report.pairs) == 2  # 0 -> 1 and 1 -> the repeat of 0
    assert report.groups["torques"]["verdict"] == "within noise"


def test_no_image_pair_is_a_clear_error():
    spec, frames, trajectories, scenarios = _twins()
    scenarios = [{**s, "yaw_deg": 10.0 * i} for i, s in enumerate(scenarios)]
    with pytest.raises(SymbenchError, match="no pair of trajectories that are images"):
        measure(trajectories, scenarios, spec.group, frames, "none", "hexa")


@pytest.fixture(scope="module")
def smoke_home(real_smoke_copy):
    """The real smoke datasets (hexa's is used) in a private home."""
    with real_smoke_copy("symmetry-home") as home:
        yield home


def test_cli_on_a_generated_dataset_and_on_a_heavier_leg(smoke_home, tmp_path):
    from symbench.core.data import load_dataset
    from symbench.core.data.importing.importer import export_dataset, import_logs

    result = invoke("data", "symmetry", "hexa-climb-smoke-v7", "--json", "--output", tmp_path)
    assert result.exit_code == 0, result.output
    report = json.loads(result.stdout)
    assert report["image_pairs"] == 2 and report["floor"] == "high-frequency"
    for row in report["groups"].values():
        assert row["relative_error"] < 1e-6, row
    assert (tmp_path / "symmetry-hexa-climb-smoke-v7.png").stat().st_size > 0

    folder = export_dataset(load_dataset("hexa-climb-smoke-v7"), tmp_path / "logs", "npz")
    for path in folder.glob("*.npz"):
        with np.load(path) as npz:
            arrays = dict(npz)
        arrays["tau"][:, 0] *= HEAVIER
        np.savez(path, **arrays)
    import_logs(folder, "hexa-heavy-leg")
    table = invoke("data", "symmetry", "hexa-heavy-leg")
    assert table.exit_code == 0, table.output
    assert "2 image pairs" in table.stdout and "asymmetric" in table.stdout
    torques = next(line for line in table.stdout.splitlines() if "torques" in line)
    assert "asymmetric" in torques
    assert (smoke_home / "datasets" / "hexa-heavy-leg" / "symmetry.png").is_file()


def test_cli_names_a_dataset_without_pairs(smoke_home, tmp_path):
    from synthetic_raw import synthetic_raw

    from symbench.core.data.importing.importer import import_logs

    folder = tmp_path / "one"
    folder.mkdir()
    np.savez(folder / "run.npz", **synthetic_raw(6, 20))
    (folder / "import.json").write_text(json.dumps({"robot": "hexa", "record_period_s": 0.006}))
    import_logs(folder, "one-log")
    line = error_line(invoke("data", "symmetry", "one-log"), 1)
    assert "dataset 'one-log' has no pair of trajectories that are images" in line


def _simulated_climbs(monkeypatch, heavier: float):
    """hexa on a wall at yaws 0 and 180 degrees (images under the half turn), 0.4 s each,
    simulated with leg 0's links (mass and inertia) `heavier` times their spec's."""
    import symbench.core.sim.scene.mjcf as model
    from symbench.core.sim.climb.rollout import simulate
    from symbench.core.sim.scene.scenario import Scenario

    inertial = model._inertial

    def scaled(body, mass, inertia, com=(0.0, 0.0, 0.0)):
        factor = heavier if body.name.startswith("leg0_") else 1.0
        inertial(body, mass * factor, [i * factor for i in inertia], com)

    monkeypatch.setattr(model, "_inertial", scaled)
    scenarios = [
        Scenario("hexa", 90.0, 0.0, yaw, "forward", None, 0, 0.4).to_dict() for yaw in (0.0, 180.0)
    ]
    trajectories = {k: simulate(Scenario.from_dict(s)).arrays for k, s in enumerate(scenarios)}
    return trajectories, tuple(scenarios)


def test_a_simulated_robot_with_a_heavier_leg_is_measurably_asymmetric(monkeypatch):
    """Not perturbed data: the physics of a robot whose leg 0 is 10 % heavier."""
    spec = load_robot("hexa")
    frames = LegFrames.from_spec(spec)
    verdicts = {}
    for heavier in (1.0, HEAVIER):
        trajectories, scenarios = _simulated_climbs(monkeypatch, heavier)
        report = measure(trajectories, scenarios, spec.group, frames, "sim", "hexa")
        assert len(report.pairs) == 1
        verdicts[heavier] = {g: row["verdict"] for g, row in report.groups.items()}
        ratios = [row["ratio"] for row in report.groups.values()]
        if heavier == 1.0:
            assert all(row["relative_error"] < 1e-9 for row in report.groups.values())
        else:
            assert min(ratios) > 10  # every group, the torques most of all
    assert set(verdicts[1.0].values()) == {"exact (float precision)"}
    assert all(v.startswith("asymmetric") for v in verdicts[HEAVIER].values())
