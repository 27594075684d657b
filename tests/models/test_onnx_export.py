"""`symbench export`: every built-in torch model's ONNX file gives the model's torques at any
batch size, carries its description, and a file that would not is never written."""

from __future__ import annotations

import json

import numpy as np
import onnx
import pytest
from cli_invoke import error_line, invoke

from symbench.core.common.errors import SymbenchError
from symbench.core.data.views.model_dims import dims_for
from symbench.core.plugin import registry
from symbench.core.training import onnx_export
from symbench.core.training.backends import get_backend
from symbench.core.training.normalization import Normalizer
from symbench.core.training.onnx_export import (
    METADATA_KEY,
    onnx_bytes,
    onnx_predictor,
    parity_inputs,
    write_onnx,
)
from symbench.core.training.trained_model import TrainedModel

MODELS = ["sdnn", "sdgnn", "gnn", "ffnn", "ffnn-leg"]


def trained(name: str, backend: str = "torch", n_legs: int = 6) -> TrainedModel:
    """An initialized model with a random normalization, as training would leave one."""
    entry = registry.model(name, backend)
    dims = dims_for(entry.view, entry.variant, n_legs)
    params = get_backend(backend).init_params(entry, dims, {}, seed=0)
    normalizer = Normalizer.random(dims, np.random.default_rng(0))
    history = {"train_loss": [1.0], "val_loss": [0.5]}
    return TrainedModel(entry, dims, {}, normalizer, params, history, 0, {"seed": 0}, "done")


def test_an_export_of_fixed_batch_size_predicts_the_models_torques_at_that_size(tmp_path):
    model = trained("sdgnn")
    assert write_onnx(model, tmp_path / "model.onnx", batch=3)[1] == 258  # 256 rounded up
    predict = onnx_predictor((tmp_path / "model.onnx").read_bytes(), model.dims.keys)
    inputs = parity_inputs(model, 3)
    np.testing.assert_allclose(predict(inputs), model.predict(inputs), rtol=1e-4, atol=1e-5)
    with pytest.raises(
        SymbenchError, match=r"of shape \(3, .*a fixed batch of 3 rows\); got shape \(1, "
    ):
        predict({k: v[:1] for k, v in inputs.items()})


@pytest.mark.parametrize("name", MODELS)
def test_the_export_predicts_the_models_torques_at_any_batch_size(name, tmp_path):
    model = trained(name)
    write_onnx(model, tmp_path / "model.onnx")
    predict = onnx_predictor((tmp_path / "model.onnx").read_bytes(), model.dims.keys)
    for rows in (1, 7):
        inputs = {k: v[:rows] for k, v in parity_inputs(model, 7).items()}
        expected = model.predict(inputs)
        assert expected.shape == (rows, 6, 3)
        np.testing.assert_allclose(predict(inputs), expected, rtol=1e-4, atol=1e-5)


@pytest.mark.parametrize("name", MODELS)
def test_a_batch_1_export_predicts_the_models_torques(name, tmp_path):
    """A control loop's file (`--batch 1`), rewritten on rows where its graph allows: the
    model's torques all the same."""
    model = trained(name)
    write_onnx(model, tmp_path / "model.onnx", batch=1)
    predict = onnx_predictor((tmp_path / "model.onnx").read_bytes(), model.dims.keys)
    inputs = parity_inputs(model, 5)
    for row in range(5):
        one = {k: v[row : row + 1] for k, v in inputs.items()}
        np.testing.assert_allclose(predict(one), model.predict(one), rtol=1e-4, atol=1e-5)


def test_sdnns_batch_1_export_computes_on_rows():
    model = trained("sdnn")
    exported = onnx.load_from_string(
        onnx_bytes(model.entry, model.dims, {}, model.params, model.normalizer, batch=1)
    )
    ops = [node.op_type for node in exported.graph.node]
    assert ops[0] == ops[-1] == "Reshape" and ops.count("Reshape") == 2, ops


def test_sdnn_is_exported_with_its_normalization_folded_into_its_layers():
    model = trained("sdnn")
    exported = onnx.load_from_string(
        onnx_bytes(model.entry, model.dims, {}, model.params, model.normalizer)
    )
    ops = {node.op_type for node in exported.graph.node}
    assert not ops & {"Sub", "Div", "Mul"}, ops


def test_the_file_names_the_model_it_was_exported_from(tmp_path):
    model = trained("sdnn")
    write_onnx(model, tmp_path / "model.onnx")
    props = {p.key: p.value for p in onnx.load(tmp_path / "model.onnx").metadata_props}
    assert json.loads(props[METADATA_KEY]) == json.loads(json.dumps(model.describe()))


def test_an_export_that_differs_from_the_model_is_not_written(tmp_path, monkeypatch):
    """An exporter that got one weight wrong: the parity check refuses the file."""
    exact = onnx_export.onnx_bytes

    def wrong(entry, dims, hyper, params, normalizer, metadata=None, batch=None):
        params = {k: v + 0.5 if k == sorted(params)[0] else v for k, v in params.items()}
        return exact(entry, dims, hyper, params, normalizer, metadata, batch)

    monkeypatch.setattr(onnx_export, "onnx_bytes", wrong)
    with pytest.raises(SymbenchError, match="the ONNX export of sdnn differs from the model by"):
        write_onnx(trained("sdnn"), tmp_path / "model.onnx")
    assert list(tmp_path.iterdir()) == []


def test_a_jax_model_is_refused_in_one_line():
    model = trained("sdnn", "jax")
    with pytest.raises(SymbenchError, match="ONNX export takes a torch model; sdnn is a jax"):
        onnx_bytes(model.entry, model.dims, {}, model.params, model.normalizer)


def test_the_command_writes_a_saved_model_and_refuses_a_folder_without_one(tmp_path):
    trained("ffnn", n_legs=4).save(tmp_path / "best")
    result = invoke("export", tmp_path / "best", "--onnx", tmp_path / "ffnn.onnx")
    assert result.exit_code == 0, result.output
    assert "any number of rows per call" in result.stdout
    assert "largest |ONNX Runtime - model| over 256 rows" in (" ".join(result.stdout.split()))
    assert (tmp_path / "ffnn.onnx").stat().st_size > 0
    refused = error_line(invoke("export", tmp_path, "--onnx", tmp_path / "x.onnx"), 1)
    assert "holds no model.safetensors: give the folder of a saved model" in refused
