"""Result records: validated and sealed when written, checked when read; broken, edited or
foreign ones are refused."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from symbench.core.common.errors import SymbenchError
from symbench.core.config.presets import LEGACY_PRESETS, PRESETS
from symbench.core.config.provenance import hardware, library_versions
from symbench.core.runs.results import read_display_record, read_record, seal_of, write_record


@pytest.fixture
def valid_record(make_record):
    return make_record


def test_round_trip(valid_record, tmp_path):
    path = tmp_path / "r.json"
    written = write_record(valid_record(), path)
    assert read_record(path) == written
    assert written.seal == seal_of(json.loads(path.read_text()))
    # a record from before the converge protocol was trained under the paper's rule
    assert written.key() == "hexa-climb-smoke-v7__smoke__iid__sdnn__acc__torch__paper__seed0"
    assert not list(tmp_path.glob(".*tmp"))  # the atomic write left no temp file
    record = valid_record()
    record["training"]["config"].update(
        protocol="converge", max_steps=30, eval_every=10, patience=2
    )
    converge = write_record(record, tmp_path / "c.json")
    assert converge.key() == "hexa-climb-smoke-v7__smoke__iid__sdnn__acc__torch__converge__seed0"


def test_provenance_is_filled():
    versions = library_versions()
    assert versions["torch"].startswith("2.") and "mujoco" in versions
    assert hardware()["cores"] >= 1


@pytest.mark.parametrize("field", ["model", "dataset", "seed", "git_commit"])
def test_missing_field_is_rejected_by_name(valid_record, tmp_path, field):
    record = valid_record()
    del record[field]
    with pytest.raises(SymbenchError, match=f"{field}: Field required"):
        write_record(record, tmp_path / "r.json")
    record["seal"] = seal_of(record)  # sealed, so that the schema is what refuses it
    (tmp_path / "bad.json").write_text(json.dumps(record))
    with pytest.raises(SymbenchError, match=f"{field}: Field required"):
        read_record(tmp_path / "bad.json")


def test_nested_missing_field_and_bad_values(valid_record, tmp_path):
    record = valid_record()
    del record["model"]["plugin"]
    with pytest.raises(SymbenchError, match="model.plugin: Field required"):
        write_record(record, tmp_path / "r.json")
    record = valid_record()
    record["model"]["backend"] = "tensorflow"
    with pytest.raises(SymbenchError, match="model.backend"):
        write_record(record, tmp_path / "r.json")
    record = valid_record()
    record["dataset"]["content_hash"] = "short"
    with pytest.raises(SymbenchError, match="dataset.content_hash"):
        write_record(record, tmp_path / "r.json")
    record = valid_record()
    record["training"]["checkpoint_sha256"] = {}
    with pytest.raises(SymbenchError, match="training.checkpoint_sha256"):
        write_record(record, tmp_path / "r.json")
    assert not (tmp_path / "r.json").exists()


def test_an_edited_metric_breaks_the_seal(valid_record, tmp_path):
    path = tmp_path / "r.json"
    write_record(valid_record(rmse=0.5), path)
    path.write_text(path.read_text().replace('"rmse": 0.5', '"rmse": 0.05'))
    with pytest.raises(SymbenchError) as error:
        read_record(path)
    assert (
        str(error.value) == f"{path}: record does not match its seal (edited after it was written)"
    )
    with pytest.raises(SymbenchError, match="does not match its seal"):
        read_display_record(path)  # not even shown
    data = json.loads(path.read_text())
    data["seal"] = seal_of(data)  # re-sealing is possible: `symbench verify` catches that
    path.write_text(json.dumps(data))
    assert read_record(path).metrics["torque-error"]["rmse"] == 0.05


@pytest.mark.parametrize(
    "field, value",
    [
        ("robot", "../../x"),
        ("split", "a/b"),
        ("model.name", ".hidden"),
        ("dataset.preset", "small@v6/../x"),
        ("dataset.preset", "small@6"),
        ("split", "iid@v6"),  # only a preset names an earlier version
    ],
)
def test_names_must_be_safe_identifiers(valid_record, tmp_path, field, value):
    record = valid_record()
    where = record
    *parents, last = field.split(".")
    for part in parents:
        where = where[part]
    where[last] = value
    with pytest.raises(SymbenchError, match=f"{field}: String should match pattern"):
        write_record(record, tmp_path / "r.json")


def test_a_record_takes_every_presets_key_earlier_versions_included(valid_record, tmp_path):
    """A run on `--preset small@v6` (the v6 board's data and budgets) once trained, evaluated
    and then failed to write its record, whose preset field refused the '@'."""
    for name in [*PRESETS, *LEGACY_PRESETS]:
        record = valid_record()
        record["dataset"]["preset"] = name
        assert write_record(record, tmp_path / "r.json").dataset.preset == name


def test_schema_1_records_are_shown_but_not_trusted(valid_record, as_schema_1, tmp_path):
    path = tmp_path / "old.json"
    path.write_text(json.dumps(as_schema_1(valid_record())))
    assert (
        read_display_record(path).key()
        == "hexa-climb-smoke-v7__smoke__iid__sdnn__acc__torch__paper__seed0"
    )
    with pytest.raises(SymbenchError) as error:
        read_record(path)
    assert str(error.value) == f"{path}: record is not sealed (schema 1); re-run it"


def test_foreign_schema_version_and_garbage(valid_record, tmp_path):
    record = valid_record()
    record["schema_version"] = 99
    (tmp_path / "v.json").write_text(json.dumps(record))
    with pytest.raises(SymbenchError, match="schema version 99"):
        read_record(tmp_path / "v.json")
    (tmp_path / "g.json").write_text("{not json")
    with pytest.raises(SymbenchError, match="cannot read result record"):
        read_record(tmp_path / "g.json")


def test_a_published_record_from_before_robot_plugin_still_reads_and_verifies():
    root = Path(__file__).resolve().parents[2] / "leaderboards/archive/small-v6-superseded/records"
    path = min(root.glob("*.json"))
    assert "robot_plugin" not in json.loads(path.read_text())
    assert read_record(path).robot_plugin is None  # and its seal still matches
