"""Builders shared by all tests."""

from __future__ import annotations

import pytest

from symbench.core.data.presets import dataset_id
from symbench.core.provenance import hardware, library_versions

HASH = "ab" * 32


def record_dict(robot: str = "hexa", split: str = "iid", model: str = "sdnn",
                backend: str = "torch", seed: int = 0, rmse: float = 0.1,
                content_hash: str = HASH) -> dict:
    """A complete, valid (unsealed: `write_record` seals it) result record with the given
    identity and RMSE."""
    return {
        "schema_version": 2,
        "created": "2026-11-22T00:00:00Z",
        "model": {"name": model, "backend": backend, "view": "leg_grouped", "variant": "acc",
                  "equivariant": True, "hyperparameters": {"latent": 128},
                  "learning_rate": 5e-4, "parameters": 1234,
                  "plugin": {"module": "symbench.plugins.torch_models.sdnn",
                             "distribution": "symbench", "version": "0.1.0",
                             "source_sha256": "12" * 32}},
        "robot": robot,
        "dataset": {"id": dataset_id(robot, "smoke"), "content_hash": content_hash,
                    "robot_spec_hash": "cd" * 32, "preset": "smoke"},
        "split": split,
        "seed": seed,
        "samples": {"train": 10, "val": 2, "test": 3, "train_trajectories": 2,
                    "val_trajectories": 1, "test_trajectories": 1},
        "training": {"epochs": 3, "best_epoch": 2, "stopped_early": False,
                     "best_val_loss": 0.5, "batch_size": 64,
                     "config": {"seed": seed, "batch_size": 64, "max_epochs": 3,
                                "stop_ratio": 0.7, "stop_patience": 5, "learning_rate": 5e-4,
                                "hyper": {}, "compile": False},
                     "checkpoint_sha256": {"model.safetensors": "34" * 32}},
        "metrics": {"torque-error": {"rmse": rmse, "nrmse": rmse / 2}},
        "timings_s": {"train": 1.0},
        "hardware": hardware(),
        "versions": library_versions(),
        "git_commit": "0" * 40,
    }


@pytest.fixture
def make_record():
    return record_dict


def schema_1(record: dict) -> dict:
    """The record as schema 1 wrote it: unsealed, without provenance."""
    record["schema_version"] = 1
    del record["model"]["plugin"]
    for field in ("config", "checkpoint_sha256"):
        del record["training"][field]
    return record


@pytest.fixture
def as_schema_1():
    return schema_1
