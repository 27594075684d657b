"""Whatever `--split-by`, `--train` and `--test` a user types, `symbench data info` and
`symbench run` refuse them in one line, or split by exactly the values asked: every
trajectory on a side takes one of that side's values (angles modulo 360), and the sides are
disjoint. Never an internal error."""

from __future__ import annotations

import contextlib
import json
import os
import tempfile

import pytest
from cli_invoke import invoke, refusal
from hypothesis import event, given
from hypothesis import strategies as st
from sandbox import fresh_home
from synthetic_raw import fake_simulate
from test_cli_properties import NUMBERS, stand_in

from symbench.core.data.generation.generate import generate
from symbench.core.data.splits import COLUMNS, check_split, column_split


def mostly(valid: st.SearchStrategy, anything: st.SearchStrategy) -> st.SearchStrategy:
    """`valid` in about four examples of five, `anything` in the fifth: Hypothesis otherwise
    spends most examples on the richer strategy, which the first check refuses."""
    return st.integers(0, 4).flatmap(lambda i: valid if i else anything)


COLUMN = mostly(st.sampled_from(list(COLUMNS)), st.sampled_from(["heading_deg", ""]) | st.text())
# values near those the smoke dataset holds (headings 0 and 180, yaws 0, 180 and 250,
# inclination 90, direction forward, seeds from 0), as the command line writes them
NEAR = {
    "heading": ["0", "180", "540", "90"],
    "yaw": ["0", "180", "250", "m110"],
    "inclination": ["90", "90.0", "45"],
    "direction": ["forward", "left"],
    "seed": ["0", "1", "2", "3", "4"],
}
ANY_VALUES = st.lists(
    st.sampled_from([v for values in NEAR.values() for v in values]) | NUMBERS, max_size=3
).map(",".join)


@st.composite
def split_values(draw: st.DrawFn, column: str) -> tuple[str, str]:
    """--train and --test for `column`: mostly its own values, the sides apart; else any."""
    near = NEAR.get(column)
    if near is None or not draw(st.integers(0, 4)):
        return draw(ANY_VALUES), draw(ANY_VALUES)
    train = draw(st.lists(st.sampled_from(near), min_size=1, max_size=2, unique=True))
    rest = [v for v in near if v not in train] or near
    test = draw(st.lists(st.sampled_from(rest), min_size=1, max_size=2, unique=True))
    return ",".join(train), ",".join(test)


@pytest.fixture(scope="module")
def smoke_home():
    """A home holding hexa's smoke dataset, made by the stand-in simulator."""
    with fresh_home() as home:
        generate("hexa", "smoke", simulator=fake_simulate, show_progress=False)
        yield home


@contextlib.contextmanager
def in_home(home):
    before = os.environ["SYMBENCH_HOME"]
    os.environ["SYMBENCH_HOME"] = str(home)
    try:
        yield
    finally:
        os.environ["SYMBENCH_HOME"] = before


def listed(text: str) -> list[str]:
    """A comma-separated list as the command line reads it (`CommaList`)."""
    return [v.strip() for v in text.split(",") if v.strip()]


def same(value, token: str, field: str) -> bool:
    """Whether a trajectory's `value` of scenario `field` is the command line's `token`."""
    if field == "direction":
        return value == token
    difference = value - float(token.replace("m", "-"))
    if field in ("heading_deg", "yaw_deg"):
        difference = (difference + 180.0) % 360.0 - 180.0
    return abs(difference) < 1e-6


@given(column=COLUMN, data=st.data())
def test_data_info_splits_by_exactly_the_values_asked_or_refuses(smoke_home, column, data):
    train, test = data.draw(split_values(column))
    with fresh_home(), in_home(smoke_home):
        result = invoke(
            "data", "info", "hexa-climb-smoke-v7", "--no-overlap", "--json",
            f"--split-by={column}", f"--train={train}", f"--test={test}",
        )  # fmt: skip
    if result.exit_code != 0:
        event("refused")
        refusal(result)
        return
    split = column_split(column, listed(train), listed(test))
    counts = json.loads(result.stdout)["splits"][split.name]
    if "error" in counts:  # the dataset lacks a value: one line, naming the dataset
        event("refused by the dataset")
        assert counts["error"].startswith("dataset hexa-climb-smoke-v7") and "\n" not in counts
        return
    event("split")
    field = COLUMNS[column]
    assert counts["disjoint"]
    for side, tokens in (("train", split.train), ("test", split.test)):
        values = counts.get(side, {}).get("scenarios", {}).get(field, [])
        assert all(any(same(v, t, field) for t in tokens) for v in values), (side, values)


@given(column=COLUMN, data=st.data())
def test_run_hands_on_a_column_split_it_can_name_or_refuses(column, data):
    train, test = data.draw(split_values(column))
    with (
        tempfile.TemporaryDirectory() as scratch,
        contextlib.chdir(scratch),
        stand_in("symbench.core.runs.cli.run:run_spec") as run,
    ):
        result = invoke(
            "run", "--model", "sdnn", "--robot", "hexa", "--preset", "smoke",
            f"--split-by={column}", f"--train={train}", f"--test={test}",
        )  # fmt: skip
        if refusal(result) != "Error: reached":
            return
    split = run.call_args.args[0].split
    assert split == column_split(column, listed(train), listed(test)).name
    check_split(split)
