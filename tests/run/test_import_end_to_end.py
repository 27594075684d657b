"""The worked example of docs/data-format.md, from the command line alone: a log shipped with
the tests (tests/data/importing/logs/magneto-wall, made by make_log.py: 3 ms rows, positions,
velocities and torques, no accelerations, base velocities in the base frame) is imported, split by
heading, trained and evaluated; a second dataset's records do not overwrite the first's."""

from __future__ import annotations

import json
import shutil
from pathlib import Path

from click.testing import CliRunner

from symbench.core.cli import build_cli

LOG = Path(__file__).parents[1] / "data" / "importing" / "logs" / "magneto-wall"
SPLIT = ["--split-by", "heading", "--train", "0,90", "--test", "180,270"]


def invoke(args):
    out = CliRunner().invoke(build_cli(), args)
    assert out.exit_code == 0, out.output
    return out.output


def test_import_split_train_and_evaluate_from_the_command_line(home, tmp_path):
    folder = tmp_path / "magneto-wall"
    shutil.copytree(LOG, folder)
    dry = " ".join(invoke(["data", "import", str(folder), "--id", "wall", "--dry-run"]).split())
    assert "derive qdd from qd in all 8 files" in dry
    assert "derive base_linacc from base_linvel in all 8 files" in dry
    assert "decimated from 0.003 s to 0.006 s" in dry
    assert "base_frame = body" in dry
    assert "license = CC0-1.0" in dry
    assert not (home / "datasets" / "wall").exists()  # a dry run writes nothing

    invoke(["data", "import", str(folder), "--id", "wall"])
    info = json.loads(invoke(["data", "info", "wall", "--json", *SPLIT]))
    assert info["record_period_s"] == 0.006 and info["samples"] == 8 * 49
    assert info["provenance"]["license"] == "CC0-1.0"
    split = info["splits"]["heading_0_90_vs_180_270"]
    headings = {p: split[p]["scenarios"]["heading_deg"] for p in ("train", "val", "test")}
    assert sorted(set(headings["train"] + headings["val"])) == [0.0, 90.0]  # val from train
    assert split["test"]["scenarios"]["heading_deg"] == [180.0, 270.0]
    assert split["disjoint"]

    # the same logs under a second id: the same content, the same hash, records of their own
    other = tmp_path / "elsewhere" / "magneto-wall"
    shutil.copytree(LOG, other)
    invoke(["data", "import", str(other), "--id", "wall-2"])
    info_2 = json.loads(invoke(["data", "info", "wall-2", "--json"]))
    assert info_2["content_hash"] == info["content_hash"]  # path and id are not content

    results = tmp_path / "results"
    run = ["run", "--model", "ffnn", "--preset", "smoke", "--max-steps", "20", *SPLIT]
    run += ["--evaluators", "torque-error", "--output", str(results)]
    invoke([*run, "--dataset", "wall"])
    invoke([*run, "--dataset", "wall-2"])
    records = [
        f"{did}__smoke__heading_0_90_vs_180_270__ffnn__acc__torch__converge__seed0.json"
        for did in ("wall", "wall-2")
    ]
    assert sorted(p.name for p in results.glob("*.json")) == sorted(records)
    for did, name in zip(("wall", "wall-2"), records, strict=True):
        record = json.loads((results / name).read_text())
        assert record["dataset"]["id"] == did
        assert record["split"] == "heading_0_90_vs_180_270"
        assert record["samples"]["test_trajectories"] == 4


def test_a_leaking_or_empty_column_split_is_refused(home):
    out = CliRunner().invoke(
        build_cli(),
        ["run", "--model", "ffnn", "--dataset", "x", "--split-by", "heading"]
        + ["--train", "0,90", "--test", "90,180"],
    )
    assert out.exit_code == 2
    assert "heading 90 is listed for both train and test" in out.output
