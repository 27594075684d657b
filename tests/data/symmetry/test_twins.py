"""Image pairs constructed on purpose (`symbench data symmetry ID --twins N`): climbs drawn
as v7 draws them hold none, so some are simulated again turned by one symmetry step."""

from __future__ import annotations

import json
from dataclasses import replace

import pytest
from cli_invoke import error_line, invoke

from symbench.core.common.errors import SymbenchError
from symbench.core.data.dataset import load_dataset
from symbench.core.data.generation.generate import generate
from symbench.core.data.storage.files import read_trajectory
from symbench.core.data.symmetry.measure import measure
from symbench.core.data.symmetry.pairing import rotation_angles
from symbench.core.data.symmetry.report import (
    FLOAT_PRECISION,
    NoImagePairsError,
    dataset_symmetry,
)
from symbench.core.data.twins import twin_symmetry, twins_dataset
from symbench.core.sim.scene.scenario import Scenario


def test_drawn_climbs_hold_no_image_pairs_and_the_error_names_twins(drawn_hexa):
    with pytest.raises(NoImagePairsError, match="symbench data symmetry hexa-drawn --twins N"):
        dataset_symmetry(drawn_hexa)


def test_constructed_twins_are_images_at_float_precision(drawn_hexa):
    report = twin_symmetry(drawn_hexa, 2)
    angles = dict(rotation_angles(drawn_hexa.spec.group, drawn_hexa.frames))
    turns = [(p.a, p.b, round(angles[p.element], 9)) for p in report.pairs]
    assert turns == [(0, 1, 60.0), (2, 3, 60.0)]
    for pair in report.pairs:
        assert max(pair.relative_error.values()) < FLOAT_PRECISION, pair
    assert {row["verdict"] for row in report.groups.values()} == {"exact (float precision)"}
    twins = report.constructed
    assert (twins.source, twins.dataset, twins.climbs, twins.step_deg) == (
        "hexa-drawn",
        "hexa-drawn-twins2",
        2,
        60.0,
    )
    assert twins.reproduced  # the originals simulated again are the source's bytes


def test_twins_turn_the_yaw_only(drawn_hexa):
    scenarios = twins_dataset(drawn_hexa, 2).scenarios
    for original, twin in zip(scenarios[::2], scenarios[1::2]):
        assert twin == {**original, "yaw_deg": (original["yaw_deg"] + 60.0) % 360.0}
    assert [s["seed"] for s in scenarios[::2]] == [3, 4]  # climbs 0 and 1 of three


def test_the_twins_dataset_is_reused_and_a_damaged_one_mended(drawn_hexa, monkeypatch):
    import symbench.core.data.generation.generate as generation

    first = twins_dataset(drawn_hexa, 2)

    def refuse(*args, **kwargs):
        raise AssertionError("the cached twins were simulated again")

    with monkeypatch.context() as patch:
        patch.setattr(generation, "generate", refuse)
        again = twins_dataset(drawn_hexa, 2)
    assert again.id == "hexa-drawn-twins2" and again.content_hash == first.content_hash
    assert again.metadata["repair_command"] == "symbench data symmetry hexa-drawn --twins 2"
    (first.root / first.metadata["trajectories"][1]["file"]).unlink()
    assert twins_dataset(drawn_hexa, 2).content_hash == first.content_hash


def _trajectories(dataset) -> dict:
    return {
        int(rec["id"]): read_trajectory(dataset.root / rec["file"], dataset.n_legs)
        for rec in dataset.metadata["trajectories"]
    }


def test_a_twin_with_other_draws_is_not_exact(drawn_hexa):
    """The twin must share its original's seed: another seed draws another start and other
    swings, which the measure sees although the scenarios still pair."""
    derived = twins_dataset(drawn_hexa, 2)
    other_seed = replace(Scenario.from_dict(derived.scenarios[1]), seed=99)
    generate("hexa", "smoke", show_progress=False, scenarios=[other_seed], id_override="other")
    trajectories = _trajectories(derived)
    trajectories[1] = _trajectories(load_dataset("other"))[0]
    spec = derived.spec
    report = measure(
        trajectories, derived.scenarios, spec.group, derived.frames, reading="simulator", spec=spec
    )
    errors = {(p.a, p.b): p.relative_error["torques"] for p in report.pairs}
    assert errors[2, 3] < FLOAT_PRECISION and errors[0, 1] > 1e-3, errors


def test_cli_says_the_pairs_were_constructed(drawn_hexa, tmp_path):
    result = invoke(
        "data", "symmetry", "hexa-drawn", "--twins", "2", "--json", "--output", tmp_path
    )
    assert result.exit_code == 0, result.output
    report = json.loads(result.stdout)
    assert report["image_pairs_were"] == "constructed" and report["image_pairs"] == 2
    assert report["constructed"]["climbs"] == 2 and report["constructed"]["step_deg"] == 60.0
    assert (tmp_path / "symmetry-hexa-drawn-twins2.png").stat().st_size > 0
    text = invoke("data", "symmetry", "hexa-drawn", "--twins", "2", "--output", tmp_path)
    assert text.exit_code == 0, text.output
    assert (
        "image pairs constructed, not found: 2 climbs of hexa-drawn simulated again turned by "
        "one symmetry step (60 degrees of yaw)" in " ".join(text.stdout.split())
    )
    assert "--twins N" in error_line(invoke("data", "symmetry", "hexa-drawn"), 1)


def test_twins_need_a_generated_dataset_and_enough_climbs(drawn_hexa):
    with pytest.raises(SymbenchError, match="takes 1 to 3 climbs of dataset 'hexa-drawn', got 4"):
        twins_dataset(drawn_hexa, 4)
    imported = replace(drawn_hexa, metadata={**drawn_hexa.metadata, "source": "imported"})
    with pytest.raises(SymbenchError, match="imported: its climbs cannot be simulated again"):
        twins_dataset(imported, 2)
