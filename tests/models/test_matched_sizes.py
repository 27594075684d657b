"""Models compared at matched size: the width keywords scaled to a parameter count."""

from __future__ import annotations

import dataclasses

import pytest

from symbench.core.common.errors import SymbenchError
from symbench.core.data.views.model_dims import dims_for
from symbench.core.plugin import registry
from symbench.core.runs.run_config import train_config
from symbench.core.runs.spec import RunSpec
from symbench.core.training import sizes
from symbench.core.training.sizes import matched_widths, parameter_count, scaled_widths

MODELS = ("ffnn", "ffnn-leg", "gnn", "sdgnn", "sdnn")


@pytest.mark.parametrize("target", [20_000, 80_000])
@pytest.mark.parametrize("name", MODELS)
def test_every_built_in_model_reaches_a_parameter_count_within_ten_percent(name, target):
    """Ten percent: a width step moves a small graph network's count by about five."""
    entry = registry.model(name, "torch")
    dims = dims_for(entry.view, entry.variant, 6)
    hyper = matched_widths(entry, dims, target)
    assert set(hyper) == set(entry.widths)
    count = parameter_count(entry, dims, hyper)
    assert abs(count - target) / target < 0.1, (hyper, count)
    # and it is the nearest of its neighbours on the first width
    first = entry.widths[0]
    for step in (-1, 1):
        scale = (hyper[first] + step) / scaled_widths(entry, 1.0)[first]
        other = parameter_count(entry, dims, scaled_widths(entry, scale))
        assert abs(other - target) >= abs(count - target)


def test_the_run_trains_the_matched_size_and_the_other_models_keep_their_defaults():
    spec = RunSpec(model="sdnn", robot="hexa", parameters=50_000, progress=False)
    assert train_config(spec).hyper == {"latent": 72}
    assert train_config(dataclasses.replace(spec, parameters=None)).hyper == {}


def test_a_model_without_widths_or_an_unreachable_count_is_refused(monkeypatch):
    entry = registry.model("sdnn", "torch")
    dims = dims_for(entry.view, entry.variant, 6)
    with pytest.raises(SymbenchError, match="declares no widths"):
        matched_widths(dataclasses.replace(entry, widths=()), dims, 1000)
    monkeypatch.setattr(sizes, "MAX_SCALE", 2)  # a smaller ceiling, so no huge net is built
    with pytest.raises(SymbenchError, match="stays below 10000000 parameters at 2 x"):
        matched_widths(entry, dims, 10**7)
