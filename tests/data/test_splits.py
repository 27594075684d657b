"""Standard splits: by trajectory, validation from the training side, deterministic."""

from __future__ import annotations

import dataclasses
import itertools
import math

import numpy as np
import pytest
from synthetic_raw import fake_simulate

from symbench import hookimpl
from symbench.core.common.errors import SymbenchError
from symbench.core.config.presets import dataset_id, preset
from symbench.core.data import load_dataset
from symbench.core.data.generation.generate import generate
from symbench.core.data.splits import SplitContext, check_split, column_split
from symbench.core.plugin import registry
from symbench.core.plugin.entries import SplitEntry
from symbench.core.plugin.host import PluginHost, set_host
from symbench.core.robot.specs import load_robot
from symbench.plugins.splits.assign import (
    iid_test_size,
    unseen_gait,
    unseen_inclination,
    unseen_rotation,
)

STANDARD = (
    "iid",
    "unseen-heading",
    "unseen-rotation",
    "orbit-rotation",
    "unseen-inclination",
    "unseen-gait",
    "fraction-0.1",
    "fraction-0.25",
    "fraction-0.5",
    "fraction-0.75",
    "control-heading",
    "control-rotation",
    "control-inclination",
    "control-gait",
)
# small and smoke vary neither slope nor gait
TRANSFER_ONLY = (
    "unseen-inclination",
    "unseen-gait",
    "control-inclination",
    "control-gait",
)


def short_grid(robot: str, key: str = "small@v6", seconds: float = 0.1):
    """A preset's scenarios (v6's small grid unless `key` names another), shortened so that
    the stand-in makes them in milliseconds (here, not in tests/data/conftest.py: `from
    conftest import` finds whichever conftest module was imported last, tests/run's when tests
    of several folders are named)."""
    spec = load_robot(robot)
    grid = preset(key).scenarios(robot, spec.n_legs, spec.group.rotation_order)
    return [dataclasses.replace(s, seconds=seconds) for s in grid]


def preset_context(robot: str, key: str) -> SplitContext:
    """A split's view of a preset's scenarios under its dataset id, without simulating them:
    a v6 grid (`small@v6`: the grid rules) or v7 drawn climbs (`transfer`: the continuous
    rules)."""
    grid = short_grid(robot, key)
    return SplitContext(
        dataset_id=dataset_id(robot, key),
        trajectory_ids=np.arange(len(grid)),
        scenarios=tuple(s.to_dict() for s in grid),
        n_samples=np.ones(len(grid), dtype=int),
        rotation_order=load_robot(robot).group.rotation_order,
        seed=0,
    )


@pytest.fixture(scope="module")
def grids_home(tmp_path_factory):
    """A private home holding the two short grids, made once: the tests only read them."""
    home = tmp_path_factory.mktemp("grids") / "home"
    with pytest.MonkeyPatch.context() as patch:
        patch.setenv("SYMBENCH_HOME", str(home))
        for grid, did in (("small@v6", "hexa-short-v6"), ("transfer@v6", "hexa-transfer-short-v6")):
            generate(
                "hexa",
                grid,
                simulator=fake_simulate,
                show_progress=False,
                scenarios=short_grid("hexa", grid),
                id_override=did,
            )
    return home


@pytest.fixture
def hexa_small(grids_home, monkeypatch):
    monkeypatch.setenv("SYMBENCH_HOME", str(grids_home))
    return load_dataset("hexa-short-v6")


def _scenario(ds, ids, field):
    by_id = dict(zip(ds.trajectory_ids.tolist(), ds.scenarios))
    return {by_id[i][field] for i in ids.tolist()}


def test_the_standard_splits_are_registered():
    assert set(STANDARD) <= set(registry.collect("splits"))


@pytest.fixture
def hexa_transfer(grids_home, monkeypatch):
    monkeypatch.setenv("SYMBENCH_HOME", str(grids_home))
    return load_dataset("hexa-transfer-short-v6")


@pytest.mark.parametrize("name", STANDARD)
def test_parts_are_disjoint_deterministic_and_select_whole_trajectories(
    hexa_small, hexa_transfer, name
):
    # small varies neither slope nor gait; the transfer grid is made for those two splits
    data = hexa_transfer if name in TRANSFER_ONLY else hexa_small
    _check_parts(data, name)


def _check_parts(data, name):
    parts = data.split_indices(name, seed=3)
    ids = np.concatenate([parts.train, parts.val, parts.test])
    assert len(np.unique(ids)) == len(ids)
    assert min(len(parts.train), len(parts.val), len(parts.test)) >= 1
    again = data.split_indices(name, seed=3)
    assert again.to_dict() == parts.to_dict()
    train, val, test = data.split_views("leg_grouped", "acc", name, seed=3)
    assert set(np.unique(train.trajectory)) == set(parts.train.tolist())
    assert set(np.unique(test.trajectory)) == set(parts.test.tolist())
    per_traj = dict(zip(data.trajectory_ids.tolist(), data.n_samples.tolist()))
    assert len(val) == sum(per_traj[i] for i in parts.val.tolist())  # whole trajectories


def test_seeds_change_iid_but_nothing_else_changes_it(hexa_small):
    a, b = hexa_small.split_indices("iid", 0), hexa_small.split_indices("iid", 1)
    assert a.test.tolist() != b.test.tolist()
    assert len(a.test) == len(b.test) == round(0.2 * 96)


def test_unseen_heading_holds_out_whole_headings(hexa_small):
    parts = hexa_small.split_indices("unseen-heading", 0)
    train = _scenario(hexa_small, parts.train, "heading_deg")
    assert train == {0.0}
    assert _scenario(hexa_small, parts.val, "heading_deg") <= train
    assert _scenario(hexa_small, parts.test, "heading_deg") == {180.0}


def test_orbit_rotation_tests_the_images_of_one_fundamental_sector(hexa_small):
    parts = hexa_small.split_indices("orbit-rotation", 0)
    # hexa: sector [0, 60) holds yaws 0, 15, 30 and 45; the rest are their symmetric images
    sector = {0.0, 15.0, 30.0, 45.0}
    assert _scenario(hexa_small, parts.train, "yaw_deg") == sector
    assert _scenario(hexa_small, parts.val, "yaw_deg") <= sector
    assert _scenario(hexa_small, parts.test, "yaw_deg") == {15.0 * k for k in range(4, 24)}


def test_unseen_rotation_tests_yaws_between_the_training_yaws(hexa_small):
    parts = hexa_small.split_indices("unseen-rotation", 0)
    # every other yaw of [0, 60) trains; in the other sectors, the yaws halfway between test
    assert _scenario(hexa_small, parts.train, "yaw_deg") == {0.0, 30.0}
    assert _scenario(hexa_small, parts.val, "yaw_deg") <= {0.0, 30.0}
    test = {60.0 * k + offset for k in range(1, 6) for offset in (15.0, 45.0)}
    assert _scenario(hexa_small, parts.test, "yaw_deg") == test


@pytest.mark.parametrize("robot", ["magneto", "hexa", "nona"])
def test_no_unseen_rotation_test_climb_is_an_image_of_a_training_climb(robot):
    """On every robot's small grid: the test yaws, taken into the first sector, lie strictly
    between training yaws, outside the first sector, and both sets are closed under the
    mirrors (offset -> -offset), so no test climb is a rotated or mirrored training climb."""
    spec = load_robot(robot)
    order = spec.group.rotation_order
    width = 360.0 / order
    yaws = np.array([s.yaw_deg for s in short_grid(robot)])
    context = SplitContext(
        dataset_id=f"{robot}-climb-small-v6",
        trajectory_ids=np.arange(len(yaws)),
        scenarios=tuple({"yaw_deg": y} for y in yaws),
        n_samples=np.ones(len(yaws), dtype=int),
        rotation_order=order,
        seed=0,
    )
    labels = unseen_rotation(context)
    offsets = np.round(np.mod(yaws, width), 6) % round(width, 6)
    trained = set(offsets[np.isin(labels, ["train", "val"])].tolist())
    tested = set(offsets[labels == "test"].tolist())
    assert len(trained) >= 2 and tested and not trained & tested
    assert (yaws[np.isin(labels, ["train", "val"])] < width).all()
    assert (yaws[labels == "test"] >= width).all()
    for offsets_ in (trained, tested):
        assert {round((width - o) % width, 6) for o in offsets_} == offsets_
    between = sorted(trained) + [width]
    assert all(any(a < o < b for a, b in itertools.pairwise(between)) for o in tested)


@pytest.mark.parametrize("robot", ["magneto", "hexa", "nona"])
def test_no_unseen_rotation_test_climb_is_an_image_on_v7_drawn_climbs(robot):
    """On every robot's v7 small climbs (drawn from continuous distributions): the fundamental
    sector trains, iid's test size of the climbs outside it test, and no test climb is a
    rotated or mirrored image of a training climb: not even their yaws' offsets within the
    sector (nor those offsets mirrored) meet."""
    context = preset_context(robot, "small")
    assert context.version == 7
    width = 360.0 / context.rotation_order
    labels = unseen_rotation(context)
    yaws = context.values("yaw_deg").astype(float)
    seen = np.isin(labels, ["train", "val"])
    test = labels == "test"
    assert (yaws[seen] < width).all() and seen.sum() == (yaws < width).sum()
    assert (yaws[test] >= width).all()
    assert test.sum() == iid_test_size(len(yaws))
    offsets = np.round(np.mod(yaws, width), 6)
    trained = set(offsets[seen].tolist())
    for o in offsets[test].tolist():
        assert o not in trained and round((width - o) % width, 6) not in trained


@pytest.mark.parametrize("robot", ["magneto", "hexa", "nona"])
def test_unseen_inclination_tests_slopes_beyond_every_training_slope(robot):
    """On every robot's transfer grid: floor to wall trains, overhangs and the ceiling test;
    every other field's values are on both sides, so only the slope is held out."""
    context = preset_context(robot, "transfer@v6")
    labels = unseen_inclination(context)
    inclinations = context.values("inclination_deg").astype(float)
    seen = np.isin(labels, ["train", "val"])
    assert set(inclinations[seen].tolist()) == {0.0, 30.0, 60.0, 90.0}
    assert set(inclinations[labels == "test"].tolist()) == {120.0, 150.0, 180.0}
    assert inclinations[labels == "test"].min() > inclinations[seen].max()
    for field in ("yaw_deg", "direction"):
        values = np.array([str(v) for v in context.values(field)])
        assert set(values[seen]) == set(values[labels == "test"]), field


@pytest.mark.parametrize("robot", ["magneto", "hexa", "nona"])
def test_unseen_inclination_on_v7_drawn_climbs_tests_slopes_beyond_every_training_slope(robot):
    """On every robot's v7 transfer climbs (slopes drawn from floor to ceiling): the steepest
    third of the slopes is held out and iid's test size of those climbs test, every test
    slope beyond every training slope; the other fields' draws span both sides."""
    context = preset_context(robot, "transfer")
    assert context.version == 7
    labels = unseen_inclination(context)
    inclinations = context.values("inclination_deg").astype(float)
    seen = np.isin(labels, ["train", "val"])
    test = labels == "test"
    assert test.sum() == iid_test_size(len(labels))
    assert inclinations[test].min() > inclinations[seen].max()
    assert (inclinations[labels == "unused"] > inclinations[seen].max()).all()
    assert seen.sum() == len(labels) - math.ceil(len(labels) / 3)
    for field in ("yaw_deg", "heading_deg"):
        values = context.values(field).astype(float)
        for part in (seen, test):  # both halves of the circle on each side
            assert (values[part] < 180.0).any() and (values[part] >= 180.0).any(), field


@pytest.mark.parametrize("robot", ["magneto", "hexa", "nona"])
def test_no_unseen_gait_test_climb_is_a_rotated_training_climb(robot):
    """On every robot's transfer grid the test climbs step in the reversed order, the training
    climbs in the default one, and no rotation of the robot's group relabels the one sequence
    into the other (as cyclic sequences): a test gait is never a rotated training gait."""
    context = preset_context(robot, "transfer@v6")
    labels = unseen_gait(context)
    n_legs = load_robot(robot).n_legs
    orders = [tuple(s["leg_order"] or range(n_legs)) for s in context.scenarios]
    seen = np.isin(labels, ["train", "val"])
    assert {o for o, s in zip(orders, seen) if s} == {tuple(range(n_legs))}
    tested = {o for o, s in zip(orders, labels == "test") if s}
    assert tested == {tuple(range(n_legs - 1, -1, -1))}

    def cyclic_forms(order):
        return {order[k:] + order[:k] for k in range(len(order))}

    rotations = [g for g in load_robot(robot).group if not g.reflect]
    assert len(rotations) == load_robot(robot).group.rotation_order
    for g in rotations:
        relabelled = {tuple(g.perm[leg] for leg in o) for o in tested}
        assert not any(cyclic_forms(o) & cyclic_forms(tuple(range(n_legs))) for o in relabelled)


GAIT_REFUSED = "unseen-gait needs climbs with the default leg order and climbs with"


@pytest.mark.parametrize(
    ("split", "key", "message"),
    [
        (
            unseen_inclination,
            "small@v6",
            "unseen-inclination needs at least 2 inclinations, found \\[90.0\\]",
        ),
        (unseen_gait, "small@v6", GAIT_REFUSED),
        (unseen_gait, "small", GAIT_REFUSED),  # v7 small: slopes drawn in a band, one gait
    ],
)
def test_the_slope_and_gait_splits_refuse_a_grid_without_either(split, key, message):
    with pytest.raises(SymbenchError, match=message):
        split(preset_context("hexa", key))


def test_fractions_are_nested_and_share_the_iid_test_set(hexa_small):
    iid = hexa_small.split_indices("iid", 5)
    previous: set[int] = set()
    for share in (0.1, 0.25, 0.5, 0.75):
        part = hexa_small.split_indices(f"fraction-{share:g}", 5)
        assert part.test.tolist() == iid.test.tolist()
        assert part.val.tolist() == iid.val.tolist()
        train = set(part.train.tolist())
        assert previous <= train <= set(iid.train.tolist())
        assert len(train) == int(np.ceil(share * len(iid.train)))
        previous = train


def test_smoke_supports_every_standard_split(smoke_hexa):
    """The smoke preset's 6 trajectories (headings 0 and 180 x yaws 0, 180 and 250) give every
    standard split but the slope and gait ones non-empty, disjoint parts that hold out what
    the split promises."""
    ds = load_dataset(smoke_hexa.dataset_id)
    assert ds.trajectory_ids.tolist() == [0, 1, 2, 3, 4, 5]
    parts = {name: ds.split_indices(name, 0) for name in STANDARD if name not in TRANSFER_ONLY}
    for name, part in parts.items():
        train, val, test = (set(ids.tolist()) for ids in (part.train, part.val, part.test))
        assert min(len(train), len(val), len(test)) >= 1, name
        assert len(train | val | test) == len(train) + len(val) + len(test), name
        assert train | val | test <= set(range(6)), name
    iid = parts["iid"]
    assert (len(iid.train), len(iid.val), len(iid.test)) == (4, 1, 1)
    # hexa: 180 is an image of 0, 250 lies between images of 0; from v7 (smoke stays a grid)
    # orbit-rotation tests the exact images only
    grid_rules = ds.split_context(0).version <= 6
    held_out = {
        ("unseen-heading", "heading_deg"): {180.0},
        ("unseen-rotation", "yaw_deg"): {250.0},
        ("orbit-rotation", "yaw_deg"): {180.0, 250.0} if grid_rules else {180.0},
    }
    for (split, field), values in held_out.items():
        seen = np.concatenate([parts[split].train, parts[split].val])
        assert _scenario(ds, seen, field) == {0.0}, split
        assert _scenario(ds, parts[split].test, field) == values, split
    for share in (0.1, 0.25, 0.5, 0.75):
        part = parts[f"fraction-{share:g}"]
        assert (part.val.tolist(), part.test.tolist()) == (iid.val.tolist(), iid.test.tolist())
        assert set(part.train.tolist()) <= set(iid.train.tolist())
        assert len(part.train) == int(np.ceil(share * len(iid.train)))


def test_a_split_plugin_is_used_and_its_mistakes_are_named(hexa_small):
    class Plugin:
        @hookimpl
        def symbench_splits(self):
            return [
                SplitEntry(
                    "first-half",
                    lambda ctx: np.where(
                        ctx.trajectory_ids < 20,
                        "train",
                        np.where(ctx.trajectory_ids < 30, "val", "test"),
                    ),
                ),
                SplitEntry("bad-label", lambda ctx: ["training"] * len(ctx.trajectory_ids)),
                SplitEntry("no-test", lambda ctx: ["train"] * len(ctx.trajectory_ids)),
            ]

    host = PluginHost()
    host.load_entry_points("none")  # the built-ins (robots, splits) ...
    host.register(Plugin(), "mine")  # ... and one in-process plugin
    set_host(host)
    try:
        parts = hexa_small.split_indices("first-half", 0)
        assert parts.train.tolist() == list(range(20)) and len(parts.test) == 66
        with pytest.raises(SymbenchError, match="unknown label"):
            hexa_small.split_indices("bad-label", 0)
        with pytest.raises(SymbenchError, match="test empty"):
            hexa_small.split_indices("no-test", 0)
        with pytest.raises(SymbenchError, match="unseen-rotation"):
            hexa_small.split_indices("unseen-rotatoin", 0)
    finally:
        set_host(None)


def test_a_column_split_name_writes_every_digit_and_parses_back():
    """Found by the property suite: `:g` named --test 1000000 `heading_0_vs_1e+06`, which
    check_split then called unknown, and rounded 12.3456789 to 12.3457."""
    split = column_split("heading", ["0"], ["1000000"])
    assert split.name == "heading_0_vs_1000000"
    check_split(split.name)
    assert column_split("yaw", ["12.3456789"], ["-0.00001"]).name == "yaw_12.3456789_vs_m0.00001"
    with pytest.raises(SymbenchError, match="allows 20 per value"):
        column_split("yaw", ["1e300"], ["0"])
