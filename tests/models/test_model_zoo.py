"""The built-in models: registered per backend, claims as documented, same networks in both."""

from __future__ import annotations

import numpy as np
import pytest
from model_sizes import BACKENDS, MODELS, SMALL

from symbench.core.data.views.model_dims import dims_for
from symbench.core.plugin import registry
from symbench.core.training.backends import get_backend

VIEWS = {
    "ffnn": "vector",
    "ffnn-leg": "leg_grouped",
    "gnn": "body_graph",
    "sdgnn": "leg_grouped",
    "sdnn": "leg_grouped",
}


@pytest.mark.parametrize("backend", BACKENDS)
@pytest.mark.parametrize("name", MODELS)
def test_entry_declares_view_claim_and_learning_rate(name, backend):
    entry = registry.model(name, backend)
    assert entry.view == VIEWS[name]
    assert entry.equivariant == (name in ("sdnn", "sdgnn"))
    # the rates `symbench tune` chose on hexa (leaderboards/tuning/README.md)
    tuned = {"sdnn": 1.5e-3, "ffnn": 3e-3, "gnn": 3e-3}
    assert entry.learning_rate == tuned.get(name, 1e-3)


@pytest.mark.parametrize("name", MODELS)
def test_both_backends_build_the_same_parameter_shapes(name):
    from symbench.core.training.backends.convert import torch_to_flax

    entry = registry.model(name, "torch")
    dims = dims_for(entry.view, entry.variant, 6)
    torch_params = get_backend("torch").init_params(entry, dims, SMALL[name], 0)
    jax_params = get_backend("jax").init_params(registry.model(name, "jax"), dims, SMALL[name], 0)
    converted = torch_to_flax(torch_params)
    assert {k: v.shape for k, v in converted.items()} == {k: v.shape for k, v in jax_params.items()}


def test_default_sizes_follow_the_paper():
    def shapes(name):
        entry = registry.model(name, "torch")
        params = get_backend("torch").init_params(
            entry, dims_for(entry.view, entry.variant, 6), {}, 0
        )
        return {k: v.shape for k, v in params.items()}

    ffnn = shapes("ffnn")
    assert [ffnn[f"body.linear{i}.weight"][0] for i in range(3)] == [256, 256, 256]
    assert "body.norm.weight" in ffnn and ffnn["out.weight"] == (18, 256)
    sdnn = shapes("sdnn")
    assert sdnn["enc.linear1.weight"] == (128, 128) and "enc.linear2.weight" not in sdnn
    assert sdnn["proc1.linear0.weight"] == (128, 256) and "proc2.linear0.weight" not in sdnn
    gnn, sdgnn = shapes("gnn"), shapes("sdgnn")
    for params, steps in ((gnn, 5), (sdgnn, 2)):
        assert params["graph.enc_edge.linear1.weight"][0] == 64
        assert params["graph.enc_node.linear1.weight"][0] == 16
        assert params["graph.enc_global.linear1.weight"][0] == 16
        assert (
            f"graph.edge{steps - 1}.norm.weight" in params
            and f"graph.edge{steps}.norm.weight" not in params
        )


@pytest.mark.parametrize("name", ["sdnn", "ffnn"])
def test_weights_copied_from_torch_give_the_same_outputs_in_jax(name):
    """Default sizes; the two backends compute the same function to 1e-5."""
    from symbench.core.training.backends.convert import torch_to_flax
    from symbench.core.training.normalization import Normalizer

    entry_t, entry_j = registry.model(name, "torch"), registry.model(name, "jax")
    dims = dims_for(entry_t.view, entry_t.variant, 6)
    rng = np.random.default_rng(3)
    params = {
        k: v + 0.05 * rng.standard_normal(v.shape).astype(np.float32)
        for k, v in get_backend("torch").init_params(entry_t, dims, {}, 0).items()
    }
    normalizer = Normalizer.random(dims, rng)
    x = {"x": rng.normal(size=(64, *dims.shape("x")))}
    y_torch = get_backend("torch").make_predictor(entry_t, dims, {}, params, normalizer)(x)
    y_jax = get_backend("jax").make_predictor(entry_j, dims, {}, torch_to_flax(params), normalizer)(
        x
    )
    assert np.abs(y_torch).max() > 0.1
    np.testing.assert_allclose(y_jax, y_torch, rtol=0, atol=1e-5 * np.abs(y_torch).max())
