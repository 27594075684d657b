"""The generalization-gap evaluator reads a held-out split's error against its size-matched
iid control, trained with the same seed on as many climbs."""

from __future__ import annotations

from types import SimpleNamespace

import pytest

from symbench.core.data import load_dataset
from symbench.core.runs.runner import run
from symbench.core.runs.spec import RunSpec
from symbench.plugins.evaluators import generalization_gap


def test_a_held_out_split_records_its_error_over_its_controls(smoke_home, tmp_path):
    spec = RunSpec(
        "sdnn",
        "hexa",
        split="unseen-rotation",
        preset="smoke",
        max_steps=10,
        evaluators=("torque-error", "generalization-gap"),
        output=tmp_path,
        workers=1,
        progress=False,
    )
    record = run(spec)
    gap = record.metrics["generalization-gap"]
    assert gap["control"] == "control-rotation"
    assert gap["rmse"] == record.metrics["torque-error"]["rmse"]  # the run's own model
    assert gap["gap"] == pytest.approx(gap["rmse"] / gap["control_rmse"], rel=1e-12)
    assert gap["control_rmse"] != gap["rmse"]  # another training, on other climbs
    dataset = load_dataset("hexa-climb-smoke-v7")
    own, control = (dataset.split_indices(s, 0) for s in ("unseen-rotation", "control-rotation"))
    assert (len(own.train), len(own.test)) == (len(control.train), len(control.test))


def test_a_split_without_a_control_says_so():
    context = SimpleNamespace(split="iid")
    assert generalization_gap.evaluate(context) == {
        "skipped": "split iid has no size-matched control"
    }
    assert generalization_gap.trainings(context) == []
