"""Splits that compare like with like (issue 38): the continuous-draw (v7) definitions of the
generalization splits, their size-matched iid controls, and the v6 grids' splits unchanged.

The v7-like scenario tables are drawn here as the v7 datasets draw them (yaw, slope heading
and step direction uniform on the circle, inclination uniform in a band, leg order uniform
among two, one seed per climb), so no climb is an image of another."""

from __future__ import annotations

import hashlib
import json
from pathlib import Path

import numpy as np
import pytest

from symbench import control_of
from symbench.core.common.errors import SymbenchError, UnknownNameError
from symbench.core.config.presets import preset
from symbench.core.data.splits import SplitContext, SplitIndices, resolve
from symbench.core.plugin import registry
from symbench.core.robot.specs import load_robot
from symbench.plugins.splits.assign import grid_rules, iid_test_size

ROBOTS = ("magneto", "hexa", "nona")
GENERALIZATION = ("unseen-heading", "unseen-rotation", "unseen-inclination", "unseen-gait")


def control_name(split: str) -> str:
    """The standard control's name: control-rotation for unseen-rotation (at most 22
    characters, so that `symbench list splits` keeps it whole at 40 columns)."""
    return "control-" + split.removeprefix("unseen-")


FRACTIONS = (0.1, 0.25, 0.5, 0.75)
# the published v6 board, archived as measured when the board moved to v7
RECORDS = Path(__file__).resolve().parents[2] / "leaderboards/archive/small-v6-superseded/records"


def drawn_context(robot: str, n: int = 120, seed: int = 0, version: str = "-v7") -> SplitContext:
    """A split's view of `n` climbs drawn from continuous distributions, with trajectory ids
    that are not positions (every 3rd id from 5), so that a split mixing them up fails."""
    spec = load_robot(robot)
    reversed_order = list(range(spec.n_legs - 1, -1, -1))
    scenarios = []
    for k in range(n):
        rng = np.random.default_rng([38, k])
        yaw, heading, direction = (round(float(a), 6) for a in rng.uniform(0, 360, 3))
        scenarios.append(
            {
                "robot": robot,
                "inclination_deg": round(float(rng.uniform(60.0, 120.0)), 6),
                "heading_deg": heading,
                "yaw_deg": yaw,
                "direction": direction,
                "leg_order": None if rng.integers(2) == 0 else reversed_order,
                "seed": k,
                "seconds": 2.6,
                "gait_spread": 0.1,
            }
        )
    return SplitContext(
        dataset_id=f"{robot}-climb-drawn{version}",
        trajectory_ids=5 + 3 * np.arange(n),
        scenarios=tuple(scenarios),
        n_samples=np.full(n, 433),
        rotation_order=spec.group.rotation_order,
        seed=seed,
    )


def grid_context(robot: str, key: str, seed: int = 0, version: str | None = None) -> SplitContext:
    """A split's view of the scenarios of the preset `key` (a v6 grid such as `small@v6`, or
    a v7 preset: smoke's grid or drawn climbs) under its dataset id, or under that id with
    `version` as its ending instead ('-v7'; '' for none)."""
    spec = load_robot(robot)
    found = preset(key)
    grid = found.scenarios(robot, spec.n_legs, spec.group.rotation_order)
    ending = f"-v{found.version}" if version is None else version
    return SplitContext(
        dataset_id=f"{robot}-climb-{found.name}{ending}",
        trajectory_ids=np.arange(len(grid)),
        scenarios=tuple(s.to_dict() for s in grid),
        n_samples=np.ones(len(grid), dtype=int),
        rotation_order=spec.group.rotation_order,
        seed=seed,
    )


def field(context: SplitContext, ids: np.ndarray, name: str) -> np.ndarray:
    by_id = dict(zip(context.trajectory_ids.tolist(), context.scenarios, strict=True))
    return np.asarray([by_id[i][name] for i in ids.tolist()], dtype=object)


def seen(parts: SplitIndices) -> np.ndarray:
    return np.concatenate([parts.train, parts.val])


def assert_disjoint(parts: SplitIndices, context: SplitContext) -> None:
    ids = np.concatenate([parts.train, parts.val, parts.test])
    assert len(np.unique(ids)) == len(ids), parts.split
    assert set(ids.tolist()) <= set(context.trajectory_ids.tolist()), parts.split
    assert min(parts.sizes.values()) >= 1, parts.split


# --- which rules a dataset gets -----------------------------------------------------------


def test_grid_rules_for_v6_and_for_grids_without_a_version_continuous_rules_from_v7():
    assert grid_context("hexa", "small@v6").version == 6
    assert grid_rules(grid_context("hexa", "small@v6"))
    assert grid_rules(drawn_context("hexa", version="-v6"))  # the version decides
    assert not grid_rules(drawn_context("hexa"))
    assert not grid_rules(grid_context("hexa", "small@v6", version="-v7"))
    # the v7 presets: drawn climbs, and smoke (still a grid) under its v7 id
    assert grid_context("hexa", "small").version == grid_context("hexa", "smoke").version == 7
    assert not grid_rules(grid_context("hexa", "small"))
    assert not grid_rules(grid_context("hexa", "smoke"))
    # no version (imported logs): grid rules where some climbs are rotated images of others
    assert grid_context("hexa", "small@v6", version="").version is None
    assert grid_rules(grid_context("hexa", "small@v6", version=""))
    assert grid_rules(grid_context("hexa", "smoke", version=""))
    assert not grid_rules(drawn_context("hexa", version=""))
    assert not grid_rules(grid_context("hexa", "small", version=""))


# --- the generalization splits on climbs drawn from continuous distributions --------------


@pytest.mark.parametrize("robot", ROBOTS)
def test_unseen_rotation_trains_in_the_fundamental_sector_and_tests_outside(robot):
    context = drawn_context(robot)
    width = 360.0 / context.rotation_order
    parts = resolve("unseen-rotation", context)
    assert_disjoint(parts, context)
    trained = field(context, seen(parts), "yaw_deg").astype(float)
    tested = field(context, parts.test, "yaw_deg").astype(float)
    assert (trained < width).all() and (tested >= width).all()
    # every climb of the sector trains: the training side is the whole sector
    inside = np.asarray([s["yaw_deg"] < width for s in context.scenarios])
    assert len(seen(parts)) == inside.sum()
    assert len(parts.test) == iid_test_size(len(inside)) == len(resolve("iid", context).test)


@pytest.mark.parametrize("robot", ROBOTS)
def test_unseen_heading_trains_on_one_half_circle_of_headings_and_tests_the_other(robot):
    context = drawn_context(robot)
    parts = resolve("unseen-heading", context)
    assert_disjoint(parts, context)
    assert (field(context, seen(parts), "heading_deg").astype(float) < 180.0).all()
    assert (field(context, parts.test, "heading_deg").astype(float) >= 180.0).all()
    assert len(parts.test) == len(resolve("iid", context).test)


@pytest.mark.parametrize("robot", ROBOTS)
def test_unseen_inclination_and_gait_hold_out_their_region_of_the_draws(robot):
    context = drawn_context(robot)
    n_test = len(resolve("iid", context).test)
    steep = resolve("unseen-inclination", context)
    assert_disjoint(steep, context)
    slopes = field(context, seen(steep), "inclination_deg").astype(float)
    assert field(context, steep.test, "inclination_deg").astype(float).min() > slopes.max()
    assert len(steep.test) == n_test
    gait = resolve("unseen-gait", context)
    assert_disjoint(gait, context)
    assert all(order is None for order in field(context, seen(gait), "leg_order"))
    assert all(order is not None for order in field(context, gait.test, "leg_order"))
    assert len(gait.test) == n_test


def test_the_test_subset_is_seeded():
    a, b = (resolve("unseen-rotation", drawn_context("hexa", seed=s)) for s in (0, 1))
    assert resolve("unseen-rotation", drawn_context("hexa")).to_dict() == a.to_dict()
    assert a.test.tolist() != b.test.tolist()
    assert sorted(seen(a).tolist()) == sorted(seen(b).tolist())  # the sector is the sector


def test_orbit_rotation_refuses_climbs_without_exact_images():
    exact = "orbit-rotation needs climbs that are exact rotated.*`symbench data symmetry hexa"
    with pytest.raises(SymbenchError, match=exact):
        resolve("orbit-rotation", drawn_context("hexa"))


def test_on_a_v7_grid_rotation_splits_test_only_what_their_name_says():
    """Smoke stays a grid in v7 (yaws 0, 180 and 250): for hexa 180 is an image of 0, so
    unseen-rotation tests the 250 climbs only and orbit-rotation the 180 ones only; on the
    small grid every climb outside the sector is an image, and unseen-rotation refuses."""
    smoke = grid_context("hexa", "smoke")
    assert smoke.dataset_id == "hexa-climb-smoke-v7"
    unseen = resolve("unseen-rotation", smoke)
    assert set(field(smoke, seen(unseen), "yaw_deg")) == {0.0}
    assert set(field(smoke, unseen.test, "yaw_deg")) == {250.0}
    assert len(unseen.test) == iid_test_size(6)
    orbit = resolve("orbit-rotation", smoke)
    assert set(field(smoke, orbit.test, "yaw_deg")) == {180.0}
    with pytest.raises(SymbenchError, match="not rotated images of them \\(16 inside, 0 such"):
        resolve("unseen-rotation", grid_context("hexa", "small@v6", version="-v7"))


# --- the size-matched iid controls --------------------------------------------------------


def test_control_of_names_each_generalization_splits_control():
    names = registry.collect("splits")
    for split in GENERALIZATION:
        assert control_of(split) == control_name(split) and control_name(split) in names
        assert control_of(control_name(split)) is None
    for split in ("iid", "orbit-rotation", *(f"fraction-{f:g}" for f in FRACTIONS)):
        assert control_of(split) is None
    assert control_of("heading_0_vs_180") is None  # a column split
    with pytest.raises(UnknownNameError):
        control_of("unseen-rotatoin")


def assert_matched(split: str, context: SplitContext) -> tuple[SplitIndices, SplitIndices]:
    parts = resolve(split, context)
    control = resolve(control_name(split), context)
    assert_disjoint(control, context)
    assert control.sizes == parts.sizes, split
    assert resolve(control_name(split), context).to_dict() == control.to_dict()
    return parts, control


@pytest.mark.parametrize("robot", ROBOTS)
@pytest.mark.parametrize("split", GENERALIZATION)
def test_each_control_draws_as_many_climbs_as_its_split_from_iid(robot, split):
    draws = [drawn_context(robot, seed=seed) for seed in (0, 1, 2)]
    controls = [assert_matched(split, context)[1] for context in draws]
    for context, control in zip(draws, controls, strict=True):
        iid = resolve("iid", context)  # equal test sizes: the control tests on iid's test set
        assert control.test.tolist() == iid.test.tolist()
        assert set(seen(control).tolist()) <= set(seen(iid).tolist())
    assert controls[0].train.tolist() != controls[1].train.tolist()  # seeds differ
    assert controls[1].test.tolist() != controls[2].test.tolist()


@pytest.mark.parametrize("robot", ROBOTS)
@pytest.mark.parametrize("name", ["smoke", "small", "transfer"])
def test_controls_match_the_v6_splits_too(robot, name):
    """On v6 grids the splits keep their own sizes (hexa small: 8 climbs train unseen-rotation
    and 40 test it); their controls match them, whatever they are."""
    refused = {"transfer": {"unseen-heading"}}.get(name, {"unseen-inclination", "unseen-gait"})
    for split in GENERALIZATION:
        for seed in (0, 3):
            if split in refused:  # the grid does not vary what the split holds out
                with pytest.raises(SymbenchError, match=f"{split} needs"):
                    resolve(control_name(split), grid_context(robot, f"{name}@v6", seed))
                continue
            assert_matched(split, grid_context(robot, f"{name}@v6", seed))


def test_the_size_check_tells_a_split_from_another():
    """What the control tests compare differs between splits: a control of another split
    (nona: a ninth of the climbs train unseen-rotation, about half unseen-heading) fails."""
    context = drawn_context("nona")
    rotation = resolve("unseen-rotation", context)
    assert resolve("control-heading", context).sizes != rotation.sizes
    assert resolve("control-rotation", context).sizes == rotation.sizes


# --- sample efficiency: one test set across fractions -------------------------------------


@pytest.mark.parametrize("robot", ROBOTS)
def test_fractions_share_iid_test_and_nest_their_training_climbs(robot):
    context = drawn_context(robot, seed=4)
    iid = resolve("iid", context)
    previous: set[int] = set()
    for share in FRACTIONS:
        part = resolve(f"fraction-{share:g}", context)
        assert (part.test.tolist(), part.val.tolist()) == (iid.test.tolist(), iid.val.tolist())
        train = set(part.train.tolist())
        assert previous < train <= set(iid.train.tolist())
        assert part.sizes["train"] == int(np.ceil(share * len(iid.train)))
        previous = train


# --- v6: the published splits unchanged ---------------------------------------------------

V6_SPLITS = (
    "iid",
    "unseen-heading",
    "unseen-rotation",
    "orbit-rotation",
    "unseen-inclination",
    "unseen-gait",
    *(f"fraction-{f:g}" for f in FRACTIONS),
)
# sha256 of every v6 split of smoke, small and transfer, seeds 0-2, on all three robots, as
# commit 476dd68 (before the continuous rules) assigned them
V6_DIGEST = "1cad53f49f53b73e28e06c157def01ea139e3e23af6e358590de4204f72da1c3"


def v6_digest() -> str:
    digest = hashlib.sha256()
    for robot in ROBOTS:
        for name in ("smoke", "small", "transfer"):
            for seed in (0, 1, 2):
                context = grid_context(robot, f"{name}@v6", seed)
                for split in V6_SPLITS:
                    try:
                        part: object = resolve(split, context).to_dict()
                    except SymbenchError:
                        part = "refused"
                    digest.update(json.dumps([robot, name, seed, split, part]).encode())
    return digest.hexdigest()


def test_v6_grids_keep_their_assignments_bit_for_bit():
    assert v6_digest() == V6_DIGEST


def test_the_published_v6_records_split_sizes_are_reproduced():
    """Every published record's numbers of training, validation and test climbs are what its
    split assigns on the v6 grid (so `symbench verify` of a v6 record still re-splits it)."""
    contexts: dict[tuple[str, int], SplitContext] = {}
    records = sorted(RECORDS.glob("*-v6__*.json"))
    assert len(records) > 100
    for path in records:
        record = json.loads(path.read_text())
        key = (record["robot"], record["seed"])
        if key not in contexts:
            contexts[key] = grid_context(
                record["robot"], f"{record['dataset']['preset']}@v6", key[1]
            )
        assert record["dataset"]["id"] == contexts[key].dataset_id
        sizes = resolve(record["split"], contexts[key]).sizes
        samples = record["samples"]
        assert sizes == {k: samples[f"{k}_trajectories"] for k in sizes}, path.name


@pytest.mark.slow
def test_the_v6_small_dataset_splits_as_its_grid(tmp_path, monkeypatch):
    """hexa's small v6 dataset (the published board's data), generated by this code: its
    scenarios are the grid's, so its splits are the ones pinned above."""
    from symbench.core.data.generation.generate import ensure_dataset

    monkeypatch.setenv("SYMBENCH_HOME", str(tmp_path))
    dataset = ensure_dataset("hexa", "small@v6", workers=2, show_progress=False)
    grid = grid_context("hexa", "small@v6", seed=2)
    assert [{**s, "robot": "hexa"} for s in dataset.scenarios] == [
        {**s, "robot": "hexa"} for s in grid.scenarios
    ]
    for split in ("unseen-rotation", "unseen-heading", "control-rotation"):
        assert dataset.split_indices(split, 2).to_dict() == resolve(split, grid).to_dict()
