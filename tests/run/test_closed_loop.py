"""Closed-loop control: the tracking loop tells a good controller from a useless one."""

from __future__ import annotations

import re

import numpy as np
import pytest

from symbench.core.runs.runner import RunSpec, run
from symbench.core.sim.learned_control import track
from symbench.core.sim.rollout import simulate
from symbench.core.sim.scenario import Scenario

PD = (2.0, 0.3)  # a tenth of hexa's servo gains, as the evaluator uses


@pytest.fixture(scope="module")
def wall_reference():
    scenario = Scenario(robot="hexa", inclination_deg=90.0, seconds=2.0)
    reference = simulate(scenario)
    assert reference.attached
    return scenario, reference.arrays


def test_expert_torques_with_small_pd_track_the_reference(wall_reference):
    scenario, ref = wall_reference

    def replay(rows):  # the torque the expert applied at the start of this period
        k = int(np.argmin(np.abs(ref["t"] - rows["t"][1]))) - 1
        return ref["tau"][k]

    result = track(scenario, ref, replay, PD)
    assert result.attached and result.failure is None
    assert result.time_to_failure_s == pytest.approx(ref["t"][-2])  # the whole horizon
    assert result.joint_rmse_rad < 0.02


def test_zero_torque_falls_off_the_wall(wall_reference):
    scenario, ref = wall_reference
    result = track(scenario, ref, lambda rows: np.zeros((6, 3)), PD)
    assert not result.attached
    assert re.fullmatch(
        r"stance foot of leg\(s\) \d(, \d)* left the surface"
        r"|base tilted more than 30 degrees from the surface normal",
        result.failure,
    ), result.failure
    assert result.time_to_failure_s < ref["t"][-1]


def test_closed_loop_evaluator_in_a_run(smoke_home, tmp_path):
    record = run(
        RunSpec(
            model="sdnn",
            robot="hexa",
            preset="smoke",
            evaluators=("closed-loop",),
            output=tmp_path,
            progress=False,
            max_epochs=2,
        )
    )
    metrics = record.metrics["closed-loop"]
    assert metrics["references"] >= 1 and metrics["horizon_s"] == 0.3
    for prefix in ("", "pd_"):
        assert 0.0 <= metrics[f"{prefix}success_rate"] <= 1.0
        assert 0.0 < metrics[f"{prefix}time_to_failure_s"] <= metrics["horizon_s"]
        assert metrics[f"{prefix}joint_rmse_rad"] >= 0.0


def test_references_are_the_test_trajectories_by_id():
    from types import SimpleNamespace

    from symbench.plugins.evaluators.closed_loop import held_out_scenarios

    # trajectory 1 failed in generation: ids are 0, 2, 3 at positions 0, 1, 2
    dataset = SimpleNamespace(
        trajectory_ids=np.array([0, 2, 3]),
        scenarios=({"yaw_deg": 0.0}, {"yaw_deg": 20.0}, {"yaw_deg": 30.0}),
    )
    assert held_out_scenarios(dataset, np.array([3, 2]), 2) == [
        {"yaw_deg": 30.0},
        {"yaw_deg": 20.0},
    ]
