"""The torch predictor runs a TorchScript trace only where the trace is faithful, and in pieces
of PREDICT_ROWS rows that change no prediction."""

from __future__ import annotations

import numpy as np
import pytest
import torch

from symbench.core.data.views.model_dims import dims_of
from symbench.core.plugin.entries import ModelEntry
from symbench.core.training.backends import get_backend
from symbench.core.training.normalization import Normalizer
from symbench.testing.synthetic import synthetic_views


class SignBranching(torch.nn.Module):
    """Data-dependent control flow: a trace would freeze whichever branch it saw."""

    def __init__(self, n_legs: int):
        super().__init__()
        self.n_legs = n_legs
        self.scale = torch.nn.Parameter(torch.ones(()))

    def forward(self, x: torch.Tensor) -> torch.Tensor:
        y = x[..., :3] * self.scale
        return y if bool(x.sum() > 0) else -y


def test_predictor_matches_eager_on_data_dependent_branches(smoke):
    data = smoke[0]["leg_grouped"]
    dims = dims_of(data)
    entry = ModelEntry(
        "branching", "torch", "leg_grouped", "acc", False, lambda d: SignBranching(d.n_legs)
    )
    backend = get_backend("torch")
    normalizer = Normalizer.fit(data)
    predict = backend.make_predictor(entry, dims, {}, {"scale": np.ones(())}, normalizer)
    for sign in (1.0, -1.0):
        x = {
            "x": normalizer.stats["x"][0]
            + sign * normalizer.stats["x"][1] * np.ones((2, *dims.shape("x")))
        }
        z = torch.from_numpy(normalizer.normalize("x", x["x"]).astype(np.float32))
        with torch.no_grad():
            eager = SignBranching(dims.n_legs)(z).numpy()
        expected = normalizer.denormalize_target(eager.astype(np.float64))
        np.testing.assert_allclose(predict(x), expected, rtol=1e-6, atol=1e-6)


def test_traced_predictor_equals_eager_bitwise_at_any_batch_size(smoke):
    from symbench.core.plugin import registry
    from symbench.core.training.backends.torch_backend import Normalized, build_network

    data = smoke[0]["leg_grouped"]
    dims = dims_of(data)
    entry = registry.model("sdnn", "torch")
    backend = get_backend("torch")
    params = backend.init_params(entry, dims, {"latent": 16}, 0)
    normalizer = Normalizer.fit(data)
    predict = backend.make_predictor(entry, dims, {"latent": 16}, params, normalizer)
    eager = Normalized(
        build_network(entry, dims, {"latent": 16}, params), normalizer, dims.keys
    ).float()
    for n in (1, 7):
        x = data.inputs["x"][:n].astype(np.float32)
        with torch.no_grad():
            expected = eager(torch.from_numpy(x)).numpy().astype(np.float64)
        np.testing.assert_array_equal(predict({"x": x}), expected)


MODELS = ["ffnn", "ffnn-leg", "gnn", "sdgnn", "sdnn"]


def _pieces_and_whole(name, figure, monkeypatch):
    """`figure(entry, dims, params, view)` with the network run on PREDICT_ROWS rows at a
    time, then on every row in one call: 3 000 rows of a hexa-like robot, 12 pieces, the last
    a short one of 184 rows."""
    from symbench.core.plugin import registry
    from symbench.core.training.backends import torch_backend

    entry = registry.model(name, "torch")
    view = synthetic_views(6, 3000, seed=3)[entry.view]
    dims = dims_of(view)
    params = get_backend("torch").init_params(entry, dims, {}, 0)
    pieces = figure(entry, dims, params, view)
    monkeypatch.setattr(torch_backend, "PREDICT_ROWS", 10**9)
    return pieces, figure(entry, dims, params, view)


@pytest.mark.parametrize("dtype", [np.float32, np.float64])
@pytest.mark.parametrize("name", MODELS)
def test_predictions_in_pieces_equal_one_call_bitwise(name, dtype, monkeypatch):
    """Predictions run the network on PREDICT_ROWS rows at a time for speed; each row must
    come out as it does from one call of every row (a network or kernel whose rows depended
    on the call's size would fail), laid out in memory alike: downstream sums run in memory
    order."""

    def predictions(entry, dims, params, view):
        backend = get_backend("torch")
        predict = backend.make_predictor(entry, dims, {}, params, Normalizer.fit(view), dtype)
        return predict(view.inputs)

    pieces, whole = _pieces_and_whole(name, predictions, monkeypatch)
    np.testing.assert_array_equal(pieces, whole)
    assert pieces.strides == whole.strides


@pytest.mark.parametrize("name", MODELS)
def test_validation_loss_in_pieces_equals_one_call_bitwise(name, monkeypatch):
    """The validation loss runs the network in pieces too; with the pieces joined row-major
    (not as one call's output is laid out), gnn's loss on 3 000 rows differed in its last
    bit, and with it the checkpoint a run keeps."""

    def loss(entry, dims, params, view):
        trainer = get_backend("torch").make_trainer(entry, dims, {}, params, 1e-3)
        trainer.set_data(view.inputs, view.target, view.inputs, view.target)
        return trainer.val_loss()

    pieces, whole = _pieces_and_whole(name, loss, monkeypatch)
    assert pieces == whole
