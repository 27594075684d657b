"""Whatever a `*.tune.json` beside a genuine summary holds (any bytes, or the summary edited
field by field), `symbench tune summarize` prints a row per summary with a best trial, or
refuses in one line naming the file; whatever `--out` names, the table is written there or
the option refused: never an internal error."""

from __future__ import annotations

import contextlib
import json
import math
import shutil
import tempfile
from pathlib import Path
from types import SimpleNamespace
from unittest import mock

import pytest
from cli_invoke import invoke, refusal
from hypothesis import event, given
from hypothesis import strategies as st
from sandbox import fresh_home
from strategies import FILE_BYTES, edited
from synthetic_raw import fake_simulate
from test_cli_properties import PATHS

from symbench.core.data.generation.generate import generate
from symbench.core.runs import tune as tuning
from symbench.core.runs.spec import RunSpec
from symbench.core.training import loop

GENUINE = "genuine.tune.json"


def train(entry, train_set, val_set, config, checkpoint_dir=None):
    loss = math.log(config.learning_rate / 3e-3) ** 2  # smallest at rate 3e-3
    return SimpleNamespace(n_params=1, history={"val_loss": [loss]}, steps=1, stopped_by="x")


@pytest.fixture(scope="module")
def genuine(tmp_path_factory):
    """The summary of a search of ffnn on hexa's smoke data (training a stand-in)."""
    folder = tmp_path_factory.mktemp("tuning")
    with fresh_home(), mock.patch.object(loop, "train", train):
        generate("hexa", "smoke", simulator=fake_simulate, show_progress=False)
        spec = RunSpec("ffnn", "hexa", preset="smoke", evaluators=(), output=folder)
        tuning.tune(spec, (1e-3, 3e-3), (0.5, 1.0), folder, report=lambda _: None)
    return json.loads(tuning.summary_path(folder, spec).read_text())


@given(data=st.data())
def test_a_folder_of_summaries_is_tabled_or_the_odd_one_named(genuine, tmp_path_factory, data):
    folder = tmp_path_factory.mktemp("summaries")
    (folder / GENUINE).write_text(json.dumps(genuine))
    odd = folder / "odd.tune.json"
    content = data.draw(FILE_BYTES | edited(genuine).map(lambda s: json.dumps(s).encode()))
    odd.write_bytes(content)
    result = invoke("tune", "summarize", folder)
    shutil.rmtree(folder)
    if result.exit_code != 0:
        event("refused")
        assert str(odd) in refusal(result)
        return
    event("tabled")
    rows = [line for line in result.stdout.splitlines() if line.startswith("| ")][1:]
    assert len(rows) == 1 + (json.loads(content)["best"] is not None), rows  # a row per best


@given(out=PATHS)
def test_summarize_out_is_refused_as_a_usage_error_or_holds_the_table(genuine, out):
    with tempfile.TemporaryDirectory() as scratch, contextlib.chdir(scratch):
        Path("blocker").write_text("a file, not a folder")
        Path("summaries").mkdir()
        (Path("summaries") / GENUINE).write_text(json.dumps(genuine))
        result = invoke("tune", "summarize", "summaries", f"--out={out}")
        if result.exit_code != 0:
            event("refused")
            assert refusal(result).startswith("Error: Invalid value for '--out'")
            return
        event("written")
        assert Path(out).read_text() in result.stdout
