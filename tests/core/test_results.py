"""Result records: validated when written and read; broken or foreign ones are refused."""

from __future__ import annotations

import copy
import json

import pytest

from symbench.core.errors import SymbenchError
from symbench.core.provenance import hardware, library_versions
from symbench.core.results import check_dataset_hash, read_record, write_record

HASH = "ab" * 32


@pytest.fixture
def valid_record(make_record):
    return make_record


def test_round_trip(valid_record, tmp_path):
    path = tmp_path / "r.json"
    written = write_record(valid_record(), path)
    assert read_record(path) == written
    assert written.key() == "hexa__iid__sdnn__acc__torch__seed0"
    assert not list(tmp_path.glob(".*tmp"))  # the atomic write left no temp file


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
    (tmp_path / "bad.json").write_text(json.dumps(record))
    with pytest.raises(SymbenchError, match=f"{field}: Field required"):
        read_record(tmp_path / "bad.json")


def test_nested_missing_field_and_bad_values(valid_record, tmp_path):
    record = valid_record()
    del record["model"]["parameters"]
    with pytest.raises(SymbenchError, match="model.parameters: Field required"):
        write_record(record, tmp_path / "r.json")
    record = copy.deepcopy(valid_record())
    record["model"]["backend"] = "tensorflow"
    with pytest.raises(SymbenchError, match="model.backend"):
        write_record(record, tmp_path / "r.json")
    record = valid_record()
    record["dataset"]["content_hash"] = "short"
    with pytest.raises(SymbenchError, match="dataset.content_hash"):
        write_record(record, tmp_path / "r.json")
    assert not (tmp_path / "r.json").exists()


def test_foreign_schema_version_and_garbage(valid_record, tmp_path):
    record = valid_record()
    record["schema_version"] = 99
    (tmp_path / "v.json").write_text(json.dumps(record))
    with pytest.raises(SymbenchError, match="schema version 99"):
        read_record(tmp_path / "v.json")
    (tmp_path / "g.json").write_text("{not json")
    with pytest.raises(SymbenchError, match="cannot read result record"):
        read_record(tmp_path / "g.json")


def test_wrong_dataset_hash_is_rejected(valid_record, tmp_path):
    record = write_record(valid_record(), tmp_path / "r.json")
    check_dataset_hash(record, HASH)
    with pytest.raises(SymbenchError, match="now has hash"):
        check_dataset_hash(record, "ef" * 32)
