"""`symbench check-equivariance`: tables or JSON, and a non-zero exit for a broken claim."""

from __future__ import annotations

import json

import broken_models
import pytest
from click.testing import CliRunner

from symbench.core.cli import cli
from symbench.core.plugin.host import PluginHost, set_host


def invoke(*args: str):
    return CliRunner().invoke(cli, ["check-equivariance", *args])


def test_sdnn_passes_in_both_backends_as_json():
    result = invoke("--model", "sdnn", "--robot", "magneto", "--json")
    assert result.exit_code == 0, result.output
    reports = json.loads(result.output)
    assert {r["backend"] for r in reports} == {"torch", "jax"}
    assert all(r["equivariant"] and len(r["elements"]) == 2 for r in reports)


def test_non_claiming_model_is_reported_without_failing():
    result = invoke("--model", "ffnn-leg", "--robot", "hexa", "--backend", "torch")
    assert result.exit_code == 0 and "not equivariant (claims none)" in result.output
    assert "shift 5" in result.output


def test_unknown_model_names_the_closest():
    result = invoke("--model", "sdn", "--robot", "hexa")
    assert result.exit_code != 0 and "did you mean sdnn" in result.output


@pytest.fixture
def host_with_broken_model():
    host = PluginHost()
    host.load_entry_points()
    host.register(broken_models, "broken")
    set_host(host)
    yield
    set_host(None)


def test_broken_claim_exits_non_zero(host_with_broken_model):
    result = invoke("--model", "broken-sdnn", "--robot", "hexa", "--backend", "torch")
    assert result.exit_code == 1 and "BROKEN" in result.output
