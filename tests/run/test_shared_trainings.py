"""Runs of one output folder share a training on another split of their dataset: the run
that asks first trains it where the run of that split keeps its own, and the other finds
it finished (the board's sweep trains each split once per seed, not once per evaluator)."""

from __future__ import annotations

from dataclasses import replace

from symbench.core.data import load_dataset
from symbench.core.runs.runner import run
from symbench.core.runs.spec import RunSpec, checkpoint_root
from symbench.core.runs.trained_models import trained_model
from symbench.core.training.trained_model import TENSORS


def test_a_retraining_is_the_run_of_that_split_and_is_trained_once(smoke_home, tmp_path):
    held_out = RunSpec(
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
    first = run(held_out)
    content_hash = load_dataset(held_out.dataset_id).content_hash
    control = replace(held_out, split="control-rotation", evaluators=("torque-error",))
    shared = checkpoint_root(tmp_path, control.key(), content_hash) / "control-rotation__acc"
    # where the control's own run keeps it, not under the asking run's key
    assert (shared / "best" / TENSORS).is_file()
    own = checkpoint_root(tmp_path, held_out.key(), content_hash)
    assert sorted(p.name for p in own.iterdir() if p.is_dir()) == ["unseen-rotation__acc"]
    written = (shared / "best" / TENSORS).stat().st_mtime_ns

    second = run(control)
    assert (shared / "best" / TENSORS).stat().st_mtime_ns == written  # loaded, not trained
    gap = first.metrics["generalization-gap"]
    assert second.metrics["torque-error"]["rmse"] == gap["control_rmse"]
    found = trained_model(tmp_path, first, "control-rotation", "acc")
    assert found.folder == shared / "best"
