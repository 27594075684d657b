"""`symbench check-equivariance`: tables or JSON, and a non-zero exit for a broken claim."""

from __future__ import annotations

import json
import re

import broken_models
import pytest
from cli_invoke import error_line
from click.testing import CliRunner

from symbench.core.cli import cli
from symbench.core.plugin import registry
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
    assert result.exit_code == 0, result.output
    title, *lines = result.output.splitlines()
    assert title.startswith("ffnn-leg/torch on C6 (6 legs): not equivariant (claims none): ")
    assert "measured max error" in " ".join(result.output.split())
    table = lines[: next(i for i, line in enumerate(lines) if line.startswith("controls"))]
    rows = [[cell.strip() for cell in line.split("│")[1:-1]] for line in table]
    rows = [row for row in rows if row]
    assert [row[0] for row in rows] == ["identity", *(f"shift {k}" for k in range(1, 6))]
    assert rows[0][1] == "(0, 1, 2, 3, 4, 5)" and float(rows[0][2]) < 1e-14
    assert rows[5][1] == "(5, 0, 1, 2, 3, 4)"
    assert all(float(error) > 1e-3 for row in rows[1:] for error in row[2:])  # measured
    assert " ".join(result.output.split()).count("fails, as it must") == 14  # a half turn: 2


def test_unknown_model_names_the_closest():
    result = invoke("--model", "sdn", "--robot", "hexa")
    known = ", ".join(sorted({entry.name for entry in registry.collect("models").values()}))
    assert error_line(result, 1) == (
        f"Error: unknown model 'sdn'; did you mean sdnn, sdgnn? (known: {known})"
    )


@pytest.fixture
def host_with_broken_model():
    host = PluginHost()
    host.load_entry_points()
    host.register(broken_models, "broken")
    set_host(host)
    yield
    set_host(None)


def test_broken_claim_exits_non_zero(host_with_broken_model):
    """The verdict line names the element furthest over its tolerance (shifts 2 and 4 of this
    model break it equally, up to the last bit: either may be named, never a lesser one)."""
    args = ("--model", "broken-sdnn", "--robot", "hexa", "--backend", "torch")
    result = invoke(*args)
    assert result.exit_code == 1, result.output
    verdict = (
        r"broken-sdnn/torch on C6 \(6 legs\): BROKEN: claims equivariance and breaks it under "
        r"(shift \d) \(legs -> \[[\d, ]+\]\): float64 error (\d\.\d\de-\d\d) > 1e-10; "
        "4 more elements break it"
    )
    named = re.fullmatch(verdict, result.output.splitlines()[0])
    assert named, result.output.splitlines()[0]
    (report,) = json.loads(invoke(*args, "--json").output)
    errors = {e["element"]: e["float64"] for e in report["elements"]}
    assert errors[named[1]] == pytest.approx(max(errors.values()), rel=1e-12)
    assert f"{errors[named[1]]:.2e}" == named[2]


def test_json_has_the_controls_and_the_model_group():
    result = invoke(
        "--model", "sdnn", "--robot", "hexa", "--backend", "torch", "--group-of-model", "--json"
    )
    assert result.exit_code == 0, result.output
    (report,) = json.loads(result.output)
    assert report["equivariant"] and len(report["controls"]) == 14
    assert all(c["failed_as_it_must"] and c["float64"] > 1e-3 for c in report["controls"])
    group = report["symmetry_group"]
    assert group["measured_order"] == 720 and group["over_constrained"] and group["legs_alike"]


def test_the_model_group_is_printed():
    result = invoke("--model", "ffnn", "--robot", "magneto", "--backend", "jax", "--group-of-model")
    assert result.exit_code == 0, result.output
    assert " ".join(result.output.split()).endswith(
        "ffnn/jax symmetry group (24 permutations tested, vector view relabelled): "
        "trivial: the identity only; breaks the robot group C2 (order 2)"
    )


def test_a_size_that_cannot_build_the_model_is_refused_in_one_line():
    """Before: latent=0 ended in "internal error: ZeroDivisionError" (JAX's initializer)."""
    result = invoke("--model", "sdnn", "--robot", "hexa", "--size", "latent=0")
    assert error_line(result, 1) == (
        "Error: --size latent=0: a width of model sdnn/jax is at least 1; nearest buildable: "
        "latent=1"
    )
