"""The image overlap is measured once per output folder and split and seed: the runs of a
sweep's five models read it back, and a cache file that is not what was written is measured
again, never trusted."""

from __future__ import annotations

import json

import pytest

from symbench.core.runs import overlap_cache
from symbench.core.runs.overlap_cache import FOLDER, cached_split_overlap


@pytest.fixture
def counted(monkeypatch):
    """How many times the overlap is really measured."""
    calls = []
    measure = overlap_cache.split_overlap

    def counting(*args):
        calls.append(args[1:])
        return measure(*args)

    monkeypatch.setattr(overlap_cache, "split_overlap", counting)
    return calls


def test_a_second_run_reads_the_overlap_instead_of_measuring_it(
    simulated_smoke_hexa, tmp_path, counted
):
    first = cached_split_overlap(simulated_smoke_hexa, "iid", 0, tmp_path)
    again = cached_split_overlap(simulated_smoke_hexa, "iid", 0, tmp_path)
    assert counted == [("iid", 0)]
    assert again == first and again.to_dict() == first.to_dict()
    other_seed = cached_split_overlap(simulated_smoke_hexa, "iid", 1, tmp_path)
    assert counted == [("iid", 0), ("iid", 1)] and other_seed.seed == 1
    assert len(list((tmp_path / FOLDER).glob("*.json"))) == 2


@pytest.mark.parametrize(
    "damage",
    [
        lambda data: "not json {",
        lambda data: json.dumps({**data, "key": {**data["key"], "version": -1}}),
        lambda data: json.dumps({**data, "key": {**data["key"], "content_hash": "0" * 64}}),
        lambda data: json.dumps({**data, "overlap": {**data["overlap"], "comparisons": "many"}}),
        lambda data: json.dumps({**data, "overlap": {**data["overlap"], "sides": [1, 2]}}),
        lambda data: json.dumps({"key": data["key"]}),
    ],
    ids=["not-json", "old-version", "other-data", "wrong-type", "wrong-shape", "no-overlap"],
)
def test_a_cache_file_that_is_not_what_was_written_is_measured_again(
    simulated_smoke_hexa, tmp_path, counted, damage
):
    first = cached_split_overlap(simulated_smoke_hexa, "iid", 0, tmp_path)
    (path,) = (tmp_path / FOLDER).glob("*.json")
    path.write_text(damage(json.loads(path.read_text())))
    again = cached_split_overlap(simulated_smoke_hexa, "iid", 0, tmp_path)
    assert len(counted) == 2 and again.to_dict() | {"seconds": 0} == first.to_dict() | {
        "seconds": 0
    }
    assert json.loads(path.read_text())["key"]["version"] == overlap_cache.CACHE_VERSION
