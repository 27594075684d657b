"""Whatever `--learning-rates` and `--width-scales` a user gives `symbench tune`, the search
refuses them in one line before any work, or trains exactly its grid (then at most
MAX_EXTENSIONS rates past its edge), each trial at the widths its scale gives: never an
internal error. Training is a stand-in whose loss is known, so a search takes a fraction of
a second."""

from __future__ import annotations

import contextlib
import json
import math
import re
import tempfile
from pathlib import Path
from types import SimpleNamespace
from unittest import mock

import pytest
from cli_invoke import invoke, refusal
from hypothesis import event, given, settings
from hypothesis import strategies as st
from sandbox import fresh_home
from synthetic_raw import fake_simulate
from test_cli_properties import NUMBERS

from symbench.core.data.generation.generate import generate
from symbench.core.plugin import registry
from symbench.core.runs import tune as tuning
from symbench.core.training import loop
from symbench.core.training.sizes import scaled_widths

# rates and scales a search takes, mostly; at the edges of what it takes and past them, or any
# number the command line reads, in one example of five
RATES = st.sampled_from(["1e-3", "3e-3", "0.5", "0.99", "1e-9"]) | st.floats(1e-9, 0.99).map(repr)
ODD_RATES = st.sampled_from(["1", "1e-12", "5e-324", "0.999999999"]) | st.floats(1e-12, 2).map(repr)
SCALES = st.sampled_from(["0.5", "1", "2", "0.001", "64"]) | st.floats(1e-3, 64).map(repr)
ODD_SCALES = st.sampled_from(["65", "1000", "1e-4", "64.0000001"]) | st.floats(1e-4, 100).map(repr)


def values(valid: st.SearchStrategy, odd: st.SearchStrategy) -> st.SearchStrategy:
    """A comma-separated list of at most 3 `valid` values, one of them `odd` or any text
    in one example of five."""
    listed = st.lists(valid, min_size=1, max_size=3).map(",".join)
    other = st.lists(valid | odd | NUMBERS, min_size=1, max_size=3).map(",".join)
    return st.integers(0, 4).flatmap(lambda i: listed if i else other)


@pytest.fixture(scope="module")
def smoke_home(tmp_path_factory):
    """A home holding hexa's smoke dataset, made by the stand-in simulator."""
    with fresh_home() as home:
        generate("hexa", "smoke", simulator=fake_simulate, show_progress=False)
        yield home


def train(entry, train_set, val_set, config, checkpoint_dir=None):
    """A loss smallest at rate 3e-3, known at once."""
    loss = math.log(config.learning_rate / 3e-3) ** 2
    return SimpleNamespace(n_params=1, history={"val_loss": [loss]}, steps=1, stopped_by="x")


@settings(max_examples=settings.default.max_examples // 2)  # a valid grid runs a tuning
@given(
    model=st.sampled_from(["sdnn", "gnn"]),
    rates=values(RATES, ODD_RATES),
    scales=values(SCALES, ODD_SCALES),
)
def test_tune_grids_are_refused_in_one_line_or_searched_as_given(smoke_home, model, rates, scales):
    with (
        tempfile.TemporaryDirectory() as scratch,
        contextlib.chdir(scratch),
        fresh_home(),
        mock.patch.dict("os.environ", {"SYMBENCH_HOME": str(smoke_home)}),
        mock.patch.object(loop, "train", train),
    ):
        result = invoke(
            "tune", "--model", model, "--robot", "hexa", "--preset", "smoke",
            f"--learning-rates={rates}", f"--width-scales={scales}", "--output", "out",
        )  # fmt: skip
        if result.exit_code != 0:
            line = refusal(result)
            option = re.match(r"Error: (learning rates|--width-scales|Invalid value for '--)", line)
            assert option, line
            event(f"refused: {option.group(1)}")
            return
        (path,) = Path("out").glob("*.tune.json")
        summary = json.loads(path.read_text())
    event("searched")
    entry = registry.model(model, "torch")
    listed = [[float(v) for v in text.split(",") if v.strip()] for text in (rates, scales)]
    grid = {(r, s) for r in listed[0] for s in listed[1]}  # as the command line reads them
    assert {(g["learning_rate"], g["width_scale"]) for g in summary["grid"]} == grid
    trained = {(t["learning_rate"], t["width_scale"]) for t in summary["trials"]}
    assert grid <= trained and len(trained - grid) <= tuning.MAX_EXTENSIONS
    assert summary["complete"]
    for trial in summary["trials"]:
        assert trial["hyper"] == scaled_widths(entry, trial["width_scale"])
        assert 0 < trial["learning_rate"] < 1
