"""Closed-loop control: the loop actuates exactly what the label means, and the protocol
tells a good feedforward from none."""

from __future__ import annotations

import re
from types import SimpleNamespace

import numpy as np
import pytest

from symbench.core.data import load_dataset
from symbench.core.robot.specs import load_robot
from symbench.core.runs.runner import RunSpec, run
from symbench.core.sim.scene.scenario import Scenario
from symbench.core.sim.tracking.learned_control import expert_reference, track
from symbench.core.sim.tracking.references import held_out_scenarios
from symbench.core.training.checkpoints import checkpoint_sha256
from symbench.core.training.resume import BEST_DIR
from symbench.core.training.trained_model import TENSORS, TrainedModel

ROBOTS = ("magneto", "hexa", "nona")
HEADLINE = 0.1  # the preset's headline PD fraction
FRACTIONS = (0.0, 0.1, 0.3, 1.0)  # the presets' PD fractions


def _climb(robot: str, seconds: float, **fields):
    scenario = Scenario(robot=robot, inclination_deg=90.0, seconds=seconds, **fields)
    reference = expert_reference(scenario)
    assert reference.attached, reference.failure
    return scenario, reference.arrays


def _oracle(ref):
    """The expert's recorded torque of the current step: the dataset's tau column."""
    dt = float(ref["t"][1] - ref["t"][0])
    return lambda rows: ref["tau"][int(round(float(rows["t"][0]) / dt))]


def _gains(robot: str, fraction: float) -> tuple[float, float]:
    control = load_robot(robot).control
    return fraction * control.kp, fraction * control.kd


@pytest.fixture(scope="module", params=ROBOTS)
def smoke_climb(request):
    return _climb(request.param, 1.0)  # the smoke preset's climb


def _assert_replays(scenario, ref, fraction: float) -> None:
    result = track(scenario, ref, _oracle(ref), _gains(scenario.robot, fraction))
    assert result.attached and result.failure is None
    assert result.steps == len(ref["t"])  # the whole climb
    assert result.time_to_failure_s == pytest.approx(len(ref["t"]) * (ref["t"][1] - ref["t"][0]))
    assert result.max_joint_error_rad < 1e-6, result
    assert result.base_drift_m < 1e-6 and result.base_drift_deg < 1e-4


def test_replaying_the_recorded_torques_is_the_experts_climb(smoke_climb):
    """The label is what the loop actuates: with no extra feedback, and with the PD at every
    fraction of the protocol (zero on the reference), the recorded tau gives back the
    expert's climb. So the oracle row is one replay, reported at every fraction."""
    scenario, ref = smoke_climb
    for fraction in FRACTIONS:
        _assert_replays(scenario, ref, fraction)


@pytest.mark.slow
@pytest.mark.parametrize("robot", ROBOTS)
def test_replay_holds_over_a_small_preset_climb(robot):
    scenario, ref = _climb(robot, 2.6, yaw_deg=30.0, direction="left", heading_deg=180.0)
    _assert_replays(scenario, ref, 0.0)


def test_the_reference_is_the_datasets_climb_every_physics_step(smoke_home):
    from symbench.core.data import load_dataset

    dataset = load_dataset("hexa-climb-smoke-v7")
    raw, ids = dataset.raw()
    fields = dataset.scenarios[0]
    reference = expert_reference(Scenario.from_dict(fields)).arrays
    rows = ids == dataset.trajectory_ids[0]
    every = 6  # record period / physics step
    # the same numbers up to rounding (generation runs in a worker with pinned kernels)
    for column in ("q", "qd", "tau", "base_pos", "magnet"):
        np.testing.assert_allclose(reference[column][::every], raw[column][rows], atol=1e-6)


def test_the_oracle_holds_and_the_pd_alone_does_not(smoke_climb):
    scenario, ref = smoke_climb
    gains = _gains(scenario.robot, HEADLINE)
    oracle = track(scenario, ref, _oracle(ref), gains)
    floor = track(scenario, ref, lambda rows: np.zeros_like(ref["tau"][0]), gains)
    assert oracle.attached and oracle.joint_rmse_rad < 1e-9
    assert not floor.attached or floor.joint_rmse_rad >= 3 * oracle.joint_rmse_rad
    assert not floor.attached, floor  # measured: it loses the path within 0.3 s
    assert re.fullmatch(
        r"stance foot of leg\(s\) \d(, \d)* left the surface"
        r"|base tilted more than 30 degrees from the surface normal"
        r"|base dropped to .*|base left its path .*",
        floor.failure,
    ), floor.failure
    assert floor.time_to_failure_s < oracle.time_to_failure_s


def test_the_tracking_cost_grows_with_the_error(smoke_climb):
    """The feedforward's error scaled up step by step: the tracking cost rises with it, from
    the oracle's (0) to the PD alone's (near 1: it falls early)."""
    scenario, ref = smoke_climb
    gains = _gains(scenario.robot, HEADLINE)
    oracle = _oracle(ref)
    costs = [
        track(scenario, ref, lambda rows, s=scale: s * oracle(rows), gains).tracking_cost
        for scale in (1.0, 0.97, 0.9, 0.0)
    ]
    assert costs[0] < 1e-9 and costs == sorted(costs) and len(set(costs)) == 4
    assert 0.5 < costs[-1] <= 1.0


def test_a_batch_tracks_each_job_as_alone(smoke_climb):
    """In lockstep, jobs that fall at once (PD alone, no gains), later (PD alone at the
    headline) and never (the oracle) each come out exactly as tracked alone: the shared
    rows belong to their job, and a finished job's rows are left alone."""
    from symbench.core.sim.tracking.learned_control import TrackJob, track_batch

    scenario, ref = smoke_climb
    oracle, zero = _oracle(ref), (lambda rows: np.zeros_like(ref["tau"][0]))
    cases = [(zero, 0.0), (oracle, HEADLINE), (zero, HEADLINE), (oracle, 0.0)]
    jobs = [TrackJob(scenario, ref, _gains(scenario.robot, f)) for _, f in cases]

    def each(rows):  # job i's policy on its own pair of rows
        pair = [{k: v[2 * i : 2 * i + 2] for k, v in rows.items()} for i in range(len(cases))]
        return np.stack([policy(r) for (policy, _), r in zip(cases, pair, strict=True)])

    together = track_batch(jobs, each)
    alone = [track(scenario, ref, policy, job.pd_gains) for (policy, _), job in zip(cases, jobs)]
    assert together == alone
    assert len({r.steps for r in together}) >= 2  # some ended before others


def test_the_reference_must_be_at_the_physics_step(smoke_climb):
    from symbench import SymbenchError

    scenario, ref = smoke_climb
    coarse = {k: v[::6] for k, v in ref.items()}
    with pytest.raises(SymbenchError, match="every physics step"):
        track(scenario, coarse, _oracle(coarse))


def test_closed_loop_evaluator_in_a_run(smoke_home, tmp_path):
    record = run(
        RunSpec(
            model="sdnn",
            robot="hexa",
            preset="smoke",
            evaluators=("closed-loop",),
            output=tmp_path,
            progress=False,
            max_steps=20,
        )
    )
    metrics = record.metrics["closed-loop"]
    # trained on the noisy variant of the standard dataset (made when missing), saying so
    assert metrics["trained_on"] == "hexa-climb-smoke-noisy-v7"
    folders = list((tmp_path / "checkpoints").glob("*/*/hexa-climb-smoke-noisy-v7-*/iid__next"))
    assert len(folders) == 1
    assert metrics["references"] >= 1 and metrics["horizon_s"] == 1.0  # the climb's length
    assert metrics["pd_fractions"] == [0.0, 0.1, 0.3, 1.0]
    assert metrics["headline_pd_fraction"] == HEADLINE
    assert set(metrics["by_pd_fraction"]) == {"0.0", "0.1", "0.3", "1.0"}
    for prefix in ("", "pd_"):
        assert 0.0 <= metrics[f"{prefix}success_rate"] <= 1.0
        assert 0.0 < metrics[f"{prefix}time_to_failure_s"] <= metrics["horizon_s"]
        assert metrics[f"{prefix}joint_rmse_rad"] >= 0.0
        assert metrics[f"{prefix}oracle_success_rate"] == 1.0
        assert metrics[f"{prefix}oracle_joint_rmse_rad"] < 1e-9
        assert metrics[f"{prefix}floor_success_rate"] == 0.0
    assert metrics["expert_success_rate"] == 1.0
    score = metrics["pd_normalized_score"]
    assert score is not None and score < 1.0  # two epochs: nowhere near the oracle
    # the continuous score, per reference and over them
    tracking = metrics["pd_tracking_score"]
    low, high = metrics["pd_tracking_score_ci95"]
    assert tracking < 1.0 and low <= tracking <= high
    assert metrics["pd_oracle_tracking_cost"] < 1e-9 < metrics["pd_floor_tracking_cost"] <= 1.0
    per_reference = metrics["per_reference"]
    assert len(per_reference) == metrics["references"]
    for item in per_reference:  # every reference pushed as the preset says
        assert item["push"]["duration_s"] == 0.1 and item["open_loop_torque_rmse"] > 0.0
        assert set(item["by_pd_fraction"]) == {"0.0", "0.1", "0.3", "1.0"}
    # which network it judged: the `next` model trained on the noisy data, as saved
    judged = metrics["judged"]
    noisy = load_dataset("hexa-climb-smoke-noisy-v7")
    assert judged["dataset"] == metrics["trained_on"]
    assert judged["dataset_content_hash"] == noisy.content_hash
    assert (judged["split"], judged["variant"], judged["seed"]) == ("iid", "next", 0)
    saved = TrainedModel.load(folders[0] / BEST_DIR)
    assert judged["checkpoint_sha256"] == checkpoint_sha256(folders[0] / BEST_DIR / TENSORS)
    assert judged["steps"] == saved.steps == 20 and judged["stopped_by"] == saved.stopped_by
    assert judged["stop_reason"] == saved.stopped
    assert judged["open_loop_torque_rmse"] > 0.0


@pytest.mark.slow  # two or three runs with a closed loop each
def test_the_calibration_is_measured_once_per_output_folder(smoke_home, tmp_path):
    """Oracle, floor and the expert's references do not depend on the model: a second run
    in the same folder reads them back (cache keyed by dataset content, references and
    fractions) and reports the very same metrics."""
    from symbench.plugins.evaluators.closed_loop import CACHE_DIR

    def closed_loop(model: str) -> dict:
        spec = RunSpec(
            model=model,
            robot="hexa",
            preset="smoke",
            evaluators=("closed-loop",),
            output=tmp_path,
            progress=False,
            max_steps=10,
        )
        return run(spec).metrics["closed-loop"]

    first = closed_loop("sdnn")
    (folder,) = (tmp_path / CACHE_DIR).iterdir()
    assert (folder / "calibration.json").is_file()
    stamp = (folder / "calibration.json").stat().st_mtime_ns
    again = closed_loop("sdnn")
    assert again == first  # the cached calibration gives the same numbers
    other = closed_loop("ffnn")
    assert (folder / "calibration.json").stat().st_mtime_ns == stamp  # read, not measured
    assert len(list((tmp_path / CACHE_DIR).iterdir())) == 1
    for key in ("oracle_joint_rmse_rad", "floor_time_to_failure_s", "pd_floor_joint_rmse_rad"):
        assert other[key] == first[key]


@pytest.mark.slow  # a closed loop each (iid's, by default: test_closed_loop_evaluator_in_a_run)
@pytest.mark.parametrize("split", ("unseen-heading", "unseen-rotation"))
def test_closed_loop_on_the_held_out_splits(smoke_home, tmp_path, split):
    """Every split whose test climbs are held out gets its closed loop (iid: above)."""
    record = run(
        RunSpec(
            model="sdnn",
            robot="hexa",
            preset="smoke",
            split=split,
            evaluators=("closed-loop",),
            output=tmp_path,
            progress=False,
            max_steps=10,
        )
    )
    metrics = record.metrics["closed-loop"]
    assert metrics["references"] >= 1 and metrics["expert_success_rate"] == 1.0
    assert metrics["pd_oracle_success_rate"] == 1.0
    assert 0.0 <= metrics["pd_success_rate"] <= 1.0


def _dataset(scenarios):
    return SimpleNamespace(trajectory_ids=np.arange(len(scenarios)), scenarios=scenarios)


def test_references_come_from_distinct_orbits_in_id_order():
    s = [
        {"heading_deg": 0.0, "yaw_deg": 0.0, "direction": "forward"},  # 0
        {"heading_deg": 0.0, "yaw_deg": 60.0, "direction": "forward"},  # 1: image of 0 (C6)
        {"heading_deg": 180.0, "yaw_deg": 0.0, "direction": "forward"},  # 2: other heading
        {"heading_deg": 0.0, "yaw_deg": 30.0, "direction": "forward"},  # 3
        {"heading_deg": 0.0, "yaw_deg": 0.0, "direction": "left"},  # 4
        {"heading_deg": 0.0, "yaw_deg": 90.0, "direction": "forward"},  # 5: image of 3
    ]
    chosen = held_out_scenarios(_dataset(s), np.array([5, 4, 3, 2, 1, 0]), 6, 6)
    assert chosen == [s[0], s[3], s[4], s[2]]  # motions first, then another heading
    assert held_out_scenarios(_dataset(s), np.arange(6), 2, 6) == [s[0], s[3]]
    # without symmetry (order 1) every yaw is its own orbit
    assert len(held_out_scenarios(_dataset(s), np.arange(6), 6, 1)) == 6


def test_references_are_the_test_trajectories_by_id():
    # trajectory 1 failed in generation: ids are 0, 2, 3 at positions 0, 1, 2
    dataset = SimpleNamespace(
        trajectory_ids=np.array([0, 2, 3]),
        scenarios=({"yaw_deg": 0.0}, {"yaw_deg": 20.0}, {"yaw_deg": 30.0}),
    )
    assert held_out_scenarios(dataset, np.array([3, 2]), 2) == [
        {"yaw_deg": 20.0},
        {"yaw_deg": 30.0},
    ]


@pytest.mark.slow  # two or three runs with a closed loop each
def test_trainings_ahead_in_parallel_give_the_same_record(smoke_home, tmp_path):
    """With two workers the trainings the evaluators declare (generalization's splits, the
    closed loop's model on the noisy data) run beside the run's own, in other processes;
    every model, hence every metric, is the same bit for bit as trained one after another."""
    records, stages = {}, {}
    for workers in (1, 2):
        stages[workers] = []
        records[workers] = run(
            RunSpec(
                model="sdnn",
                robot="hexa",
                preset="smoke",
                evaluators=("torque-error", "generalization", "closed-loop"),
                output=tmp_path / f"workers-{workers}",
                workers=workers,
                progress=False,
                max_steps=20,
            ),
            stages[workers].append,
        )
    alone, together = records[1], records[2]
    noisy = "hexa-climb-smoke-noisy-v7 iid (next variant)"
    assert "training" in stages[1] and f"training on {noisy}" in stages[1]
    # the stages say that the models trained ahead are loaded, not trained again
    assert "training" not in stages[2] and not any(s.startswith("training on") for s in stages[2])
    assert "loading the model trained ahead" in stages[2]
    assert f"loading the model trained ahead on {noisy}" in stages[2]
    assert together.metrics == alone.metrics
    assert together.training.checkpoint_sha256 == alone.training.checkpoint_sha256
    assert "trained_ahead_wall_s" in together.timings_s
    assert "trained_ahead_wall_s" not in alone.timings_s
    # the four trainings (iid, unseen-heading, unseen-rotation, noisy iid next) ran ahead
    folders = sorted(
        p.relative_to(tmp_path / "workers-2").parts[3:]
        for p in (tmp_path / "workers-2" / "checkpoints").glob("**/resume.safetensors")
    )
    assert len(folders) == 4, folders


class _Renamed:
    """A dataset seen under another id: whose preset names the closed loop's data."""

    def __init__(self, dataset, did: str):
        self._dataset, self.id = dataset, did

    def __getattr__(self, name: str):
        return getattr(self._dataset, name)


@pytest.mark.parametrize(
    ("did", "variant", "trained_on"),
    [
        ("hexa-climb-smoke-v7", "acc", "hexa-climb-smoke-noisy-v7"),
        ("hexa-climb-smoke-v7", "next", "hexa-climb-smoke-noisy-v7"),
        ("hexa-climb-paper-v7", "acc", None),  # paper's closed loop trains on its own data
        ("hexa-climb-paper-v7", "next", "own"),  # ... and then judges the run's own model
    ],
)
def test_the_closed_loop_declares_its_training_where_its_preset_says(
    smoke_home, did, variant, trained_on
):
    from symbench.core.config.presets import preset
    from symbench.core.data import load_dataset
    from symbench.core.runs.evaluation import EvaluationContext
    from symbench.core.runs.planning import planned_trainings
    from symbench.core.runs.spec import model_entry
    from symbench.core.runs.trainings import TrainingJob

    def refuse(*_):
        raise AssertionError("planning only")

    spec = RunSpec(model="sdnn", robot="hexa", preset="smoke", variant=variant)
    dataset = _Renamed(load_dataset("hexa-climb-smoke-v7"), did)
    context = EvaluationContext(
        entry=model_entry(spec),
        dataset=dataset,
        preset=preset("smoke"),
        split="iid",
        seed=0,
        predict=refuse,
        test=None,
        test_trajectories=np.array([], dtype=np.int64),
        output_dir=smoke_home,
        retrain=refuse,
        retrain_on=refuse,
    )
    jobs = planned_trainings(context, ("torque-error", "closed-loop"))
    own = TrainingJob(None, "iid", variant)
    if trained_on == "own":
        assert jobs == [own]  # one training per run
    else:
        assert jobs == [own, TrainingJob(trained_on, "iid", "next")]
