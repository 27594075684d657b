"""`symbench bench models`: FLOP counts that add up, and a report with every figure."""

from __future__ import annotations

import json

import pytest
import torch
from click.testing import CliRunner

from symbench.core.bench.flops import step_flops_per_sample
from symbench.core.cli import build_cli
from symbench.core.data.views.model_dims import dims_for
from symbench.core.plugin import registry
from symbench.core.training.backends.torch_backend import build_network

BATCH = 8


def test_torch_flops_of_an_mlp_are_its_matmuls_forward_and_backward():
    """Each Linear layer: 2io forward, 2io for its weight gradient, 2io for its input's
    gradient except the first layer's (the data needs none): per sample."""
    entry = registry.model("ffnn", "torch")
    dims = dims_for(entry.view, entry.variant, 6)
    layers = [m for m in build_network(entry, dims, {}).modules() if isinstance(m, torch.nn.Linear)]
    expected = sum(6 * m.in_features * m.out_features for m in layers)
    expected -= 2 * layers[0].in_features * layers[0].out_features
    assert step_flops_per_sample(entry, dims, BATCH) == expected


@pytest.mark.parametrize("name", ["ffnn", "sdnn"])
def test_both_backends_count_nearly_the_same_flops(name):
    """XLA also counts elementwise operations; the matmuls dominate, so within 10%."""
    torch_entry, jax_entry = registry.model(name, "torch"), registry.model(name, "jax")
    dims = dims_for(torch_entry.view, torch_entry.variant, 6)
    by_torch = step_flops_per_sample(torch_entry, dims, BATCH)
    by_jax = step_flops_per_sample(jax_entry, dims, BATCH)
    assert by_torch > 0 and abs(by_jax - by_torch) / by_torch < 0.1


def test_the_report_has_rates_and_the_fraction_of_the_matmul_limit():
    args = ["bench", "models", "--models", "ffnn", "--seconds", "0.05", "--json"]
    result = CliRunner().invoke(build_cli(), args)
    assert result.exit_code == 0, result.output
    report = json.loads(result.stdout)
    assert [(r["model"], r["backend"]) for r in report["rows"]] == [
        ("ffnn", "torch"),
        ("ffnn", "jax"),
    ]
    for row in report["rows"]:
        mode = row["train_best"]
        assert mode == ("plain" if row["backend"] == "torch" else "compiled")
        rate = row[f"train_samples_per_s_{mode}"]
        assert row["train_flops_per_s"] == pytest.approx(rate * row["train_flops_per_sample"])
        fraction = row["train_flops_per_s"] / row["matmul_flops_per_s"]
        assert row["train_matmul_fraction"] == pytest.approx(fraction) and 0 < fraction < 2
    assert "[2/2] ffnn/jax: training, compiled" in result.stderr
