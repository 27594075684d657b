"""Whatever `--size NAME=INT` and `--parameters` values a user types, `symbench run` and
`symbench sweep` (and `check-equivariance`, which takes `--size`) refuse them in one line
before any work, or hand on networks that build with no empty tensor, at the parameter count
asked within the matching tolerance: never an internal error."""

from __future__ import annotations

import contextlib
import math
import tempfile

from cli_invoke import invoke, refusal
from hypothesis import event, given
from hypothesis import strategies as st
from test_cli_properties import NUMBERS, stand_in

from symbench.core.data.views.model_dims import dims_for
from symbench.core.runs.run_config import train_config
from symbench.core.runs.spec import model_entry
from symbench.core.training.backends import get_backend
from symbench.core.training.sizes import MATCH_TOLERANCE

MODELS = st.sampled_from(["sdnn", "ffnn", "gnn"])
KEYWORDS = {  # each model's build keywords, and one of another model's
    "sdnn": ["latent", "steps", "mlp_layers", "ring", "mirror", "width"],
    "ffnn": ["width", "layers", "latent"],
    "gnn": ["edge", "node", "glob", "mlp_layers", "steps", "latent"],
}
# small values build in milliseconds; huge ones are refused before anything is built; shapes
# are checked without allocating, so a network of gigabytes within the bound costs nothing
VALUES = st.integers(-3, 40) | st.integers(-20, 300) | st.integers(-(2**70), 2**70)


def sizes(model: str) -> st.SearchStrategy:
    """`--size` values for `model`: mostly its keywords with small values, some any text."""
    keyword = st.sampled_from(KEYWORDS[model])
    return st.lists(
        st.tuples(keyword, VALUES.map(str)).map("=".join)
        | st.tuples(keyword | st.text(max_size=6), NUMBERS).map("=".join)
        | st.text(max_size=8),
        max_size=2,
    )


PARAMETERS = st.none() | st.integers(-5, 300_000).map(str) | NUMBERS


def assert_built_as_asked(spec) -> None:
    """`spec`'s network builds with no empty tensor, with the sizes given by hand, and at
    the parameter count asked (when no size changes its widths) within the tolerance."""
    entry = model_entry(spec)
    dims = dims_for(entry.view, entry.variant, 6)
    hyper = train_config(spec).hyper
    shapes = get_backend(entry.backend).parameter_shapes(entry, dims, hyper)
    assert all(0 not in shape for shape in shapes.values())
    assert set(dict(spec.sizes).items()) <= set(hyper.items())
    if spec.parameters is not None and not spec.sizes:  # --size may change a matched width
        count = sum(math.prod(shape) for shape in shapes.values())
        assert abs(count - spec.parameters) <= MATCH_TOLERANCE * spec.parameters


def options(data, model: str, parameters: str | None) -> list[str]:
    asked = [f"--size={s}" for s in data.draw(sizes(model))]
    return asked + ([] if parameters is None else [f"--parameters={parameters}"])


@given(data=st.data(), model=MODELS, parameters=PARAMETERS)
def test_sizes_and_parameter_counts_are_refused_or_build_what_was_asked(data, model, parameters):
    with (
        tempfile.TemporaryDirectory() as scratch,
        contextlib.chdir(scratch),
        stand_in("symbench.core.runs.cli.run:run_spec") as run,
    ):
        result = invoke(
            "run", "--model", model, "--robot", "hexa", "--preset", "smoke",
            *options(data, model, parameters),
        )  # fmt: skip
        if refusal(result) != "Error: reached":
            event("refused")
            return
    event("built")
    assert_built_as_asked(run.call_args.args[0])


@given(data=st.data(), models=st.lists(MODELS, min_size=1, max_size=2, unique=True),
       parameters=PARAMETERS)  # fmt: skip
def test_a_sweep_refuses_sizes_one_of_its_models_cannot_build_or_builds_them_all(
    data, models, parameters
):
    with (
        tempfile.TemporaryDirectory() as scratch,
        contextlib.chdir(scratch),
        stand_in("symbench.core.runs.sweep:sweep") as sweep,
    ):
        result = invoke(
            "sweep", f"--models={','.join(models)}", "--robots=hexa", "--preset=smoke",
            "--seeds=0", *options(data, models[0], parameters),
        )  # fmt: skip
        if refusal(result) != "Error: reached":
            event("refused")
            return
    event("built")
    specs = sweep.call_args.args[0]
    assert sorted(spec.model for spec in specs) == sorted(models)
    for spec in specs:
        assert_built_as_asked(spec)


@given(data=st.data(), model=MODELS, backend=st.sampled_from(["torch", "jax"]))
def test_check_equivariance_refuses_a_size_it_cannot_build_or_checks_that_network(
    data, model, backend
):
    with stand_in("symbench.testing.cli:check_model") as check:
        result = invoke(
            "check-equivariance", "--model", model, "--robot", "hexa", "--backend", backend,
            *(f"--size={s}" for s in data.draw(sizes(model))),
        )  # fmt: skip
        if refusal(result) != "Error: reached":
            event("refused")
            return
    event("built")
    entry, hyper = check.call_args.args[0], check.call_args.kwargs["hyper"]
    dims = dims_for(entry.view, entry.variant, 6)
    shapes = get_backend(entry.backend).parameter_shapes(entry, dims, hyper)
    assert all(0 not in shape for shape in shapes.values())
