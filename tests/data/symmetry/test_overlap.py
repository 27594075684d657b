"""The image-overlap diagnostic (symmetry/compare.py, symmetry/overlap.py): which held-out
climbs are images of training climbs under each class of symmetries, judged on raw states.

Synthetic climbs (random raw states, so no two are alike by accident) and their images made
with the raw action check each class's verdict; the v6 smoke dataset, simulated, checks the
shares and motion counts its grid implies (on a wall the two headings are images, and yaws
0 and 180 are images under hexa's rotations; 250 is an image of neither).
"""

from __future__ import annotations

import json

import numpy as np
import pytest
from cli_invoke import invoke
from synthetic_raw import synthetic_raw

from symbench.core.common.errors import SymbenchError
from symbench.core.data.symmetry.compare import (
    CLASSES,
    COMPARED,
    EXACT_TOLERANCE,
    NEAR_TOLERANCE,
    Climbs,
)
from symbench.core.data.symmetry.overlap import DatasetOverlap, distinct_motions, image_counts
from symbench.core.data.symmetry.raw_action import act_on_raw, rotate_scene_about_gravity
from symbench.core.data.symmetry.report import GROUPS
from symbench.core.data.symmetry.screen import SCREEN_MARGIN
from symbench.core.data.views.frames import LegFrames
from symbench.core.robot.specs import load_robot

ROBOTS = ("magneto", "hexa", "nona")
HEADING = 0.7  # rad: any turn about gravity, not a multiple of a symmetry angle


def _perturbed(raw: dict[str, np.ndarray], share: float, seed: int = 5) -> dict[str, np.ndarray]:
    """`raw` with white noise of `share` of each compared column's RMS added."""
    rng = np.random.default_rng(seed)
    out = dict(raw)
    for column in COMPARED:
        x = np.asarray(raw[column], np.float64)
        out[column] = x + rng.normal(scale=share * np.sqrt(np.mean(x**2)), size=x.shape)
    return out


def _images(robot: str) -> tuple[Climbs, dict[str, int]]:
    """Training climbs 0 (`base`) and 1 (unrelated) and, by name, images of climb 0."""
    spec = load_robot(robot)
    frames = LegFrames.from_spec(spec)
    assert spec.geometry_group.has_reflections
    rotation = next(g for g in spec.group if not g.reflect and g != spec.group.identity)
    reflection = next(g for g in spec.geometry_group if g.reflect)
    base = synthetic_raw(spec.n_legs, 150, seed=1)
    twin = act_on_raw(rotation, base, frames)
    made = {
        "copy": base,
        "heading": rotate_scene_about_gravity(base, HEADING),
        "twin": twin,
        "turned twin": rotate_scene_about_gravity(twin, HEADING),
        "mirrored": act_on_raw(reflection, base, frames),
        "near twin": _perturbed(twin, 0.01),  # far above the exact tolerance, within near
        "far twin": _perturbed(twin, 0.3),  # beyond near
        "other": synthetic_raw(spec.n_legs, 150, seed=3),
        # the joints' states as the base climb's, the base elsewhere: only the base group
        # tells them apart, so no early stop may skip it
        "base moved": {**base, "base_pos": np.asarray(base["base_pos"]) + 0.5},
    }
    raw = {0: base, 1: synthetic_raw(spec.n_legs, 150, seed=2)}
    ids = {}
    for k, (name, climb) in enumerate(made.items(), start=10):
        raw[k] = climb
        ids[name] = k
    return Climbs(raw, spec.group, spec.geometry_group, frames), ids


# which classes count each construction as an image: exactly, and within the near tolerance
EXPECTED = {
    "copy": ({"none", "heading", "group", "mirror"}, {"none", "heading", "group", "mirror"}),
    "heading": ({"heading", "group", "mirror"}, {"heading", "group", "mirror"}),
    "twin": ({"group", "mirror"}, {"group", "mirror"}),
    "turned twin": ({"group", "mirror"}, {"group", "mirror"}),
    "mirrored": ({"mirror"}, {"mirror"}),
    "near twin": (set(), {"group", "mirror"}),
    "far twin": (set(), set()),
    "other": (set(), set()),
    "base moved": (set(), set()),
}


@pytest.mark.parametrize("robot", ROBOTS)
def test_each_class_counts_the_images_it_respects(robot):
    climbs, ids = _images(robot)
    for name, (exact, near) in EXPECTED.items():
        counts = image_counts(climbs, [ids[name]], [0, 1])
        assert {c for c in CLASSES if counts[c][0]} == exact, name
        assert {c for c in CLASSES if counts[c][1]} == near, name


def test_errors_bracket_the_tolerances():
    """An exact twin agrees to float precision, the near twin lies between the tolerances."""
    climbs, ids = _images("hexa")
    group = CLASSES.index("group")
    assert climbs.class_error(0, ids["turned twin"], group) < 1e-12
    near = climbs.class_error(0, ids["near twin"], group)
    assert 100 * EXACT_TOLERANCE < near < NEAR_TOLERANCE
    assert climbs.class_error(0, ids["other"], CLASSES.index("mirror")) > NEAR_TOLERANCE


@pytest.mark.parametrize("robot", ROBOTS)
def test_an_early_stop_changes_no_error_at_or_below_where_it_stops(robot):
    """Stopped above a threshold, an element's error is a lower bound above it; at or
    below it, the whole error, bit for bit: so no count at either tolerance can change."""
    climbs, ids = _images(robot)
    stops = 0
    for k in ids.values():
        for tier in climbs.tiers:
            for g, heading in tier:
                whole = climbs.element_error(0, k, g, heading)
                stopped = climbs.element_error(0, k, g, heading, NEAR_TOLERANCE)
                if whole <= NEAR_TOLERANCE:
                    assert stopped == whole
                else:
                    assert NEAR_TOLERANCE < stopped <= whole
                    stops += stopped < whole
    assert stops > 0  # some comparison did stop before its last group


@pytest.mark.parametrize("robot", ROBOTS)
def test_the_screen_gives_every_elements_joint_error(robot):
    """The screen's expanded form (one matrix of leg inner products per pair and shift) is
    the joint-state group's error under every element, mirrors' joint signs included, to well
    within its margin: a wrong relabelling, sign or norm would be off by orders more."""
    climbs, ids = _images(robot)
    joints = GROUPS["joint states"]
    checked = 0
    for k in ids.values():
        for tier in climbs.tiers:
            for g, _ in tier:
                src, signs = climbs.legs(g)
                shift = climbs._shift(0, k, None if g == climbs.group.identity else g)
                moved = {c: climbs.joints(0)[c][:, src, :] * (1 if signs is None else signs)
                         for c in joints}  # fmt: skip
                exact = climbs._group_error(moved, climbs.joints(k), joints, shift)
                screened = climbs.screen(0, k, shift, src, signs)
                # within a tenth of the margin, even for the twins (exact ~1e-13) where the
                # expanded form rounds worst
                assert abs(screened - exact) < SCREEN_MARGIN / 10, (k, g, screened, exact)
                checked += 1
    assert checked == len(ids) * sum(len(t) for t in climbs.tiers)


def test_distinct_motions_gather_images_per_class():
    climbs, ids = _images("hexa")
    side = [0, ids["heading"], ids["twin"], ids["mirrored"], ids["near twin"], ids["other"]]
    exact = [distinct_motions(climbs, side, k, EXACT_TOLERANCE) for k in range(len(CLASSES))]
    near = [distinct_motions(climbs, side, k, NEAR_TOLERANCE) for k in range(len(CLASSES))]
    # none: all 6; heading: the turned scene joins climb 0; group: the twin too; mirror: the
    # mirrored copy too; at the near tolerance the near twin joins the twin under every class
    assert exact == [6, 5, 4, 3]
    assert near == [5, 4, 3, 2]


def _motion(scenario: dict, cls: str) -> tuple:
    """What the smoke grid says a climb is up to `cls`: its yaw and heading (none), its yaw
    (heading: on a wall the two headings are images), its yaw modulo hexa's 60 degrees."""
    yaw, heading = scenario["yaw_deg"], scenario["heading_deg"]
    return {"none": (yaw, heading), "heading": (yaw,)}.get(cls, (yaw % 60,))


@pytest.mark.parametrize("split", ["iid", "unseen-rotation", "orbit-rotation", "unseen-heading"])
def test_smoke_shares_and_motions_follow_the_grid(simulated_smoke_hexa, split):
    ds = simulated_smoke_hexa
    by_id = dict(zip(ds.trajectory_ids.tolist(), ds.scenarios, strict=True))
    parts = ds.split_indices(split, 0)
    found = DatasetOverlap(ds).split(split, 0).to_dict()
    for side in ("train", "val", "test"):
        ids = getattr(parts, side).tolist()
        if not ids:
            continue
        for cls in CLASSES:
            row = found["sides"][side]["classes"][cls]
            motions = {_motion(by_id[i], cls) for i in ids}
            assert row["distinct_motions_exact"] == row["distinct_motions_near"] == len(motions)
            if side == "train":
                continue
            seen = {_motion(by_id[i], cls) for i in parts.train.tolist()}
            images = sum(_motion(by_id[i], cls) in seen for i in ids)
            assert row["exact_images"] == row["near_images"] == images, (side, cls)
    test = found["sides"]["test"]["classes"]
    if split == "unseen-rotation":  # yaws never seen, up to rotations too
        assert test["group"]["exact_image_share"] == 0.0
    if split == "iid":
        assert test["none"]["exact_image_share"] == 0.0  # no climb is simulated twice


def test_unknown_columns_are_refused_in_one_line(smoke_hexa):
    from symbench.core.data.dataset import load_dataset

    ds = load_dataset(smoke_hexa.dataset_id)
    ds.metadata["unknown_columns"] = ["qdd"]
    with pytest.raises(SymbenchError) as caught:
        DatasetOverlap(ds).split("iid", 0)
    message = str(caught.value)
    assert "\n" not in message
    assert f"dataset '{ds.id}', split 'iid'" in message and "qdd" in message


def test_data_info_shows_the_overlap_per_split(smoke_hexa):
    result = invoke("data", "info", smoke_hexa.dataset_id, "--json")
    assert result.exit_code == 0, result.output
    splits = json.loads(result.stdout)["splits"]
    iid = splits["iid"]["image_overlap"]
    assert set(iid["sides"]["test"]["classes"]) == set(CLASSES)
    assert iid["sides"]["test"]["climbs"] == splits["iid"]["test"]["trajectories"]
    shown = invoke("data", "info", smoke_hexa.dataset_id)
    assert shown.exit_code == 0 and "image overlap" in shown.stdout
    quiet = invoke("data", "info", smoke_hexa.dataset_id, "--json", "--no-overlap")
    assert "image_overlap" not in json.loads(quiet.stdout)["splits"]["iid"]


def test_imported_logs_of_other_lengths_are_images_on_their_aligned_rows(home):
    """magneto's logged gaits (tests/data/symmetry/logs): climb 1 is climb 0 turned by the
    half turn, its log 42 rows longer; climbs 0 and 2 step in other
    orders. The verdict reads only the raw states, aligned on their lift-offs."""
    from pathlib import Path

    from symbench.core.data.importing.importer import import_logs

    ds = import_logs(Path(__file__).parent / "logs" / "magneto-gaits", "gaits")
    climbs = DatasetOverlap(ds).climbs()
    assert len(climbs.raw[0]["t"]) != len(climbs.raw[1]["t"])
    group, heading = CLASSES.index("group"), CLASSES.index("heading")
    assert climbs.class_error(0, 1, group) < EXACT_TOLERANCE
    assert climbs.class_error(0, 1, heading) > NEAR_TOLERANCE
    assert climbs.class_error(0, 2, CLASSES.index("mirror")) > NEAR_TOLERANCE
