"""Matched sizes (`--parameters N`): named in the run key and the record, kept apart from
default sizes on every board table, with ranks of their own and each model's miss shown."""

from __future__ import annotations

import json
from dataclasses import replace
from pathlib import Path

import pandas as pd
import pytest

from symbench.core.board.claims import claims_markdown
from symbench.core.board.leaderboard import aggregate, load_records, markdown, write_leaderboard
from symbench.core.board.site.reproduce import run_command
from symbench.core.board.summary import headline
from symbench.core.runs.results import read_record, run_key, seal_of, write_record
from symbench.core.runs.spec import RunSpec
from symbench.core.runs.verify import replay_spec

# records written before matched sizes existed: the archived v6 board's
RECORDS = Path(__file__).resolve().parents[2] / "leaderboards/archive/small-v6-superseded/records"
DEFAULT_KEY = "hexa-climb-small-v5__small__iid__sdnn__acc__torch__converge__seed0"


def matched(record: dict, target: int, count: int) -> dict:
    record["model"]["matched_parameters"] = target
    record["model"]["parameters"] = count
    return record


def test_key_names_a_matched_size_only():
    args = ("hexa-climb-small-v5", "small", "iid", "sdnn", "acc", "torch", "converge", 0)
    assert run_key(*args) == DEFAULT_KEY
    assert run_key(*args, 100000) == DEFAULT_KEY.replace("__seed0", "__p100000__seed0")


def test_spec_and_record_keys_agree(tmp_path, make_record):
    record = write_record(matched(make_record(), 100000, 101000), tmp_path / "r.json")
    spec = RunSpec(
        model="sdnn",
        robot="hexa",
        dataset=record.dataset.id,
        preset=record.dataset.preset,
        protocol=record.protocol(),
        parameters=100000,
    )
    assert record.key() == spec.key()
    assert record.key().endswith("__p100000__seed0")
    default = record.model_copy(
        update={"model": record.model.model_copy(update={"matched_parameters": None})}
    )
    assert (
        replace(spec, parameters=None).key()
        == default.key()
        == record.key().replace("__p100000", "")
    )


def test_the_field_is_left_out_at_default_size(tmp_path, make_record):
    """A default record is written (and sealed) as before the field existed; a matched one
    carries it and reads back with it."""
    old = make_record()
    written = write_record(old, tmp_path / "default.json")
    data = json.loads((tmp_path / "default.json").read_text())
    assert "matched_parameters" not in data["model"]
    assert data["seal"] == seal_of(data)
    assert written.model.matched_parameters is None
    mine = write_record(matched(make_record(), 100000, 99000), tmp_path / "matched.json")
    back = read_record(tmp_path / "matched.json")
    assert back.model.matched_parameters == 100000 == mine.model.matched_parameters
    assert back.configuration()["matched parameters"] == 100000
    assert "matched parameters" not in written.configuration()


def test_committed_records_keep_their_seals_and_keys(tmp_path):
    """Records written before the field still match their seals and keep their file names
    as keys; a re-write (publish's) adds no size to them."""
    for path in sorted(RECORDS.glob("*.json"))[:20]:
        record = read_record(path)
        assert record.key() == path.stem and record.model.matched_parameters is None
        write_record(record, tmp_path / path.name)
        assert "matched_parameters" not in (tmp_path / path.name).read_text()


def _both_sizes(folder, make_record) -> None:
    """Three seeds of sdnn and ffnn at default size, and at 100 000 parameters where the
    order flips and ffnn misses by 6 %."""
    for seed in range(3):
        for model, rmse, size, count in (
            ("sdnn", 0.1, None, 1234),
            ("ffnn", 0.5, None, 1234),
            ("sdnn", 0.9, 100000, 100400),
            ("ffnn", 0.2, 100000, 106000),
        ):
            record = make_record(model=model, seed=seed, rmse=rmse + seed / 100)
            if size is not None:
                matched(record, size, count)
            sealed = write_record(record, folder / "scratch.json")
            write_record(sealed, folder / f"{sealed.key()}.json")
    (folder / "scratch.json").unlink()


def test_default_and_matched_runs_coexist_and_rank_apart(tmp_path, make_record):
    _both_sizes(tmp_path, make_record)
    assert len(list(tmp_path.glob("*.json"))) == 12  # one folder, no shared key
    table = aggregate(load_records(tmp_path))
    ranks = {(r["size"], r.model): r["rank"] for _, r in table.iterrows()}
    assert ranks == {
        ("default", "sdnn"): 1,
        ("default", "ffnn"): 2,
        ("matched 100000", "ffnn"): 1,
        ("matched 100000", "sdnn"): 2,
    }
    misses = {(r["size"], r.model): r.parameters_miss for _, r in table.iterrows()}
    assert misses["matched 100000", "ffnn"] == pytest.approx(0.06)
    assert pd.isna(misses["default", "ffnn"])


def test_tables_show_the_matched_section_apart(tmp_path, make_record):
    _both_sizes(tmp_path, make_record)
    table = aggregate(load_records(tmp_path))
    page = markdown(table, "hexa")
    default, matched_part = page.split("matched at 100 000 parameters")
    assert "| 1234 |" in default and "100400" not in default
    assert "106000 (+6.0 % (outside 5 %))" in matched_part
    assert "100400 (+0.4 %)" in matched_part
    assert "a model outside it is marked, not left out" in matched_part
    summary = headline(table)
    assert "# Trained under the paper protocol, matched at 100 000 parameters" in summary
    assert summary.index("# Trained under the paper protocol\n") < summary.index("matched at")
    assert "100000" not in claims_markdown(table) and "default sizes" in claims_markdown(table)
    write_leaderboard(tmp_path, tmp_path / "out")
    csv = (tmp_path / "out" / "leaderboard.csv").read_text().splitlines()
    assert "size" in csv[0].split(",")
    assert sum("matched 100000" in line for line in csv) == 2


def test_reproduce_and_verify_replay_the_size(tmp_path, make_record):
    record = write_record(matched(make_record(), 100000, 100400), tmp_path / "r.json")
    assert "--parameters 100000" in run_command(record)
    assert "--parameters" not in run_command(write_record(make_record(), tmp_path / "d.json"))
    assert replay_spec(record, tmp_path, 1).parameters == 100000
