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


@pytest.mark.parametrize("dtype", [np.float32, np.float64])
@pytest.mark.parametrize("name", ["ffnn", "ffnn-leg", "gnn", "sdgnn", "sdnn"])
def test_predictions_in_pieces_equal_one_call_bitwise(name, dtype, monkeypatch):
    """Predictions and the validation loss run the network on PREDICT_ROWS rows at a time
    for speed; each row must come out as it does from one call of every row (a network or
    kernel whose rows depended on the call's size would fail), the last piece a short one,
    and laid out in memory alike: sums run in memory order (with the pieces joined row-major,
    gnn's validation loss on 3 000 rows differed in its last bit)."""
    from symbench.core.plugin import registry
    from symbench.core.training.backends import torch_backend

    data = synthetic_views(6, 3000, seed=3)  # 12 pieces, the last of 184 rows
    entry = registry.model(name, "torch")
    view = data[entry.view]
    dims = dims_of(view)
    backend = get_backend("torch")
    params = backend.init_params(entry, dims, {}, 0)
    normalizer = Normalizer.fit(view)

    def figures() -> tuple[np.ndarray, float]:
        predict = backend.make_predictor(entry, dims, {}, params, normalizer, dtype)
        trainer = backend.make_trainer(entry, dims, {}, params, 1e-3)
        trainer.set_data(view.inputs, view.target, view.inputs, view.target)
        return predict(view.inputs), trainer.val_loss()

    pieces = figures()
    monkeypatch.setattr(torch_backend, "PREDICT_ROWS", 10**9)
    whole = figures()
    np.testing.assert_array_equal(pieces[0], whole[0])
    assert pieces[0].strides == whole[0].strides
    assert pieces[1] == whole[1]
