"""The JAX predictor and validation loss run the network on PREDICT_ROWS rows at a time: a
longer call as pieces of exactly that size, the last one padded, so that a row comes out the
same whatever the length of the call it is in."""

from __future__ import annotations

import numpy as np
import pytest

from symbench.core.data.views.model_dims import dims_of
from symbench.core.plugin import registry
from symbench.core.training.backends import get_backend, jax_backend
from symbench.core.training.normalization import Normalizer
from symbench.testing.synthetic import synthetic_views

PIECE = 16  # rows: small, so that a few dozen rows make several pieces and compile fast
# the graph networks compile for long on 2 cores (tests/models/test_jax_few_rows.py)
MODELS = [
    "ffnn",
    "sdnn",
    pytest.param("ffnn-leg", marks=pytest.mark.slow),
    pytest.param("sdgnn", marks=pytest.mark.slow),
    pytest.param("gnn", marks=pytest.mark.slow),
]


def _predictor(name, dtype, monkeypatch):
    monkeypatch.setattr(jax_backend, "PREDICT_ROWS", PIECE)
    entry = registry.model(name, "jax")
    view = synthetic_views(6, 5 * PIECE, seed=3)[entry.view]
    dims = dims_of(view)
    backend = get_backend("jax")
    params = backend.init_params(entry, dims, {}, 0)
    return backend.make_predictor(entry, dims, {}, params, Normalizer.fit(view), dtype), view


@pytest.mark.parametrize("dtype", [np.float32, np.float64])
@pytest.mark.parametrize("name", MODELS)
def test_a_row_comes_out_the_same_in_any_call_longer_than_a_piece(name, dtype, monkeypatch):
    """Every evaluator calls the predictor with its own number of rows (the test set, each
    group element's image of it, the closed loop's references): each row must not depend on
    that number, nor on the rows padding the last piece. Rows 0-39 are 2.5 pieces of a 40-row
    call (the third padded with copies of row 39) and the first 2.5 of an 80-row call's 5."""
    predict, view = _predictor(name, dtype, monkeypatch)
    short = predict({k: v[: 5 * PIECE // 2] for k, v in view.inputs.items()})
    long = predict(view.inputs)
    assert short.shape == (5 * PIECE // 2, *long.shape[1:]) and short.dtype == np.float64
    np.testing.assert_array_equal(short, long[: len(short)])


def test_a_call_of_one_piece_or_less_runs_at_its_own_size(monkeypatch):
    """A control loop's batch-1 call is not padded to a piece (that would multiply its cost
    by PREDICT_ROWS); it predicts what the same row predicts in a batch, to rounding
    (tests/models/test_jax_few_rows.py), and a call of exactly one piece is one call."""
    calls: list[list[int]] = []  # per call, the rows each piece runs (padding included)
    pieces = jax_backend._pieces

    def counted(xs):
        out = pieces(xs)
        calls.append([len(arrays[0]) for _, arrays in out])
        return out

    monkeypatch.setattr(jax_backend, "_pieces", counted)
    predict, view = _predictor("sdnn", np.float32, monkeypatch)
    for rows in (1, PIECE, PIECE + 1, 5 * PIECE):
        out = predict({k: v[:rows] for k, v in view.inputs.items()})
        assert out.shape[0] == rows
    assert calls == [[1], [PIECE], [PIECE, PIECE], [PIECE] * 5]


def test_the_validation_loss_is_the_mean_of_every_rows_squared_error(monkeypatch):
    """The validation loss sums the squared errors of each piece (the last one's padding
    weighted 0) and divides by every value's count: it equals the mean squared error of the
    network's normalized predictions over all rows, within float32 rounding."""
    monkeypatch.setattr(jax_backend, "PREDICT_ROWS", PIECE)
    entry = registry.model("ffnn", "jax")
    view = synthetic_views(6, 5 * PIECE // 2, seed=4)[entry.view]
    dims = dims_of(view)
    backend = get_backend("jax")
    params = backend.init_params(entry, dims, {}, 0)
    trainer = backend.make_trainer(entry, dims, {}, params, 1e-3)
    trainer.set_data(view.inputs, view.target, view.inputs, view.target)
    identity = Normalizer({k: (np.zeros(1), np.ones(1)) for k in [*dims.keys, "target"]})
    predict = backend.make_predictor(entry, dims, {}, params, identity, np.float64)
    expected = float(np.mean((predict(view.inputs) - view.target) ** 2))
    assert trainer.val_loss() == pytest.approx(expected, rel=1e-5)
