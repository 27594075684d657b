"""Checkpoints carry their content hash: a flipped byte or a truncated file is detected, and a
resumed training recovers to exactly the result of an uninterrupted one."""

from __future__ import annotations

import warnings
from pathlib import Path

import numpy as np
import pytest
from model_sizes import SMALL
from safetensors import safe_open
from safetensors.numpy import save_file

from symbench.core.config.protocols import Converge
from symbench.core.plugin import registry
from symbench.core.training.checkpoints import CheckpointError, checkpoint_sha256
from symbench.core.training.loop import TrainConfig, train
from symbench.core.training.resume import BEST_DIR, PREVIOUS, RESUME, CheckpointWarning
from symbench.core.training.trained_model import TENSORS, TrainedModel

WHOLE, FIRST = (
    TrainConfig(schedule=Converge(max_steps=n, eval_every=4), hyper=SMALL["sdnn"], progress=False)
    for n in (16, 8)
)
DAMAGED = "damaged (its content does not match its SHA-256)"


@pytest.fixture(scope="module")
def data(smoke):
    return tuple(s["leg_grouped"].take(np.arange(256)) for s in smoke)


@pytest.fixture(scope="module")
def whole(data) -> TrainedModel:
    """The uninterrupted run that every recovered run must reproduce."""
    model = train(registry.model("sdnn", "torch"), *data, WHOLE)
    assert len(model.history["val_loss"]) == 4  # so resumed runs train on after check 2
    return model


def data_start(raw: bytes) -> int:
    return 8 + int.from_bytes(raw[:8], "little")


def flip(path: Path) -> str:
    """Flip every bit of one byte in the middle of the tensor data; the reason reported."""
    raw = bytearray(path.read_bytes())
    raw[(data_start(raw) + len(raw)) // 2] ^= 0xFF
    path.write_bytes(bytes(raw))
    return DAMAGED


def truncate(path: Path) -> str:
    """Cut the file in the middle of its tensor data; the reason reported."""
    raw = path.read_bytes()
    start = data_start(raw)
    cut = (start + len(raw)) // 2
    path.write_bytes(raw[:cut])
    return f"truncated ({cut - start} of {len(raw) - start} data bytes)"


def assert_same_model(model: TrainedModel, expected: TrainedModel) -> None:
    assert model.history == expected.history and model.best_epoch == expected.best_epoch
    for key, value in expected.params.items():
        np.testing.assert_array_equal(model.params[key], value)
    assert model.sha256() == expected.sha256()


def resumed(data, folder: Path) -> tuple[TrainedModel, list[str]]:
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        model = train(registry.model("sdnn", "torch"), *data, WHOLE, folder)
    return model, [str(w.message) for w in caught if w.category is CheckpointWarning]


def test_checkpoint_sha256_is_the_hash_inside_the_file(data, whole, tmp_path):
    model = train(registry.model("sdnn", "torch"), *data, WHOLE, tmp_path)
    path = tmp_path / BEST_DIR / TENSORS
    with safe_open(path, framework="np") as f:
        stored = f.metadata()["sha256"]
    assert checkpoint_sha256(path) == stored == model.sha256() == whole.sha256()
    assert TrainedModel.load(tmp_path / BEST_DIR).sha256() == stored
    assert checkpoint_sha256(tmp_path / RESUME) != checkpoint_sha256(tmp_path / PREVIOUS)


@pytest.mark.parametrize("damage", [flip, truncate])
def test_damaged_checkpoint_is_refused_on_load(data, damage, tmp_path):
    train(registry.model("sdnn", "torch"), *data, FIRST, tmp_path)
    path = tmp_path / BEST_DIR / TENSORS
    reason = damage(path)
    with pytest.raises(CheckpointError) as error:
        TrainedModel.load(tmp_path / BEST_DIR)
    assert str(error.value) == f"checkpoint {path} is {reason}"
    with pytest.raises(CheckpointError):
        checkpoint_sha256(path)


def test_checkpoint_without_hash_is_refused(tmp_path):
    path = tmp_path / "old.safetensors"
    save_file({"params/w": np.zeros(3, np.float32)}, path, {"symbench": "{}"})
    with pytest.raises(CheckpointError) as error:
        checkpoint_sha256(path)
    assert str(error.value) == (
        f"checkpoint {path} carries no content hash (damaged, or "
        "written before checkpoints were hashed)"
    )


@pytest.mark.parametrize("damage", [flip, truncate])
@pytest.mark.parametrize("target", ["best", "resume"])
def test_resumed_run_recovers_from_a_damaged_checkpoint(data, whole, target, damage, tmp_path):
    first = train(registry.model("sdnn", "torch"), *data, FIRST, tmp_path)
    assert len(first.history["val_loss"]) == 2
    path = tmp_path / (RESUME if target == "resume" else f"{BEST_DIR}/{TENSORS}")
    reason = damage(path)
    model, warned = resumed(data, tmp_path)
    then = (
        f"deleted it, falling back to {tmp_path / PREVIOUS}"
        if target == "resume"
        else "rewriting it from the resume checkpoint"
    )
    assert warned == [f"checkpoint {path} is {reason}; {then}"]
    assert_same_model(model, whole)
    assert checkpoint_sha256(tmp_path / BEST_DIR / TENSORS) == whole.sha256()


def test_run_retrains_from_scratch_when_no_resume_checkpoint_is_good(data, whole, tmp_path):
    train(registry.model("sdnn", "torch"), *data, FIRST, tmp_path)
    reasons = [flip(tmp_path / RESUME), truncate(tmp_path / PREVIOUS)]
    model, warned = resumed(data, tmp_path)
    assert warned == [
        f"checkpoint {tmp_path / RESUME} is {reasons[0]}; deleted it, falling back to "
        f"{tmp_path / PREVIOUS}",
        f"checkpoint {tmp_path / PREVIOUS} is {reasons[1]}; deleted it, training from scratch",
    ]
    assert_same_model(model, whole)
    assert checkpoint_sha256(tmp_path / BEST_DIR / TENSORS) == whole.sha256()


@pytest.mark.parametrize("config", [FIRST, WHOLE], ids=["unfinished", "finished"])
def test_resume_checkpoint_alone_carries_a_training(data, whole, config, tmp_path):
    """What leaderboards/sweeps/keep-trainings.sh carries to the next machine: a training's
    resume checkpoint without best/ or the previous one resumes to the uninterrupted result,
    and a finished one is loaded as it is."""
    train(registry.model("sdnn", "torch"), *data, config, tmp_path)
    carried = (tmp_path / RESUME).stat().st_mtime_ns
    (tmp_path / PREVIOUS).unlink()
    for part in (tmp_path / BEST_DIR).iterdir():
        part.unlink()
    (tmp_path / BEST_DIR).rmdir()
    model, warned = resumed(data, tmp_path)
    best = tmp_path / BEST_DIR / TENSORS
    assert warned == [f"checkpoint {best} does not exist; rewriting it from the resume checkpoint"]
    assert_same_model(model, whole)
    assert checkpoint_sha256(best) == whole.sha256()
    if config is WHOLE:
        assert (tmp_path / RESUME).stat().st_mtime_ns == carried  # loaded, not trained again
