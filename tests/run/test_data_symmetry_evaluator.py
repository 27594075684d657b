"""The data-symmetry evaluator keeps the dataset's own symmetry measure in the record."""

from __future__ import annotations

from dataclasses import replace
from types import SimpleNamespace

from symbench.core.data import load_dataset
from symbench.core.data.symmetry.report import dataset_symmetry
from symbench.plugins.evaluators import data_symmetry


def test_it_reports_what_data_symmetry_measures(smoke_hexa):
    dataset = load_dataset(smoke_hexa.dataset_id)
    report = dataset_symmetry(dataset)
    out = data_symmetry.evaluate(SimpleNamespace(dataset=dataset))
    assert out["image_pairs"] == len(report.pairs) == 2  # yaw 180 is an image of yaw 0
    assert out["pairs"] == "found"
    for key, group in (("tau", "torques"), ("joint", "joint states"), ("base", "base")):
        assert out[f"{key}_rel_error"] == report.groups[group]["relative_error"]
        assert out[f"{key}_ratio_to_floor"] == report.groups[group]["ratio"]


def test_a_generated_dataset_without_image_climbs_gets_constructed_pairs(drawn_hexa):
    out = data_symmetry.evaluate(SimpleNamespace(dataset=drawn_hexa))
    assert out["pairs"] == "constructed" and out["twins"] == 3  # all, fewer than eight
    assert out["image_pairs"] == 3 * 15  # every two of a climb's six copies
    for key in ("tau", "joint", "base"):
        assert out[f"{key}_rel_error"] < 1e-6  # hexa is symmetric: its twins are exact


def test_an_imported_dataset_without_image_climbs_says_so(drawn_hexa):
    imported = replace(drawn_hexa, metadata={**drawn_hexa.metadata, "source": "imported"})
    out = data_symmetry.evaluate(SimpleNamespace(dataset=imported))
    assert out == {
        "image_pairs": 0,
        "reason": "no two climbs of the dataset are rotated images of each other, and an "
        "imported dataset cannot be simulated again to construct some",
    }


def test_it_is_a_registered_evaluator_that_needs_raw_states():
    from symbench.core.plugin import registry

    entry = registry.evaluator("data-symmetry")
    assert entry.needs == ("raw", "scenarios") and "not the model's" in entry.description
