"""The invariance evaluator: "by construction" where the model's view does not change under
the moves (leg-grouped), measured otherwise; its control (a tilt against gravity) must fail."""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

from symbench.core.config.presets import PRESETS, Evaluation
from symbench.core.data import load_dataset
from symbench.core.plugin import registry
from symbench.core.runs.evaluation import EvaluationContext
from symbench.plugins.evaluators import invariance
from symbench.testing.equivariance import model_predictors


@pytest.mark.parametrize(("name", "exact"), [("sdnn", True), ("ffnn", False), ("gnn", False)])
def test_by_construction_or_measured_with_its_control(smoke_hexa, name, exact):
    dataset = load_dataset(smoke_hexa.dataset_id)
    entry = registry.model(name, "torch")
    predict = model_predictors(entry, 6, dtypes=("float64",))["float64"]
    preset = dataclasses.replace(
        PRESETS["smoke"], evaluation=Evaluation(max_samples=40, invariance_trials=2)
    )
    context = EvaluationContext(
        entry=entry,
        dataset=dataset,
        preset=preset,
        split="iid",
        seed=0,
        predict=predict,
        test=None,
        test_trajectories=np.asarray(dataset.trajectory_ids),
        output_dir=None,
        retrain=None,
    )
    out = invariance.evaluate(context)
    assert out["by_construction"] is exact
    assert ("computed in the base frame" in out["reason"]) is exact
    assert out["control"]["failed_as_it_must"] and out["control"]["rel_change"] > 1e-3
    if exact:
        assert out["max_rel_change"] < 1e-10 and out["view_rel_change"] <= 1e-12
    else:
        assert out["max_rel_change"] > 1e-3 and out["view_rel_change"] > 1e-3
