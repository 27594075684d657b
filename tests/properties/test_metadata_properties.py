"""Whatever a dataset's metadata.json holds, even re-hashed by hand, reading the dataset gives
one of the one-line errors that name it, or exactly what the metadata and its files say."""

from __future__ import annotations

import contextlib
import json
import re
import shutil

import pytest
from cli_invoke import error_line, invoke
from hypothesis import given, settings
from hypothesis import strategies as st
from sandbox import fresh_home
from strategies import FILE_BYTES, edited
from synthetic_raw import fake_simulate

from symbench.core.common.errors import SymbenchError
from symbench.core.data import load_dataset
from symbench.core.data.generation.generate import generate
from symbench.core.data.storage.files import step_count
from symbench.core.data.storage.metadata import METADATA, content_hash
from symbench.core.plugin import registry

DATASET = "hexa-climb-smoke-v7"


@pytest.fixture(scope="module")
def template(tmp_path_factory):
    """A dataset folder made by the stand-in simulator, and its metadata."""
    with fresh_home():
        root = generate("hexa", "smoke", simulator=fake_simulate, show_progress=False).root
        template = shutil.copytree(root, tmp_path_factory.mktemp("template") / DATASET)
    return template, json.loads((template / METADATA).read_text())


def refusals(root) -> list[str]:
    """Every message symbench gives for a bad metadata.json (whole messages, as patterns):
    each names the dataset or its metadata file first, and says what is wrong."""
    dataset, path = re.escape(f"dataset '{DATASET}'"), re.escape(str(root / METADATA))
    repair = r"\S.*"  # the repair command the (edited) metadata holds, or the generic one
    return [
        rf"{dataset}: {path}: not valid JSON \(.+\)",
        rf"{path} is not a symbench dataset's metadata",
        rf"{dataset} has format version .+, this symbench reads 1; {repair}",
        rf"{dataset}: metadata.json was edited or damaged \(content hash mismatch\); "
        rf"rebuild it with: {repair}",
        rf"{dataset}: {path} is malformed: \S.*: \S.*",
        rf"{dataset}: trajectories/.+ changed, truncated or missing \(SHA-256 mismatch\); "
        rf"fix it with: {repair}",
        rf"{dataset}: trajectories/.+ holds \d+ steps, metadata.json says -?\d+; "
        rf"fix it with: {repair}",
        rf"{dataset} has no trajectories \(\d+ failed\)",
        rf"{dataset}: {path} names dataset '.*' \(a folder copied or renamed by hand\); "
        rf"rebuild it with: {repair}",
    ]


def values_of(meta: dict, ids: list[int]) -> dict[str, list]:
    """The distinct values of each scenario column among trajectories `ids`, from the
    metadata as written (numbers before text, each sorted)."""
    scenario = {r["id"]: r.get("scenario") or {} for r in meta["trajectories"]}
    out = {}
    for column in ("inclination_deg", "heading_deg", "yaw_deg", "direction"):
        values = {scenario[i].get(column) for i in ids} - {None}
        if values:
            out[column] = sorted(values, key=lambda v: (isinstance(v, str), v))
    orders = {  # the stepping sequence: absent, default (None), reversed, or the legs in order
        "default" if o is None else "reversed" if o == sorted(o)[::-1] else ",".join(map(str, o))
        for i in ids
        if "leg_order" in scenario[i]
        for o in [scenario[i]["leg_order"]]
    }
    if orders:
        out["leg_order"] = sorted(orders)
    return out


def check_reading(template, metadata: bytes) -> None:
    """`symbench data info` on the template with `metadata` as its metadata.json: one of the
    refusals above, or exactly what that metadata.json and the files say."""
    with fresh_home() as home:
        root = shutil.copytree(template, home / "datasets" / DATASET)
        (root / METADATA).write_bytes(metadata)
        result = invoke("data", "info", DATASET, "--json")
        if result.exit_code != 0:
            line = error_line(result, 1).removeprefix("Error: ")
            assert any(re.fullmatch(p, line) for p in refusals(root)), line
            return
        info = json.loads(result.stdout)
        splits = info.pop("splits")
        meta = json.loads(metadata)  # what was written, read here independently of symbench
        files = {r["id"]: root / r["file"] for r in meta["trajectories"]}
        steps = {i: step_count(f) for i, f in files.items()}
        assert info == {
            "id": DATASET,
            "robot": meta["robot"],
            "source": meta["source"],
            "preset": meta.get("preset"),
            "content_hash": meta["content_hash"],
            "trajectories": len(steps),
            "failed": len(meta["failures"]),
            "failures": meta["failures"],
            "samples": sum(steps.values()) - len(steps),
            "record_period_s": meta["record_period_s"],
            "size_bytes": sum(f.stat().st_size for f in files.values()),
            "versions": meta["versions"],
            "provenance": meta.get("provenance", {}),
            "unknown_columns": meta.get("unknown_columns", []),
            "import": meta.get("import"),
            "scenarios": values_of(meta, list(files)),
            "split_seed": 0,
        }
        dataset = load_dataset(DATASET)
        assert list(splits) == list(registry.collect("splits"))
        for name, counts in splits.items():
            try:
                parts = dataset.split_indices(name, 0)
            except SymbenchError as error:  # an edited scenario grid may not support it
                assert counts == {"error": str(error)}, name
                continue
            named = (("train", parts.train), ("val", parts.val), ("test", parts.test))
            overlap = counts.pop("image_overlap")  # measured or refused in one line
            assert "error" in overlap or {s: p["climbs"] for s, p in overlap["sides"].items()} == {
                part: len(ids) for part, ids in named if len(ids)
            }, name
            assert counts == {
                part: {
                    "trajectories": len(ids),
                    "samples": sum(steps[i] - 1 for i in ids),
                    "scenarios": values_of(meta, ids.tolist()),
                }
                for part, ids in named
            } | {"unused": len(steps) - sum(len(ids) for _, ids in named), "disjoint": True}, name
        try:  # a robot edited into another is refused when the data is used
            assert len(dataset.view("leg_grouped", "acc")) == info["samples"]
        except SymbenchError as error:
            subject = rf"dataset '{re.escape(DATASET)}'( was made with|:) "
            assert re.fullmatch(rf"{subject}\S.*", str(error)), str(error)


@given(data=FILE_BYTES)
def test_any_metadata_file_gives_an_error_naming_the_dataset(template, data):
    check_reading(template[0], data)


@pytest.mark.parametrize("rehash", [True, False], ids=["re-hashed", "as edited"])
@settings(max_examples=settings.default.max_examples // 5)  # each reads every split: seconds
@given(data=st.data())
def test_edited_metadata_gives_an_error_or_counts_that_agree_with_the_files(template, rehash, data):
    meta = data.draw(edited(template[1]))
    if rehash and isinstance(meta, dict):
        with contextlib.suppress(ValueError):  # NaN cannot be hashed, so stays un-hashed
            meta["content_hash"] = content_hash(meta)
    check_reading(template[0], json.dumps(meta).encode())
