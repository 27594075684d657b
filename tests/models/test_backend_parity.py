"""Every built-in model computes the same function in torch and in JAX, at default sizes.

For each built-in model and each built-in robot's leg count, both backends build the network
with their own defaults (no hyperparameters given), the torch weights are perturbed (so that
no LayerNorm is the identity and a scale/bias mix-up would show) and copied into the JAX
network, and both run on the same synthetic inputs. A default that differed between the
backends shows up as different parameter shapes; a difference in what they compute, as
outputs more than 1e-5 apart (float32, outputs of order one).
"""

from __future__ import annotations

import numpy as np
import pytest

from symbench.core.data.views.model_dims import dims_for
from symbench.core.plugin import registry
from symbench.core.plugin.host import get_host
from symbench.core.training.backends.convert import torch_to_flax
from symbench.testing import BUILTIN_ROBOTS, robot_group, synthetic_views

ATOL = 1e-5
BUILTIN_MODELS = sorted(
    {
        reg.entry.name
        for reg in registry.registrations("models")
        if get_host().info[reg.plugin].builtin
    }
)
LEGS = sorted({robot_group(robot).n_legs for robot in BUILTIN_ROBOTS})


def torch_and_jax_outputs(name: str, n_legs: int, **hyper) -> tuple[np.ndarray, np.ndarray]:
    """Outputs of the torch network and of its JAX twin holding the same weights."""
    import jax
    import torch
    from flax import traverse_util

    entry_t, entry_j = registry.model(name, "torch"), registry.model(name, "jax")
    dims = dims_for(entry_t.view, entry_t.variant, n_legs)
    inputs = {
        k: v.astype(np.float32)
        for k, v in synthetic_views(n_legs, 32, seed=n_legs)[entry_t.view].inputs.items()
    }

    torch.manual_seed(0)
    net_t = entry_t.build(dims, **hyper).eval()
    rng = np.random.default_rng(n_legs)
    params = {
        k: v.numpy() + 0.05 * rng.standard_normal(v.shape).astype(np.float32)
        for k, v in net_t.state_dict().items()
    }
    net_t.load_state_dict({k: torch.from_numpy(v) for k, v in params.items()})
    with torch.no_grad():
        y_torch = net_t(**{k: torch.from_numpy(v) for k, v in inputs.items()}).numpy()

    net_j = entry_j.build(dims, **hyper)
    converted = torch_to_flax(params)
    expected = jax.eval_shape(net_j.init, jax.random.PRNGKey(0), **inputs)["params"]
    expected_shapes = {k: v.shape for k, v in traverse_util.flatten_dict(expected, sep="/").items()}
    assert {k: v.shape for k, v in converted.items()} == expected_shapes, (
        f"{name}: the backends' default networks differ in parameters"
    )
    tree = traverse_util.unflatten_dict(converted, sep="/")
    y_jax = np.asarray(jax.jit(net_j.apply)({"params": tree}, **inputs))
    return y_torch, y_jax


def test_every_builtin_model_is_checked():
    assert {"ffnn", "ffnn-leg", "gnn", "sdgnn", "sdnn"} <= set(BUILTIN_MODELS)
    assert LEGS == [4, 6, 9]


@pytest.mark.parametrize("n_legs", LEGS)
@pytest.mark.parametrize("name", BUILTIN_MODELS)
def test_torch_weights_give_the_same_outputs_in_jax(name, n_legs):
    y_torch, y_jax = torch_and_jax_outputs(name, n_legs)
    assert y_torch.shape == y_jax.shape == (32, n_legs, 3)
    assert np.abs(y_torch).max() > 0.1  # not a vanishing output that any network matches
    np.testing.assert_allclose(y_jax, y_torch, rtol=0, atol=ATOL)


@pytest.mark.parametrize("name", ["sdnn", "sdgnn"])
def test_the_mirror_averaged_twins_agree(name):
    """`mirror=1` (equivariant to the robot's mirrors too) computes the same in both."""
    y_torch, y_jax = torch_and_jax_outputs(name, 6, mirror=1)
    plain, _ = torch_and_jax_outputs(name, 6)
    assert np.abs(y_torch - plain).max() > 1e-3  # the average is another function
    np.testing.assert_allclose(y_jax, y_torch, rtol=0, atol=ATOL)


def test_the_ring_twins_agree():
    """`ring=1` (each leg also sees its neighbours) computes the same in both."""
    y_torch, y_jax = torch_and_jax_outputs("sdnn", 6, ring=1)
    assert np.abs(y_torch).max() > 0.1
    np.testing.assert_allclose(y_jax, y_torch, rtol=0, atol=ATOL)
