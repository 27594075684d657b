"""The trained model as the climbing robot's inverse-dynamics controller, in simulation.

For the first held-out test scenarios (as many as the preset says) the expert (the
whole-body controller) first climbs for the preset's horizon, giving reference trajectories
(`symbench presets` shows both numbers). The same architecture trained on the `next`
variant then drives the robot alone, and again with a small PD term added. Reported per
mode: success rate (stayed attached), mean time to failure and joint tracking RMSE.
"""

from __future__ import annotations

import numpy as np

from symbench import EvaluationContext

NAME = "closed-loop"
DESCRIPTION = (
    "learned model as the controller tracking held-out climbs over the preset's horizon "
    "(alone and with small PD)"
)
PD_FRACTION = 0.1  # the small PD term: a tenth of the robot's servo gains


def evaluate(context: EvaluationContext) -> dict:
    from symbench import Scenario, build_view, simulate, track

    trained = context.on_split(context.split, "next")
    frames, entry = context.dataset.frames, context.entry
    pair = np.zeros(2, dtype=np.int64)

    def policy(rows: dict[str, np.ndarray]) -> np.ndarray:
        inputs = build_view(rows, pair, frames, entry.view, "next").inputs
        return trained.predict(inputs)[0]

    budget = context.preset.closed_loop
    seconds = budget.seconds
    control = context.robot.control
    gains = {"model": (0.0, 0.0), "model+pd": (PD_FRACTION * control.kp, PD_FRACTION * control.kd)}
    runs: dict[str, list] = {mode: [] for mode in gains}
    references = 0
    for fields in held_out_scenarios(context.dataset, context.test_trajectories, budget.scenarios):
        scenario = Scenario.from_dict({**fields, "seconds": seconds})
        reference = simulate(scenario)
        if not reference.attached:  # the expert itself fell: no reference to track
            continue
        references += 1
        for mode, pd in gains.items():
            runs[mode].append(track(scenario, reference.arrays, policy, pd))
    out: dict = {
        "references": references,
        "horizon_s": seconds,
        "pd_gains": list(gains["model+pd"]),
    }
    for mode, results in runs.items():
        prefix = "" if mode == "model" else "pd_"
        out.update({prefix + k: v for k, v in _summary(results).items()})
    return out


def held_out_scenarios(dataset, test_ids: np.ndarray, n: int) -> list[dict]:
    """The scenarios of the first n test trajectories, looked up by trajectory id (ids skip
    the trajectories that failed in generation, so they are not positions)."""
    by_id = dict(zip(np.asarray(dataset.trajectory_ids).tolist(), dataset.scenarios))
    return [by_id[int(i)] for i in test_ids[:n]]


def _summary(results: list) -> dict:
    def mean(values: list[float]) -> float:
        return float(np.mean(values)) if values else float("nan")

    return {
        "success_rate": mean([r.attached for r in results]),
        "time_to_failure_s": mean([r.time_to_failure_s for r in results]),
        "joint_rmse_rad": mean([r.joint_rmse_rad for r in results]),
        "failures": [r.failure for r in results if r.failure],
    }
