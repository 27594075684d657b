"""Whatever a dataset's metadata.json holds, even re-hashed by hand, reading the dataset gives
a one-line error naming it, or a dataset whose counts agree with its files."""

from __future__ import annotations

import contextlib
import json
import shutil

import pytest
from cli_invoke import error_line, invoke
from hypothesis import given
from hypothesis import strategies as st
from sandbox import fresh_home
from strategies import FILE_BYTES, edited
from synthetic_raw import fake_simulate

from symbench.core.common.errors import SymbenchError
from symbench.core.data import load_dataset
from symbench.core.data.generation import generate
from symbench.core.data.metadata import METADATA, content_hash
from symbench.core.data.storage import step_count

DATASET = "hexa-climb-smoke-v4"


@pytest.fixture(scope="module")
def template(tmp_path_factory):
    """A dataset folder made by the stand-in simulator, and its metadata."""
    with fresh_home():
        root = generate("hexa", "smoke", simulator=fake_simulate, show_progress=False).root
        template = shutil.copytree(root, tmp_path_factory.mktemp("template") / DATASET)
    return template, json.loads((template / METADATA).read_text())


def check_reading(template, metadata: bytes) -> None:
    """`symbench data info` on the template with `metadata` as its metadata.json."""
    with fresh_home() as home:
        root = shutil.copytree(template, home / "datasets" / DATASET)
        (root / METADATA).write_bytes(metadata)
        result = invoke("data", "info", DATASET, "--json")
        if result.exit_code != 0:
            assert DATASET in error_line(result, 1) or str(root) in error_line(result, 1)
            return
        info = json.loads(result.stdout)
        dataset = load_dataset(DATASET)
        steps = [step_count(root / r["file"]) for r in dataset.metadata["trajectories"]]
        assert info["trajectories"] == len(steps)
        assert info["samples"] == sum(steps) - len(steps)
        try:  # a robot edited into another is refused when the data is used
            assert len(dataset.view("leg_grouped", "acc")) == info["samples"]
        except SymbenchError as error:
            assert "\n" not in str(error) and DATASET in str(error)


@given(data=FILE_BYTES)
def test_any_metadata_file_gives_an_error_naming_the_dataset(template, data):
    check_reading(template[0], data)


@pytest.mark.parametrize("rehash", [True, False], ids=["re-hashed", "as edited"])
@given(data=st.data())
def test_edited_metadata_gives_an_error_or_counts_that_agree_with_the_files(template, rehash, data):
    meta = data.draw(edited(template[1]))
    if rehash and isinstance(meta, dict):
        with contextlib.suppress(ValueError):  # NaN cannot be hashed, so stays un-hashed
            meta["content_hash"] = content_hash(meta)
    check_reading(template[0], json.dumps(meta).encode())
