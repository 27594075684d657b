"""The boards' statistics: intervals over seeds, rank bands by a paired test, the aggregate
over datasets and splits, and their columns in leaderboard.csv."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest

from symbench.core.board.leaderboard import write_leaderboard
from symbench.core.board.statistics import across_tasks, mean_interval, rank_bands
from symbench.core.runs.results import write_record


def by_seed(*values: float) -> dict[int, float]:
    return dict(enumerate(values))


def test_an_interval_holds_the_mean_and_narrows_with_more_seeds_of_equal_spread():
    three = np.array([-1.0, 0.0, 1.0]) + 5
    eight = np.linspace(-1, 1, 8)
    eight = eight / eight.std(ddof=1) + 5  # the same standard deviation as `three`
    intervals = {}
    for values in (three, eight):
        low, high = mean_interval(values)
        assert low < values.mean() < high
        intervals[len(values)] = high - low
    assert intervals[8] < intervals[3]
    assert mean_interval(three) == (4.0, 6.0)  # with 3 seeds: their range
    assert mean_interval([2.0, np.nan, 2.0]) == (2.0, 2.0)  # a missing value left out
    assert np.isnan(mean_interval([1.0])).all()  # one seed: no interval


def test_an_interval_is_the_same_on_every_call():
    values = np.random.default_rng(1).random(5)
    assert mean_interval(values) == mean_interval(values.copy())


def test_identical_seed_results_share_a_band_and_separated_ones_do_not():
    same = by_seed(0.1, 0.2, 0.3)
    assert rank_bands([same, dict(same)]) == ["1-2", "1-2"]
    separated = [by_seed(0.1, 0.11, 0.12), by_seed(1.0, 1.2, 1.1), by_seed(10, 12, 11)]
    assert rank_bands(separated) == ["1", "2", "3"]


def test_a_difference_the_seeds_do_not_agree_on_is_a_tie():
    """Lower by mean, but one seed of three reverses the order: a paired t-test on 3 seeds
    cannot separate them; a model with no seed in common cannot be separated either."""
    noisy = [by_seed(0.1, 0.1, 0.3), by_seed(0.2, 0.2, 0.2), by_seed(1.0, 1.1, 1.2)]
    assert rank_bands(noisy) == ["1-2", "1-2", "3"]
    unpaired = [by_seed(0.1, 0.1, 0.1), {5: 1.0, 6: 1.1, 7: 1.2}]
    assert rank_bands(unpaired) == ["1-2", "1-2"]


def test_the_aggregate_normalizes_by_the_best_mean_and_pairs_seeds():
    tasks = [
        pd.DataFrame({"a": [1.0, 1.1, 0.9], "b": [2.0, 2.2, 1.8]}),
        pd.DataFrame({"a": [10.0, 11.0, 9.0], "b": [30.0, 33.0, 27.0]}),
    ]
    result = across_tasks(tasks)
    assert (result.tasks, result.seeds) == (2, 6)
    assert result.iqm["a"].value == pytest.approx(1.0, abs=0.1)  # a is the best mean
    assert result.iqm["a"].low <= result.iqm["a"].value <= result.iqm["a"].high
    assert result.iqm["b"].low > result.iqm["a"].high
    better, worse = result.improvement["a", "b"], result.improvement["b", "a"]
    assert (better.value, better.low, better.high) == (1.0, 1.0, 1.0)
    assert (worse.value, worse.low, worse.high) == (0.0, 0.0, 0.0)
    assert across_tasks(tasks) == result  # a fixed bootstrap seed


def test_the_csv_has_intervals_and_rank_bands_and_the_tables_show_them(tmp_path, make_record):
    runs = [("sdnn", s, 0.1 + s / 100) for s in range(3)]
    runs += [("sdgnn", s, 0.1 + s / 100) for s in range(3)]  # the same results: a tie
    runs += [("ffnn", s, 1.0 + s / 10) for s in range(3)]
    for i, (model, seed, rmse) in enumerate(runs):
        write_record(make_record(model=model, seed=seed, rmse=rmse), tmp_path / f"r{i}.json")
    write_leaderboard(tmp_path, tmp_path / "out")
    csv = pd.read_csv(tmp_path / "out" / "leaderboard.csv").set_index("model")
    for metric in ("rmse_Nm", "nrmse", "epochs"):
        low, high = csv[f"{metric}_ci_low"], csv[f"{metric}_ci_high"]
        assert (low <= csv[f"{metric}_mean"]).all() and (csv[f"{metric}_mean"] <= high).all()
    assert csv.rank_band.to_dict() == {"sdnn": "1-2", "sdgnn": "1-2", "ffnn": "3"}
    page = (tmp_path / "out" / "hexa.md").read_text()
    assert "| 1-2 | sdgnn | acc | torch | 3 | " in page
    assert "| 3 | ffnn | acc | torch | 3 | " in page


def test_the_summary_aggregates_over_datasets_and_splits(tmp_path, make_record):
    runs = [
        (model, split, seed, rmse * (1 + seed / 10))
        for split, scale in (("iid", 1.0), ("unseen-rotation", 10.0))
        for model, rmse in (("sdnn", 0.1 * scale), ("ffnn", 0.5 * scale))
        for seed in range(3)
    ]
    for i, (model, split, seed, rmse) in enumerate(runs):
        record = make_record(model=model, split=split, seed=seed, rmse=rmse)
        write_record(record, tmp_path / f"r{i}.json")
    write_leaderboard(tmp_path, tmp_path / "out")
    summary = (tmp_path / "out" / "summary.md").read_text()
    assert "Over the 2 of 2 (dataset, split) pairs" in summary
    assert "| sdnn | - | 1.00 [1.00, 1.00] |" in summary  # better on every seed of both
    assert "| ffnn | 0.00 [0.00, 0.00] | - |" in summary


def test_an_entry_on_only_some_pairs_is_left_out_of_the_aggregate(tmp_path, make_record):
    """A second backend run on one pair (the board's JAX entries) must neither empty the
    aggregate nor enter it; it is named instead."""
    runs = [
        (model, "torch", split, seed, rmse * scale * (1 + seed / 10))
        for split, scale in (("iid", 1.0), ("unseen-rotation", 10.0))
        for model, rmse in (("sdnn", 0.1), ("ffnn", 0.5))
        for seed in range(3)
    ] + [("sdnn", "jax", "iid", seed, 0.01) for seed in range(3)]
    for i, (model, backend, split, seed, rmse) in enumerate(runs):
        record = make_record(model=model, backend=backend, split=split, seed=seed, rmse=rmse)
        write_record(record, tmp_path / f"r{i}.json")
    write_leaderboard(tmp_path, tmp_path / "out")
    summary = (tmp_path / "out" / "summary.md").read_text()
    assert "Over the 2 of 2 (dataset, split) pairs" in summary
    assert "Left out, as they ran on only some pairs: sdnn (acc, jax) (1 of 2)." in summary
    # normalized by the best mean of the entries kept: sdnn (torch) is 1, not 10
    assert "| sdnn (acc, torch) | 1.0" in summary
    aggregate = summary.split("## Aggregate")[1].split("\n#")[0]
    assert "| sdnn (acc, torch) | - |" in aggregate and "sdnn (acc, jax) |" not in aggregate
