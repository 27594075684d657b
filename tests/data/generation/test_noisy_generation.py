"""Data for control (issue 18 item 4): the expert's execution perturbed by torque noise, its
own command at the perturbed state recorded; noise 0 is exactly today's rollout; a noisy
preset variant with its own id, on which the closed-loop evaluator trains."""

from __future__ import annotations

import dataclasses
import json
from types import SimpleNamespace

import numpy as np
import pytest
from stand_ins import closed_loop_dataset, tracked_to_the_end, trained_on_split, without_open_loop

from symbench.core.common.errors import SymbenchError
from symbench.core.config.presets import PRESETS, dataset_id, parse_dataset_id
from symbench.core.data.storage.scenario_fields import StoredScenario
from symbench.core.runs.evaluation import REPLAY_FIELDS, EvaluationContext
from symbench.core.runs.spec import is_standard
from symbench.core.sim.climb.rollout import run_climb, simulate
from symbench.core.sim.scene.scenario import Scenario
from symbench.core.sim.scene.setup import Climb
from symbench.plugins.evaluators import closed_loop

SCENARIO = Scenario("hexa", inclination_deg=90.0, seconds=0.25)
NOISY = dataclasses.replace(SCENARIO, torque_noise=0.5)


def _same(a: dict[str, np.ndarray], b: dict[str, np.ndarray]) -> bool:
    return a.keys() == b.keys() and all(np.array_equal(a[k], b[k]) for k in a)


def test_no_noise_is_the_noise_free_rollout_bit_for_bit():
    assert SCENARIO.to_dict() == dataclasses.replace(SCENARIO, torque_noise=0.0).to_dict()
    assert "torque_noise" not in SCENARIO.to_dict()  # stored metadata as it always was
    plain = run_climb(Climb.from_scenario(SCENARIO), SCENARIO.seconds, 0.006)
    # a seed without noise draws nothing
    seeded = run_climb(
        Climb.from_scenario(SCENARIO), SCENARIO.seconds, 0.006, torque_noise=0.0, noise_seed=[1]
    )
    assert _same(simulate(SCENARIO).arrays, plain.arrays)
    assert _same(seeded.arrays, plain.arrays)


def test_noise_perturbs_the_execution_and_the_label_is_the_experts_command():
    climb, dt = Climb.from_scenario(NOISY), 0.001
    commands, executed = [], []

    def on_step(out, physics):  # after each physics step (the controller runs at every one)
        commands.append(out.command.copy())
        executed.append(np.asarray(physics.data.ptr.ctrl)[physics.layout.motor].copy())

    rollout = run_climb(
        climb, NOISY.seconds, dt, on_step, torque_noise=0.5, noise_seed=NOISY.noise_seed()
    )
    assert rollout.attached, rollout.failure
    commands, executed = np.array(commands), np.array(executed)
    noise = executed - commands
    assert noise.std() == pytest.approx(0.5, rel=0.1) and abs(noise.mean()) < 0.05
    # the label: the expert's command (without the noise) at the perturbed state
    a, control = rollout.arrays, climb.spec.control
    n = len(a["t"]) - 1

    def received(u: np.ndarray) -> np.ndarray:
        torque = u[:n] - control.kp * a["q"][:n] - control.kd * a["qd"][1:]
        return np.clip(torque, -control.torque_limit, control.torque_limit)

    assert np.array_equal(a["tau"][:n], received(commands))
    assert not np.allclose(a["tau"][:n], received(executed))
    # the motion is not the noise-free one; the noise is the same in every run
    clean = run_climb(Climb.from_scenario(SCENARIO), SCENARIO.seconds, dt)
    assert not np.allclose(clean.arrays["q"], a["q"])
    again = simulate(NOISY, record_period=dt)  # the scenario's own seed
    assert _same(again.arrays, a)
    assert _same(simulate(NOISY).arrays, simulate(NOISY).arrays)


def test_the_noise_is_a_stored_scenario_field():
    d = NOISY.to_dict()
    assert d["torque_noise"] == 0.5 and Scenario.from_dict(d) == NOISY
    StoredScenario.model_validate(d)
    assert "torque_noise" not in REPLAY_FIELDS  # imported scenarios need not state it
    assert NOISY.noise_seed() != dataclasses.replace(NOISY, yaw_deg=30.0).noise_seed()
    with pytest.raises(SymbenchError, match="torque_noise must not be negative"):
        Scenario("hexa", torque_noise=-0.1)


def test_the_noisy_preset_is_smalls_grid_with_noise_under_its_own_id():
    did = dataset_id("hexa", "small-noisy")
    assert did == "hexa-climb-small-noisy-v7"
    assert parse_dataset_id(did) == ("hexa", "small-noisy") and is_standard(did)
    assert parse_dataset_id("hexa-climb-small-v7") == ("hexa", "small")
    assert parse_dataset_id("hexa-climb-large-noisy-v7") is None
    small, noisy = PRESETS["small"], PRESETS["small-noisy"]
    assert noisy.dataset == dataclasses.replace(small.dataset, torque_noise=0.5)
    clean = small.scenarios("hexa", 6, 6)
    assert noisy.scenarios("hexa", 6, 6) == [
        dataclasses.replace(s, torque_noise=0.5) for s in clean
    ]
    assert "torque_noise" not in small.grid(6) and noisy.grid(6)["torque_noise"] == 0.5
    assert small.closed_loop.train_preset == "small-noisy"
    assert PRESETS["smoke"].closed_loop.train_preset == "smoke-noisy"


def test_the_noisy_smoke_dataset_is_the_same_on_every_machine(tmp_path, monkeypatch):
    """The noise is drawn from the scenario: the dataset matches the committed hash."""
    from symbench.core.data.generation.generate import generate
    from symbench.core.data.generation.reference_hashes import LIBRARY_VERSIONS, reference_hash
    from symbench.core.data.storage.metadata import library_versions

    monkeypatch.setenv("SYMBENCH_HOME", str(tmp_path))
    report = generate("hexa", "smoke-noisy", workers=1, show_progress=False)
    assert report.dataset_id == "hexa-climb-smoke-noisy-v7" and report.n_failed == 0
    if library_versions() != LIBRARY_VERSIONS:
        pytest.skip("the installed libraries are not the pinned ones")
    assert report.content_hash == reference_hash(report.dataset_id, LIBRARY_VERSIONS)
    meta = json.loads((report.root / "metadata.json").read_text())
    assert meta["scenario_grid"]["torque_noise"] == 0.5
    assert all(t["scenario"]["torque_noise"] == 0.5 for t in meta["trajectories"])


@pytest.mark.parametrize(
    ("did", "trained_on"),
    [
        ("hexa-climb-smoke-v7", "hexa-climb-smoke-noisy-v7"),  # standard: its noisy variant
        ("hexa-climb-smoke-noisy-v7", "hexa-climb-smoke-noisy-v7"),  # itself
        ("my-hexa-logs", "my-hexa-logs"),  # imported: no noisy variant, its own data
    ],
)
def test_the_closed_loop_trains_on_the_noisy_variant_and_says_so(
    monkeypatch, tmp_path, did, trained_on
):
    simulated, asked = [], []

    def simulate(scenario, record_period, push=None):
        simulated.append(scenario)
        steps = int(round(scenario.seconds / 0.001))
        arrays = {"t": 0.001 * np.arange(steps), "tau": np.zeros((steps, 6, 3))}
        return SimpleNamespace(attached=True, arrays=arrays)

    def track(scenario, reference, policy, pd, observe=None, push=None):
        policy({"t": np.zeros(1)})  # the model is asked
        return tracked_to_the_end(scenario)

    def retrain(split, variant):
        asked.append((did, split, variant))
        return trained_on_split(split, variant)

    def retrain_on(other, split, variant):
        asked.append((other, split, variant))
        return trained_on_split(split, variant)

    def track_batch(jobs, policy):  # the model's rollouts (its policy is built, not run)
        return [track(job.scenario, job.reference, lambda rows: None, job.pd_gains) for job in jobs]

    # where the closed loop's one implementation (`ClosedLoopSetup`) finds them
    monkeypatch.setattr("symbench.core.sim.climb.rollout.simulate", simulate)
    monkeypatch.setattr("symbench.core.runs.closed_loop.track", track)
    monkeypatch.setattr("symbench.core.runs.closed_loop.track_batch", track_batch)
    without_open_loop(monkeypatch)
    noise = {"torque_noise": 0.5} if "noisy" in did else {}
    dataset = closed_loop_dataset(
        [{"robot": "hexa", "yaw_deg": 10.0 * i, **noise} for i in range(2)], did
    )
    context = EvaluationContext(
        entry=SimpleNamespace(name="m", backend="torch", view="leg_grouped", variant="acc"),
        dataset=dataset,
        preset=PRESETS["smoke"],
        split="iid",
        seed=0,
        predict=None,
        test=None,
        test_trajectories=np.arange(2),
        output_dir=tmp_path,
        retrain=retrain,
        retrain_on=retrain_on,
    )
    metrics = closed_loop.evaluate(context)
    assert metrics["trained_on"] == trained_on
    assert asked == [(trained_on, "iid", "next")]
    # the references are the expert's climbs without noise
    assert simulated and all(s.torque_noise == 0.0 for s in simulated)
