"""Stand-ins shared by the evaluator tests: trained models and datasets that cost nothing."""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np

from symbench.core.common.arrays import ViewArrays
from symbench.core.runs.evaluation import TrainedOnSplit


def trained_on_split(split: str, variant: str) -> TrainedOnSplit:
    """A 'model' of six legs predicting zero torques, with a two-sample test set of ones."""
    test = ViewArrays(
        "leg_grouped",
        variant,
        6,
        {"x": np.zeros((2, 6, 1))},
        np.ones((2, 6, 3)),
        np.zeros(2, dtype=np.int64),
    )
    return TrainedOnSplit(split, variant, lambda inputs: np.zeros((2, 6, 3)), test)


def closed_loop_dataset(scenarios: list[dict], dataset_id: str | None = None) -> SimpleNamespace:
    """What the closed-loop evaluator reads of a dataset: hexa's gains and no symmetry to
    sort references by, one trajectory per scenario."""
    return SimpleNamespace(
        id=dataset_id,
        spec=SimpleNamespace(
            control=SimpleNamespace(kp=20.0, kd=3.0, timestep=0.001),
            group=SimpleNamespace(rotation_order=1),
            spec_hash=lambda: "spec",
        ),
        content_hash="content",
        frames=None,
        trajectory_ids=np.arange(len(scenarios)),
        scenarios=scenarios,
    )


def tracked_to_the_end(scenario) -> SimpleNamespace:
    """What `track` returns for a stand-in model that holds on over the whole climb."""
    return SimpleNamespace(
        attached=True,
        time_to_failure_s=scenario.seconds,
        steps=int(round(scenario.seconds / 0.001)),
        joint_rmse_rad=0.0,
        base_drift_m=0.0,
        base_drift_deg=0.0,
        failure=None,
        tracking_cost=0.0,
    )


def without_open_loop(monkeypatch) -> None:
    """The closed loop's open-loop error skipped (0 per reference): a stand-in dataset has
    no rows to build the model's view from."""
    monkeypatch.setattr(
        "symbench.core.runs.closed_loop.ClosedLoopSetup.open_loop_rmse",
        lambda self, predict, view, references: [0.0] * len(references),
    )
