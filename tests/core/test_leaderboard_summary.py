"""The summary page puts models side by side; the sample-efficiency curve ends at iid."""

from __future__ import annotations

import pytest

from symbench.core.board.leaderboard import aggregate, load_records
from symbench.core.board.series import sample_efficiency_panels, sample_efficiency_series
from symbench.core.board.summary import headline
from symbench.core.runs.results import write_record


def write_runs(folder, make_record, runs):
    for i, kwargs in enumerate(runs):
        write_record(make_record(**kwargs), folder / f"r{i}.json")


def test_models_are_columns_and_splits_are_ordered(tmp_path, make_record):
    runs = [
        dict(model=m, split=split, seed=s, rmse=r + s / 100)
        for m, r in (("sdnn", 0.1), ("ffnn", 1.0))
        for split in ("unseen-rotation", "iid", "fraction-0.5")
        for s in range(3)
    ]
    write_runs(tmp_path, make_record, runs)
    page = headline(aggregate(load_records(tmp_path)))
    rows = [line for line in page.splitlines() if line.startswith("| ")]
    assert rows[0] == "| dataset | split | sdnn | ffnn |"  # the better model first
    assert [r.split(" | ")[1] for r in rows[1:4]] == ["iid", "unseen-rotation", "fraction-0.5"]
    # fixed decimals to 3 significant digits, the bounds on the mean's decimals
    assert rows[1] == "| hexa-climb-smoke-v7 | iid | 0.110 [0.100, 0.120] | 1.01 [1.00, 1.02] |"
    nrmse = "| hexa-climb-smoke-v7 | iid | 0.0550 [0.0500, 0.0600] | 0.505 [0.500, 0.510] |"
    assert rows[5] == nrmse  # the NRMSE table
    assert "Closed loop" not in page  # no closed-loop records, no section


def test_closed_loop_section_shows_the_headline_score_and_time_held(tmp_path, make_record):
    for s in range(3):
        record = make_record(seed=s)
        record["metrics"]["closed-loop"] = {
            "time_to_failure_s": 0.5,  # the model alone: not the headline
            "pd_time_to_failure_s": 1.0 + s,
            "pd_success_rate": 0.0,
            "pd_joint_rmse_rad": 0.02,
            "pd_normalized_score": 0.4 + 0.1 * s,
        }
        write_record(record, tmp_path / f"r{s}.json")
    page = headline(aggregate(load_records(tmp_path)))
    assert "| hexa-climb-smoke-v7 | iid | 0.50 [0.40, 0.60] / 2 |" in page


def test_sample_efficiency_curve_ends_with_iid_at_one(tmp_path, make_record):
    runs = [
        dict(model="sdnn", split=split, seed=s, rmse=r)
        for split, r in (("fraction-0.25", 0.4), ("iid", 0.1))
        for s in range(3)
    ] + [dict(model="sdnn", backend="jax", split="iid", seed=s, rmse=0.1) for s in range(3)]
    write_runs(tmp_path, make_record, runs)
    # the jax entry has the iid point alone: no curve
    (curve,) = sample_efficiency_series(aggregate(load_records(tmp_path)), "hexa")
    assert (curve.model, curve.label) == ("sdnn", "sdnn (acc, torch)")
    assert list(curve.points) == [0.25, 1.0]
    assert [s.mean for s in curve.points.values()] == pytest.approx([0.4, 0.1])


def test_each_dataset_has_its_own_sample_efficiency_panel(tmp_path, make_record):
    """A fraction of one dataset is not the same number of climbs as that of another, nor
    are its test climbs the same: two datasets of a robot are never drawn on one axes."""
    runs = [
        dict(model="sdnn", split=split, seed=s, rmse=r)
        for split, r in (("fraction-0.25", 0.4), ("iid", 0.1))
        for s in range(3)
    ]
    write_runs(tmp_path, make_record, runs)
    for i, (split, rmse) in enumerate((("fraction-0.5", 0.2), ("iid", 0.05)) * 3):
        record = make_record(split=split, seed=i // 2, rmse=rmse, content_hash="ef" * 32)
        record["dataset"]["id"] = "hexa-climb-small-v7"
        write_record(record, tmp_path / f"small{i}.json")
    table = aggregate(load_records(tmp_path))
    panels = sample_efficiency_panels(table, "hexa")
    protocol = table.protocol.iloc[0]
    assert list(panels) == [
        f"hexa-climb-small-v7, {protocol} protocol",
        f"hexa-climb-smoke-v7, {protocol} protocol",
    ]
    (small,), (smoke,) = panels.values()
    assert small.label == smoke.label == "sdnn (acc, torch)"  # the panel names the dataset
    assert list(small.points) == [0.5, 1.0] and list(smoke.points) == [0.25, 1.0]
    assert [s.mean for s in small.points.values()] == pytest.approx([0.2, 0.05])
    # one dataset: the robot's title, as before
    one = table[table.dataset == "hexa-climb-smoke-v7"]
    assert list(sample_efficiency_panels(one, "hexa")) == ["hexa: sample efficiency"]


def test_closed_loop_section_prefers_the_continuous_tracking_score(tmp_path, make_record):
    for s in range(3):
        record = make_record(seed=s)
        record["metrics"]["closed-loop"] = {
            "pd_time_to_failure_s": 2.0,
            "pd_normalized_score": 1.0,  # saturated: every reference held
            "pd_tracking_score": 0.3 + 0.1 * s,
        }
        write_record(record, tmp_path / f"r{s}.json")
    page = headline(aggregate(load_records(tmp_path)))
    assert "tracking score (floor 0, oracle 1)" in page
    assert "| hexa-climb-smoke-v7 | iid | 0.40 [0.30, 0.50] / 2 |" in page
