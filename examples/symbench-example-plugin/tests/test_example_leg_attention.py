"""The plugin's own tests, written with symbench's kit."""

from __future__ import annotations

import numpy as np
import pytest

from symbench import Converge, ModelDims, ModelEntry, TrainConfig, model_entry, schema, train
from symbench.testing import assert_equivariant, check_model, synthetic_views

BACKENDS = ("torch", "jax")
HEXA = ModelDims("leg_grouped", "acc", 6, (("x", (6, schema.leg_grouped_input("acc").size)),))


@pytest.mark.parametrize("backend", BACKENDS)
def test_leg_attention_is_equivariant_on_every_builtin_robot(
    symbench_kit, symbench_groups, backend
):
    entry = model_entry("leg-attention", backend)  # found through the entry point
    for group in symbench_groups.values():
        report = symbench_kit.assert_equivariant(entry, group)
        assert report.max_error("float64") <= 1e-10


@pytest.mark.parametrize("backend", BACKENDS)
def test_leg_attention_learns(backend):
    entry = model_entry("leg-attention", backend)
    tr, va = synthetic_views(6, 512, seed=0), synthetic_views(6, 128, seed=1)
    model = train(
        entry,
        tr["leg_grouped"],
        va["leg_grouped"],
        TrainConfig(
            schedule=Converge(max_steps=32, eval_every=8), hyper={"latent": 16}, progress=False
        ),
    )
    assert min(model.history["val_loss"][1:]) < model.history["val_loss"][0]


def test_the_flax_model_builds_a_flax_module_of_the_views_shape():
    import flax.linen as nn
    import jax

    module = model_entry("leg-attention", "jax").build(HEXA, latent=8, heads=2)
    assert isinstance(module, nn.Module)
    x = synthetic_views(6, 5, seed=0)["leg_grouped"].inputs["x"]
    variables = module.init(jax.random.PRNGKey(0), x)
    assert np.asarray(module.apply(variables, x)).shape == (5, 6, 3)


def with_leg_positions(dims: ModelDims, latent: int = 16, heads: int = 4):
    """The Flax leg attention with a learned embedding per leg added to its inputs:
    positional encodings tell the legs apart, so relabelling them no longer relabels the
    torques. The mistake the kit must catch in a model that claims equivariance."""
    import flax.linen as nn

    from symbench_example_plugin.leg_attention_flax import LegAttention

    class PositionedLegAttention(nn.Module):
        @nn.compact
        def __call__(self, x):
            legs = self.param("legs", nn.initializers.normal(1.0), x.shape[-2:])
            return LegAttention(latent, heads)(x + legs)

    return PositionedLegAttention()


def test_a_flax_model_that_tells_legs_apart_fails_the_kit():
    wrong = ModelEntry(
        "leg-attention-positions", "jax", "leg_grouped", "acc", True, with_leg_positions
    )
    report = check_model(wrong, "hexa", n_samples=8)
    assert report.claims and not report.equivariant and not report.passed
    assert report.max_error("float64") > 1e-2  # not rounding: the symmetry is gone
    with pytest.raises(AssertionError, match="equivariance broken") as failure:
        assert_equivariant(wrong, "hexa", n_samples=8)
    assert "BROKEN: claims equivariance and breaks it under shift" in str(failure.value)
