"""The plugin's own tests, written with symbench's kit."""

from __future__ import annotations

import pytest

from symbench import Converge, TrainConfig, model_entry, train
from symbench.testing import synthetic_views

BACKENDS = ("torch", "jax")


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
