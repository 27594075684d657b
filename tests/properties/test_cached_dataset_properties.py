"""Whatever a cached dataset's trajectory file holds (a few bytes changed, any bytes, or a
valid table with one defect), with metadata.json re-hashed to match it or not, reading the
dataset (`symbench data info`, then its views) gives a one-line error naming the dataset or
the file, or the rows that file holds: never an internal error."""

from __future__ import annotations

import json
import re
import shutil

import pytest
from cli_invoke import invoke, refusal
from hypothesis import event, given, settings
from hypothesis import strategies as st
from sandbox import fresh_home
from strategies import FILE_BYTES, changed, defective
from synthetic_raw import fake_simulate

from symbench.core.common.errors import SymbenchError
from symbench.core.data import load_dataset
from symbench.core.data.generation.generate import generate
from symbench.core.data.storage.columns import flatten
from symbench.core.data.storage.files import read_trajectory, sha256_bytes
from symbench.core.data.storage.metadata import METADATA, content_hash

DATASET = "hexa-climb-smoke-v7"
LEGS = 6


@pytest.fixture(scope="module")
def template(tmp_path_factory):
    """A dataset folder made by the stand-in simulator, and its metadata."""
    with fresh_home():
        root = generate("hexa", "smoke", simulator=fake_simulate, show_progress=False).root
        template = shutil.copytree(root, tmp_path_factory.mktemp("template") / DATASET)
    return template, json.loads((template / METADATA).read_text())


def defective_table(draw, path) -> bytes:
    """The trajectory at `path` as Parquet with one defect in its columns (pyarrow writes
    the table as it is: a column of text, a value NaN, a column missing or added...)."""
    import pyarrow as pa
    import pyarrow.parquet as pq

    columns = flatten(read_trajectory(path, LEGS), LEGS)
    table = pa.table(draw(defective(columns, same_length=True)))
    sink = pa.BufferOutputStream()
    pq.write_table(table, sink)
    return sink.getvalue().to_pybytes()


@settings(max_examples=settings.default.max_examples // 2)  # a dataset read per example
@given(data=st.data(), rehash=st.booleans())
def test_a_damaged_trajectory_file_is_named_or_read_as_it_is(template, data, rehash):
    folder, meta = template
    meta = json.loads(json.dumps(meta))
    at = data.draw(st.integers(0, len(meta["trajectories"]) - 1))
    record = meta["trajectories"][at]
    original = (folder / record["file"]).read_bytes()
    kind = data.draw(st.sampled_from(["changed", "any", "defective"]))
    if kind == "changed":
        content = data.draw(changed(original))
    elif kind == "any":
        content = data.draw(FILE_BYTES)
    else:
        content = defective_table(data.draw, folder / record["file"])
    with fresh_home() as home:
        root = shutil.copytree(folder, home / "datasets" / DATASET)
        path = root / record["file"]
        path.write_bytes(content)
        if rehash:  # the file's digest and the content hash made to match it by hand
            record["sha256"] = sha256_bytes(content)
            meta["content_hash"] = content_hash(meta)
            (root / METADATA).write_text(json.dumps(meta))
        # the image-overlap measure (1.4 s a time) in one example of ten
        overlap = [] if data.draw(st.integers(0, 9)) == 0 else ["--no-overlap"]
        result = invoke("data", "info", DATASET, "--json", *overlap)
        if result.exit_code != 0:
            event(f"{kind}: info refused")
            line = refusal(result).removeprefix("Error: ")
            assert re.match(rf"(dataset '{DATASET}'|{re.escape(str(path))})", line), line
            return
        try:
            view = load_dataset(DATASET).view("leg_grouped", "acc")
        except SymbenchError as error:
            event(f"{kind}: view refused")
            message = str(error)
            assert "\n" not in message and (DATASET in message or str(path) in message), message
            return
    event(f"{kind}: read")
    assert content == original or rehash
    steps = [r["n_steps"] for r in meta["trajectories"]]
    assert len(view) == json.loads(result.stdout)["samples"] == sum(steps) - len(steps)
