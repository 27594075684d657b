"""The generalization gap: each model entry's test RMSE on unseen-rotation (unseen-heading)
over its RMSE on the size-matched control (control-rotation, control-heading), seed by seed,
else over iid's; the third (fourth) plot of the board page, absent with its reason when the
splits are missing."""

from __future__ import annotations

import pytest

from symbench.core.board.gap import generalization_gaps
from symbench.core.board.leaderboard import aggregate, load_records
from symbench.core.board.site.plots import draw_plots
from symbench.core.runs.results import write_record

# model -> split -> test RMSE by seed; sdnn's control has a seed that unseen-rotation lacks
RMSE = {
    "sdnn": {
        "unseen-rotation": [0.20, 0.22, 0.24],
        "control-rotation": [0.10, 0.10, 0.12, 5.0],
        "iid": [0.05, 0.05, 0.05],
    },
    "ffnn": {
        "unseen-rotation": [1.0, 1.1, 1.2],
        "control-rotation": [1.0, 1.1, 1.2],
        "iid": [0.5, 0.5, 0.5],
    },
}


def table_of(folder, make_record, splits):
    for model, by_split in RMSE.items():
        for split in splits:
            for seed, rmse in enumerate(by_split[split]):
                record = make_record(model=model, split=split, seed=seed, rmse=rmse)
                write_record(record, folder / f"{model}-{split}-{seed}.json")
    return aggregate(load_records(folder))


def test_the_gap_divides_by_the_control_seed_by_seed(tmp_path, make_record):
    table = table_of(tmp_path, make_record, ["unseen-rotation", "control-rotation", "iid"])
    gaps = generalization_gaps(table)
    assert gaps is not None and gaps.control == "control-rotation" and gaps.protocols == ["paper"]
    bars = {s.label: (s.model, s.points["paper"]) for s in gaps.series}
    assert sorted(bars) == ["ffnn (acc, torch)", "sdnn (acc, torch)"]
    model, sdnn = bars["sdnn (acc, torch)"]
    assert model == "sdnn"
    assert sdnn.seeds == pytest.approx((2.0, 2.2, 2.0))  # seed 3 has no pair: left out
    assert sdnn.mean == pytest.approx(6.2 / 3)
    assert (sdnn.low, sdnn.high) == pytest.approx((2.0, 2.2))  # 3 seeds: their range
    ffnn = bars["ffnn (acc, torch)"][1]
    assert (ffnn.mean, ffnn.low, ffnn.high) == pytest.approx((1.0, 1.0, 1.0))


def test_without_the_control_the_gap_divides_by_iid_and_says_so(tmp_path, make_record):
    table = table_of(tmp_path, make_record, ["unseen-rotation", "iid"])
    gaps = generalization_gaps(table)
    assert gaps is not None and gaps.control == "iid"
    ffnn = next(s for s in gaps.series if s.model == "ffnn").points["paper"]
    assert ffnn.seeds == pytest.approx((2.0, 2.2, 2.4))
    plot = draw_plots(table, "hexa", table.dataset[0], tmp_path / "site")[2]
    assert "overstates the gap" in plot.caption


def test_the_gap_plot_is_drawn_with_its_result_in_words(tmp_path, make_record):
    table = table_of(tmp_path, make_record, ["unseen-rotation", "control-rotation"])
    plot = draw_plots(table, "hexa", table.dataset[0], tmp_path / "site")[2]
    assert plot.title == "Generalization gap" and plot.path is not None
    assert plot.path.endswith("-generalization-gap.svg")
    assert (tmp_path / "site" / plot.path).read_bytes().startswith(b"<?xml")
    assert "over its test RMSE on control-rotation" in plot.caption
    assert "overstates" not in plot.caption
    assert plot.alt == (
        "The ratio of test RMSE on unseen-rotation to control-rotation per protocol. The "
        "smallest gap: ffnn (acc, torch) at protocol paper. The largest gap: sdnn (acc, torch) "
        "at protocol paper."
    )


def test_unseen_headings_have_a_gap_plot_of_their_own_against_their_control(tmp_path, make_record):
    for model, by_split in RMSE.items():  # the rotation splits' numbers, as headings
        for held_out, control in (
            ("unseen-heading", "unseen-rotation"),
            ("control-heading", "iid"),
        ):
            for seed, rmse in enumerate(by_split[control]):
                record = make_record(model=model, split=held_out, seed=seed, rmse=rmse)
                write_record(record, tmp_path / f"{model}-{held_out}-{seed}.json")
    table = aggregate(load_records(tmp_path))
    gaps = generalization_gaps(table, "unseen-heading")
    assert gaps is not None and gaps.control == "control-heading"
    ffnn = next(s for s in gaps.series if s.model == "ffnn").points["paper"]
    assert ffnn.seeds == pytest.approx((2.0, 2.2, 2.4))
    rotation, heading = draw_plots(table, "hexa", table.dataset[0], tmp_path / "site")[2:]
    assert rotation.path is None and heading.title == "Generalization gap, unseen-heading"
    assert heading.path.endswith("-generalization-gap-unseen-heading.svg")
    assert "over its test RMSE on control-heading" in heading.caption
    assert "the unseen slope headings cost nothing" in heading.caption


@pytest.mark.parametrize("splits", [["iid", "control-rotation"], ["unseen-rotation"]])
def test_without_the_splits_the_gap_plot_is_absent_and_says_why(tmp_path, make_record, splits):
    table = table_of(tmp_path, make_record, splits)
    assert generalization_gaps(table) is None
    plot = draw_plots(table, "hexa", table.dataset[0], tmp_path / "site")[2]
    assert plot.path is None and plot.alt == ""
    assert plot.caption == (
        "No plot: no model has records of both unseen-rotation and its control or iid on this "
        "dataset."
    )
