"""The data-symmetry evaluator keeps the dataset's own symmetry measure in the record."""

from __future__ import annotations

from types import SimpleNamespace

from symbench.core.data import load_dataset
from symbench.core.data.symmetry.report import dataset_symmetry
from symbench.plugins.evaluators import data_symmetry


def test_it_reports_what_data_symmetry_measures(smoke_hexa):
    dataset = load_dataset(smoke_hexa.dataset_id)
    report = dataset_symmetry(dataset)
    out = data_symmetry.evaluate(SimpleNamespace(dataset=dataset))
    assert out["image_pairs"] == len(report.pairs) == 2  # yaw 180 is an image of yaw 0
    for key, group in (("tau", "torques"), ("joint", "joint states"), ("base", "base")):
        assert out[f"{key}_rel_error"] == report.groups[group]["relative_error"]
        assert out[f"{key}_ratio_to_floor"] == report.groups[group]["ratio"]


def test_a_dataset_without_image_climbs_says_so(smoke_hexa, monkeypatch):
    dataset = load_dataset(smoke_hexa.dataset_id)
    empty = dataset_symmetry(dataset)
    empty.pairs = []
    monkeypatch.setattr(data_symmetry, "dataset_symmetry", lambda _: empty)
    out = data_symmetry.evaluate(SimpleNamespace(dataset=dataset))
    assert out == {
        "image_pairs": 0,
        "floor": empty.floor_source,
        "reason": "no two climbs of the dataset are rotated images of each other",
    }


def test_it_is_a_registered_evaluator_that_needs_raw_states():
    from symbench.core.plugin import registry

    entry = registry.evaluator("data-symmetry")
    assert entry.needs == ("raw", "scenarios") and "not the model's" in entry.description
