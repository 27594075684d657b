"""Image pairs of logged climbs (issue 42, items 5-7): leg orders and directions mapped by the
group element, phases aligned, and no verdict from repeats that are not one motion.

tests/data/symmetry/logs/magneto-gaits/ (made by make_log.py beside it) holds four magneto
wall climbs whose leg orders are logged as stepped: `a` (yaw 0, legs 0, 1, 3, 2) and its
image `b` under the half turn (yaw 180, legs 2, 3, 1, 0), logged 42 rows later in its gait
and 42 rows longer; `c` (yaw 0, legs 2, 3, 1, 0) and its image `d` (yaw 180, legs 0, 1, 3, 2),
in phase. `a` and `d` log the same list at yaws 180 degrees apart but are no images.
"""

from __future__ import annotations

import json
import shutil
from pathlib import Path

import numpy as np
import pytest

from symbench.core.data.symmetry.measure import measure
from symbench.core.data.symmetry.pairing import find_pairs, rotation_angles
from symbench.core.data.views.frames import LegFrames
from symbench.core.robot.specs import load_robot

LOGS = Path(__file__).parent / "logs" / "magneto-gaits"
A, B, C, D = 0, 1, 2, 3  # ids in the manifest's order
LATE_ROWS = 42


@pytest.fixture(scope="module")
def gaits_home(tmp_path_factory):
    """The log set imported twice in a private home: as logged (`gaits`) and without its
    leg orders (`gaits-no-order`)."""
    import os

    from symbench.core.data.importing.importer import import_logs

    home = tmp_path_factory.mktemp("gaits-home")
    before = os.environ.get("SYMBENCH_HOME")
    os.environ["SYMBENCH_HOME"] = str(home)
    import_logs(LOGS, "gaits")
    folder = tmp_path_factory.mktemp("no-order") / "logs"
    shutil.copytree(LOGS, folder)
    manifest = json.loads((folder / "import.json").read_text())
    for entry in manifest["trajectories"]:
        del entry["scenario"]["leg_order"]
    (folder / "import.json").write_text(json.dumps(manifest))
    import_logs(folder, "gaits-no-order")
    yield home
    if before is None:
        del os.environ["SYMBENCH_HOME"]
    else:
        os.environ["SYMBENCH_HOME"] = before


def _report(dataset_id: str):
    from symbench.core.data import load_dataset
    from symbench.core.data.symmetry.report import dataset_symmetry

    return dataset_symmetry(load_dataset(dataset_id))


def _pairs(report) -> set[tuple[int, int]]:
    return {(p.a, p.b) for p in report.pairs}


# item 5: every scenario field mapped by the element


def test_logged_leg_orders_pair_with_their_relabelled_images(gaits_home):
    """Not the climbs that log the same list of legs at yaws 180 degrees apart (a and d, c
    and b), which compared as 'asymmetric' before: the ones whose leg order is relabelled by
    the half turn, which agree to float precision."""
    report = _report("gaits")
    assert _pairs(report) == {(A, B), (C, D)}
    assert {p.element.name for p in report.pairs} == {"shift 2"}
    for row in report.groups.values():
        assert row["verdict"] == "exact (float precision)", row
    assert report.reading == "recorded"


def test_directions_turn_and_leg_orders_relabel_with_the_base():
    """Magneto's half turn: yaw + 180, the body direction turned back by 180 (forward ->
    backward, left -> right), leg i's part played by leg i + 2; a climb logging the same
    direction and order at the other yaw is no image. Hexa's turn by 120 degrees relabels
    leg i as leg i + 4."""
    spec = load_robot("magneto")
    frames = LegFrames.from_spec(spec)
    scenarios = [
        {"yaw_deg": 0.0, "direction": "forward", "leg_order": [0, 1, 3, 2]},
        {"yaw_deg": 180.0, "direction": "backward", "leg_order": [2, 3, 1, 0]},
        {"yaw_deg": 180.0, "direction": "forward", "leg_order": [0, 1, 3, 2]},
        {"yaw_deg": 0.0, "direction": "left", "leg_order": [0, 1, 3, 2]},
        {"yaw_deg": 180.0, "direction": "right", "leg_order": [2, 3, 1, 0]},
    ]
    images, repeats = find_pairs(scenarios, range(5), spec.group, frames)
    assert {(a, b) for a, b, _ in images} == {(0, 1), (3, 4)} and repeats == []

    spec = load_robot("hexa")
    frames = LegFrames.from_spec(spec)
    scenarios = [
        {"yaw_deg": 0.0, "leg_order": [5, 4, 3, 2, 1, 0]},
        {"yaw_deg": 120.0, "leg_order": [3, 2, 1, 0, 5, 4]},
        {"yaw_deg": 120.0, "leg_order": [5, 4, 3, 2, 1, 0]},
    ]
    images, _ = find_pairs(scenarios, range(3), spec.group, frames)
    assert [(a, b, g.perm) for a, b, g in images] == [(0, 1, (4, 5, 0, 1, 2, 3))]
    assert dict(rotation_angles(spec.group, frames))[images[0][2]] == pytest.approx(120.0)


def test_generated_scenarios_pair_as_the_simulator_builds_its_twins():
    """A generated grid (v6's transfer) stores the simulator's input (direction and leg order of the
    yaw's first sector): its images are the scenarios equal but for the yaw, as before."""
    from symbench.core.config.presets import preset

    spec = load_robot("magneto")
    frames = LegFrames.from_spec(spec)
    scenarios = [
        s.to_dict()
        for s in preset("transfer@v6").scenarios("magneto", spec.n_legs, spec.group.rotation_order)
        if s.inclination_deg == 90.0
    ]
    images, _ = find_pairs(scenarios, range(len(scenarios)), spec.group, frames, "simulator", spec)
    expected = {
        (a, b)
        for a in range(len(scenarios))
        for b in range(a + 1, len(scenarios))
        if {k: v for k, v in scenarios[a].items() if k != "yaw_deg"}
        == {k: v for k, v in scenarios[b].items() if k != "yaw_deg"}
        and (scenarios[b]["yaw_deg"] - scenarios[a]["yaw_deg"]) % 180.0 == 0.0  # magneto's C2
    }
    assert {(a, b) for a, b, _ in images} == expected and expected


# item 6: no verdict from a floor of repeats that are not one motion


def test_repeats_that_step_differently_give_no_verdict_and_name_the_field(gaits_home):
    """Without leg orders, a and c (and b and d) look like repeats of one scenario; their
    flags show that they step differently, so their difference is no noise floor."""
    report = _report("gaits-no-order")
    assert report.floor_source == "repeats" and report.repeats == 2
    for row in report.groups.values():
        assert row["verdict"].startswith("no verdict: repeats step differently"), row
        assert "lack a field that tells their motions apart (leg_order?)" in row["verdict"]
        assert not row["floor_informative"]
    assert not any(al.aligned for _, _, al in report.repeat_alignments)


def test_repeats_that_differ_as_much_as_images_give_no_verdict():
    """Repeats as different as two unrelated motions (no flags to tell): the floor is at
    least the image error and of the signal's size."""
    from test_data_symmetry import _smooth_raw, _twins

    spec, frames, trajectories, scenarios = _twins("magneto")
    trajectories[len(trajectories)] = _smooth_raw(spec.n_legs, seed=5)
    scenarios = [*scenarios, scenarios[0]]
    report = measure(trajectories, scenarios, spec.group, frames, "unrelated", "magneto")
    assert report.floor_source == "repeats"
    torques = report.groups["torques"]
    assert torques["relative_floor"] >= max(torques["relative_error"], 0.5)
    assert torques["verdict"] == (
        "no verdict: repeats differ as much as images: the logs lack a field that tells their "
        "motions apart (leg_order?, direction?, seed?, inclination_deg?)"
    )


# item 7: logs of one motion at different phases


def _arrays(dataset_id: str) -> dict[int, dict[str, np.ndarray]]:
    from symbench.core.data import load_dataset
    from symbench.core.data.storage.files import read_trajectory

    dataset = load_dataset(dataset_id)
    return {
        int(rec["id"]): read_trajectory(dataset.root / rec["file"], dataset.n_legs)
        for rec in dataset.metadata["trajectories"]
    }


def test_a_counterpart_at_another_phase_is_aligned_on_the_first_lift_off(gaits_home):
    """b starts 42 rows later in its gait than a and is 42 rows longer: compared row by row
    the two differ by as much as the signal; aligned, they agree to float precision."""
    spec = load_robot("magneto")
    frames = LegFrames.from_spec(spec)
    arrays = _arrays("gaits")
    trajectories = {A: arrays[A], B: arrays[B]}
    assert len(arrays[B]["t"]) == len(arrays[A]["t"]) + LATE_ROWS
    scenarios = [{"yaw_deg": 0.0}, {"yaw_deg": 180.0}]
    report = measure(trajectories, scenarios, spec.group, frames, "phases", "magneto")
    (pair,) = report.pairs
    for row in report.groups.values():
        assert row["verdict"] == "exact (float precision)", row
    assert report.flags == {"contact": 0.0, "magnet": 0.0}
    assert pair.rows == len(arrays[A]["t"]) - LATE_ROWS
    assert (pair.alignment.shift, pair.alignment.aligned) == (-LATE_ROWS, True)
    assert pair.alignment.how == "on the first lift-off" and pair.alignment.flag_mismatch == 0


def test_logs_that_cannot_be_aligned_say_so(gaits_home):
    """a and d step different legs: no shift lines their flags up, and the pair says that it
    was compared row by row."""
    spec = load_robot("magneto")
    frames = LegFrames.from_spec(spec)
    arrays = _arrays("gaits")
    report = measure(
        {A: arrays[A], D: arrays[D]},
        [{"yaw_deg": 0.0}, {"yaw_deg": 180.0}],
        spec.group,
        frames,
        "unaligned",
        "magneto",
    )
    (pair,) = report.pairs
    assert not pair.alignment.aligned and pair.alignment.shift == 0
    assert "compared row by row" in pair.alignment.how
    assert report.unaligned == [pair]
