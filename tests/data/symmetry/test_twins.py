"""Image pairs constructed on purpose (`symbench data symmetry ID`, `--twins N`): climbs
drawn as v7 draws them hold none, so some are simulated again under every rotation of the
robot's group. On hexa the twins agree to float precision, below the noise floor; on
`hexa-asym-0.2` (leg 0 20 % heavier) they differ far above it."""

from __future__ import annotations

import json
from dataclasses import replace

import pytest
from cli_invoke import invoke

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
from symbench.core.data.twins import symmetry_report, twin_symmetry, twins_dataset
from symbench.core.sim.scene.scenario import Scenario

ROTATIONS = [60.0, 120.0, 180.0, 240.0, 300.0]  # hexa's rotations but the identity


def test_drawn_climbs_hold_no_image_pairs_and_the_error_names_the_command(drawn_hexa):
    with pytest.raises(NoImagePairsError, match="`symbench data symmetry hexa-drawn` constructs"):
        dataset_symmetry(drawn_hexa)


def test_constructed_twins_are_images_under_every_rotation_at_float_precision(drawn_hexa):
    report = twin_symmetry(drawn_hexa, 2)
    angles = dict(rotation_angles(drawn_hexa.spec.group, drawn_hexa.frames))
    turns: dict[tuple[int, int], float] = {
        (p.a, p.b): round(angles[p.element], 9) for p in report.pairs
    }
    # every two of a climb's six copies pair, under the rotation between their yaws
    assert turns == {
        (6 * c + i, 6 * c + j): 60.0 * (j - i)
        for c in (0, 1)
        for i in range(6)
        for j in range(i + 1, 6)
    }
    for pair in report.pairs:
        assert max(pair.relative_error.values()) < FLOAT_PRECISION, pair
    for row in report.groups.values():
        assert row["verdict"] == "exact (float precision)" and row["ratio"] < 1, row
    twins = report.constructed
    assert (twins.source, twins.dataset, twins.climbs, twins.of) == (
        "hexa-drawn",
        "hexa-drawn-twins2",
        2,
        3,
    )
    assert (twins.step_deg, twins.rotations, twins.found_none) == (60.0, 5, False)
    assert twins.reproduced  # the originals simulated again are the source's bytes


def test_twins_turn_the_yaw_only(drawn_hexa):
    scenarios = twins_dataset(drawn_hexa, 2).scenarios
    originals = scenarios[::6]
    assert [s["seed"] for s in originals] == [3, 4]  # climbs 0 and 1 of three
    for c, original in enumerate(originals):
        assert list(scenarios[6 * c : 6 * c + 6]) == [
            {**original, "yaw_deg": (original["yaw_deg"] + turn) % 360.0}
            for turn in [0.0, *ROTATIONS]
        ]


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
    assert errors[0, 1] > 1e-3 and errors[1, 2] > 1e-3, errors
    assert errors[0, 2] < FLOAT_PRECISION and errors[6, 7] < FLOAT_PRECISION, errors


def test_cli_says_the_pairs_were_constructed(drawn_hexa, tmp_path):
    """Asked for (`--twins 2`), and without asking on a dataset that holds no pairs (all
    three climbs, fewer than the default eight)."""
    result = invoke(
        "data", "symmetry", "hexa-drawn", "--twins", "2", "--json", "--output", tmp_path
    )
    assert result.exit_code == 0, result.output
    report = json.loads(result.stdout)
    assert report["image_pairs_were"] == "constructed" and report["image_pairs"] == 30
    made = report["constructed"]
    assert (made["climbs"], made["rotations"], made["source_holds_none"]) == (2, 5, False)
    assert (tmp_path / "symmetry-hexa-drawn-twins2.png").stat().st_size > 0
    text = invoke("data", "symmetry", "hexa-drawn", "--output", tmp_path)
    assert text.exit_code == 0, text.output
    assert (
        "image pairs constructed on purpose, not found (the dataset itself holds none): 3 of "
        "the 3 climbs of hexa-drawn, evenly spaced, simulated again beside their images under "
        "each of the group's 5 rotations (the yaw turned by multiples of 60 degrees), kept as "
        "hexa-drawn-twins3; the originals simulated again match the source's files"
        in " ".join(text.stdout.split())
    )
    assert "45 image pairs among 18 trajectories" in " ".join(text.stdout.split())


def test_twins_need_a_generated_dataset_and_enough_climbs(drawn_hexa):
    with pytest.raises(SymbenchError, match="takes 1 to 3 climbs of dataset 'hexa-drawn', got 4"):
        twins_dataset(drawn_hexa, 4)
    imported = replace(drawn_hexa, metadata={**drawn_hexa.metadata, "source": "imported"})
    with pytest.raises(SymbenchError, match="imported: its climbs cannot be simulated again"):
        twins_dataset(imported, 2)
    with pytest.raises(NoImagePairsError, match="'hexa-drawn' has no pair of trajectories"):
        symmetry_report(imported)  # found none, and none can be constructed


@pytest.fixture(scope="module")
def drawn_asymmetric(tmp_path_factory):
    """One climb of `hexa-asym-0.2`, drawn as v7 draws them, in a private home."""
    home = tmp_path_factory.mktemp("asym") / "home"
    with pytest.MonkeyPatch.context() as patch:
        patch.setenv("SYMBENCH_HOME", str(home))
        climb = Scenario("hexa-asym-0.2", 62.5, 31.25, 12.75, 23.5, None, 3, 0.4, gait_spread=0.2)
        generate(
            "hexa-asym-0.2", "smoke", show_progress=False, scenarios=[climb], id_override="asym"
        )
    return home


def test_the_twins_of_an_asymmetric_robot_measure_asymmetric(drawn_asymmetric, monkeypatch):
    """Leg 0 20 % heavier: every rotation moves it, so every twin differs from its original
    far above the noise floor, the torques most; the symmetric robot's twins of the same climb
    do not (the test above)."""
    monkeypatch.setenv("SYMBENCH_HOME", str(drawn_asymmetric))
    report = symmetry_report(load_dataset("asym"))
    assert report.constructed.found_none and len(report.pairs) == 15
    assert min(p.relative_error["torques"] for p in report.pairs) > 1e-2
    torques = report.groups["torques"]
    assert torques["verdict"].startswith("asymmetric") and torques["ratio"] > 10, torques
