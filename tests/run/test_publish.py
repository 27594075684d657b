"""Publishing checks the schema, the standard dataset's hash and the number of seeds."""

from __future__ import annotations

import json

import pytest

from symbench.core.errors import SymbenchError
from symbench.core.publish import publish, standard_hash


def write(path, record):
    path.write_text(json.dumps(record))
    return path


@pytest.fixture
def smoke_hash(smoke_home, tmp_path):
    return standard_hash("hexa-climb-smoke-v3", tmp_path)


def test_three_seeds_on_the_standard_dataset_are_published(smoke_hash, make_record, tmp_path):
    paths = [write(tmp_path / f"s{s}.json", make_record(seed=s, content_hash=smoke_hash))
             for s in range(3)]
    board = tmp_path / "leaderboards"
    written = publish(paths, board)
    assert sorted(p.name for p in (board / "records").iterdir()) == [
        f"hexa__iid__sdnn__acc__torch__seed{s}.json" for s in range(3)]
    assert board / "hexa.md" in written and "| 1 | sdnn | acc | torch | 3 |" in (board / "hexa.md").read_text()
    publish(paths[:1], board)  # publishing the same record again changes nothing


def test_refusals_name_the_reason(smoke_hash, make_record, tmp_path):
    board = tmp_path / "leaderboards"
    two = [write(tmp_path / f"s{s}.json", make_record(seed=s, content_hash=smoke_hash))
           for s in range(2)]
    with pytest.raises(SymbenchError, match="would have 2 seed"):
        publish(two, board)
    wrong = write(tmp_path / "w.json", make_record(seed=5, content_hash="ef" * 32))
    with pytest.raises(SymbenchError, match="now has hash"):
        publish([wrong], board)
    foreign = make_record(seed=6, content_hash=smoke_hash)
    foreign["dataset"]["id"] = "my-lab-logs"
    with pytest.raises(SymbenchError, match="not a standard dataset"):
        publish([write(tmp_path / "f.json", foreign)], board)
    broken = make_record(seed=7, content_hash=smoke_hash)
    del broken["metrics"]
    with pytest.raises(SymbenchError, match="metrics: Field required"):
        publish([write(tmp_path / "b.json", broken)], board)
    assert not board.exists()  # nothing was written
