"""Inputs that used to give a wrong result without a word now give a clear error."""

from __future__ import annotations

import dataclasses
import json

import numpy as np
import pytest
from bad_plugins import SHAPES, misshaped
from cli_invoke import error_line, invoke
from synthetic_raw import write_logs

from symbench.core.common.errors import SymbenchError
from symbench.core.config.protocols import Converge
from symbench.core.data import load_dataset
from symbench.core.data.importing.importer import import_logs
from symbench.core.data.storage.files import sha256_bytes
from symbench.core.data.storage.metadata import METADATA, content_hash
from symbench.core.runs import runner
from symbench.core.runs.cli import run as run_command
from symbench.core.runs.runner import RunSpec
from symbench.core.training.loop import TrainConfig, train
from symbench.core.training.normalization import Normalizer
from symbench.testing import synthetic_views


def test_a_file_listed_twice_in_import_json_is_refused(home, tmp_path):
    folder = write_logs(tmp_path / "logs")
    manifest = json.loads((folder / "import.json").read_text())
    files = ["run0.npz", "run1.npz", "run2.npz", "./run0.npz"]
    manifest["trajectories"] = [{"file": f} for f in files]
    (folder / "import.json").write_text(json.dumps(manifest))
    with pytest.raises(SymbenchError, match=r"\./run0.npz is listed twice \(also as run0.npz\)"):
        import_logs(folder, "twice")
    assert not (home / "datasets" / "twice").exists()


def test_values_beyond_float32_are_refused_not_recorded_as_null(home, tmp_path):
    folder = write_logs(tmp_path / "logs")
    with np.load(folder / "run3.npz") as npz:
        raw = dict(npz)
    raw["tau"] = raw["tau"] * 1e300
    np.savez(folder / "run3.npz", **raw)
    with pytest.raises(
        SymbenchError, match=r"run3.npz: column 'tau' holds .*e\+300 at step 0, beyond float32"
    ):
        import_logs(folder, "huge")
    train_set = synthetic_views(4, 64)["leg_grouped"]
    huge = dataclasses.replace(train_set, target=train_set.target * 1e300)
    with pytest.raises(SymbenchError, match="training data 'target' is too large to normalize"):
        Normalizer.fit(huge)  # data imported before the check: refused before training


@pytest.mark.parametrize("backend", ["torch", "jax"])
@pytest.mark.parametrize("shape", SHAPES)
def test_a_model_whose_torques_are_misshaped_is_named_in_training(backend, shape):
    views, val = synthetic_views(4, 128, seed=0), synthetic_views(4, 64, seed=1)
    entry = misshaped(shape, backend)
    with pytest.raises(
        SymbenchError,
        match=rf"model {shape}-net/{backend} returned torques "
        r"shaped \((\d+, 4, 1|\d+, 12)\), expected \(\d+, 4, 3\)",
    ):
        train(
            entry,
            views["leg_grouped"],
            val["leg_grouped"],
            TrainConfig(schedule=Converge(max_steps=1), progress=False),
        )


@pytest.mark.parametrize(
    "option, field, protocol",
    [("--max-steps", "max_steps", "converge"), ("--max-epochs", "max_epochs", "paper")],
)
def test_a_zero_budget_is_refused_not_the_presets(monkeypatch, tmp_path, option, field, protocol):
    def never(*args, **kwargs):
        raise AssertionError("the run started")

    monkeypatch.setattr(run_command, "run_spec", never)
    monkeypatch.setattr(runner, "ensure_dataset", never)
    command = ("run", "--model", "sdnn", "--robot", "hexa", "--protocol", protocol)
    message = error_line(invoke(*command, option, "0", "--output", tmp_path), 2)
    assert f"Invalid value for '{option}': 0 is not in the range x>=1" in message
    spec = RunSpec(model="sdnn", robot="hexa", protocol=protocol, output=tmp_path)
    with pytest.raises(SymbenchError, match=f"TrainConfig.{field} must be at least 1, got 0"):
        runner.run(dataclasses.replace(spec, **{field: 0}))


def test_rehashed_metadata_whose_step_count_disagrees_with_the_files_is_refused(smoke_hexa):
    path = smoke_hexa.root / METADATA
    meta = json.loads(path.read_text())
    meta["trajectories"][1]["n_steps"] -= 40  # as if 40 steps were never recorded
    meta["n_samples"] -= 40
    meta["content_hash"] = content_hash(meta)
    path.write_text(json.dumps(meta))
    file = meta["trajectories"][1]["file"]
    steps = meta["trajectories"][1]["n_steps"]
    with pytest.raises(
        SymbenchError, match=rf"{file} holds {steps + 40} steps, metadata.json says {steps}"
    ):
        load_dataset(smoke_hexa.dataset_id)


def test_rehashed_metadata_of_a_file_whose_column_name_is_no_utf8_names_the_file(smoke_hexa):
    """Before: "internal error: UnicodeDecodeError" from counting the file's steps, which
    decodes the footer's column names (found by the property suite: one byte of a cached
    trajectory changed and its digest written into metadata.json)."""
    path = smoke_hexa.root / METADATA
    meta = json.loads(path.read_text())
    record = meta["trajectories"][0]
    file = smoke_hexa.root / record["file"]
    original = file.read_bytes()
    content = original.replace(b"tau.leg3.femur", b"tau.leg3.\x80emur")
    assert content != original  # the footer names its columns
    file.write_bytes(content)
    record["sha256"] = sha256_bytes(content)
    meta["content_hash"] = content_hash(meta)
    path.write_text(json.dumps(meta))
    result = invoke("data", "info", smoke_hexa.dataset_id, "--no-overlap")
    assert error_line(result, 1) == (
        f"Error: {file}: not a readable Parquet file ('utf-8' codec can't decode byte 0x80 in "
        "position 9: invalid start byte)"
    )
