"""Whatever `--size NAME=INT` and `--parameters` values a user types, `symbench run` refuses
them in one line before any work, or hands on a network that builds with no empty tensor, at
the parameter count asked within the matching tolerance: never an internal error."""

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


@given(data=st.data(), model=MODELS, parameters=PARAMETERS)
def test_sizes_and_parameter_counts_are_refused_or_build_what_was_asked(data, model, parameters):
    asked = [f"--size={s}" for s in data.draw(sizes(model))]
    asked += [] if parameters is None else [f"--parameters={parameters}"]
    with (
        tempfile.TemporaryDirectory() as scratch,
        contextlib.chdir(scratch),
        stand_in("symbench.core.runs.cli.run:run_spec") as run,
    ):
        result = invoke("run", "--model", model, "--robot", "hexa", "--preset", "smoke", *asked)
        if refusal(result) != "Error: reached":
            event("refused")
            return
    event("built")
    spec = run.call_args.args[0]
    entry = model_entry(spec)
    dims = dims_for(entry.view, entry.variant, 6)
    hyper = train_config(spec).hyper
    shapes = get_backend(entry.backend).parameter_shapes(entry, dims, hyper)
    assert all(0 not in shape for shape in shapes.values())
    assert set(dict(spec.sizes).items()) <= set(hyper.items())
    if parameters is not None and not spec.sizes:  # --size may change a matched width
        count = sum(math.prod(shape) for shape in shapes.values())
        assert abs(count - spec.parameters) <= MATCH_TOLERANCE * spec.parameters
