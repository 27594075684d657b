"""The paper's claims on a board (claims.md): each comparison's estimate and interval over
the seeds two models share, and a verdict that follows from the interval whichever way it
falls; comparisons the board cannot make are left out."""

from __future__ import annotations

import numpy as np
import pytest

from symbench.core.board.claims import claims, claims_markdown
from symbench.core.board.leaderboard import aggregate, load_records, write_leaderboard
from symbench.core.board.statistics import Interval, t_interval, welch_interval
from symbench.core.runs.results import write_record

SEEDS = range(5)


def board(tmp_path, make_record, runs):
    """Writes one record per (model, split, seed, rmse[, robot][, metrics]) and aggregates."""
    for i, run in enumerate(runs):
        record = make_record(**{k: v for k, v in run.items() if k != "closed_loop"})
        if "closed_loop" in run:
            record["metrics"]["closed-loop"] = run["closed_loop"]
        write_record(record, tmp_path / f"r{i}.json")
    return aggregate(load_records(tmp_path))


def comparisons(table):
    return {(c.dataset, c.what): c for claim in claims(table) for c in claim.comparisons}


def unseen(model, errors, split="unseen-rotation"):
    return [dict(model=model, split=split, seed=s, rmse=e) for s, e in zip(SEEDS, errors)]


@pytest.mark.parametrize(
    ("ffnn", "sdnn", "verdict"),
    [
        ([1.0, 1.1, 0.9, 1.05, 0.95], [0.1, 0.12, 0.09, 0.11, 0.1], "holds"),
        ([0.1, 0.12, 0.09, 0.11, 0.1], [1.0, 1.1, 0.9, 1.05, 0.95], "fails"),
        ([1.0, 0.5, 1.0, 0.5, 1.0], [0.5, 1.0, 0.5, 1.0, 0.5], "tie"),
    ],
)
def test_the_verdict_follows_from_the_interval_whichever_way_it_falls(
    tmp_path, make_record, ffnn, sdnn, verdict
):
    table = board(tmp_path, make_record, unseen("ffnn", ffnn) + unseen("sdnn", sdnn))
    found = comparisons(table)
    (comparison,) = found.values()  # no gnn, sdgnn or ffnn-leg: nothing else is compared
    assert comparison.what == "ffnn / sdnn on unseen-rotation"
    assert comparison.seeds == 5
    geometric = np.exp(np.mean(np.log(ffnn) - np.log(sdnn)))  # the ratio of geometric means
    assert comparison.estimate.value == pytest.approx(geometric)
    assert comparison.verdict == verdict


@pytest.mark.parametrize(
    ("held_out", "control"),
    [("unseen-rotation", "control-rotation"), ("unseen-heading", "control-heading")],
)
def test_the_penalty_for_unseen_orientations_is_each_model_against_its_own_control(
    tmp_path, make_record, held_out, control
):
    runs = (
        unseen("ffnn", [2.0] * 5, held_out)
        + unseen("ffnn", [1.0, 1.0, 1.0, 1.0, 2.0], control)
        + unseen("sdnn", [0.3] * 5, held_out)
        + unseen("sdnn", [0.3] * 5, control)
        # the other held-out split's control, which must not stand in for this one's
        + unseen(
            "ffnn",
            [9.0] * 5,
            "control-heading" if control == "control-rotation" else "control-rotation",
        )
    )
    found = comparisons(board(tmp_path, make_record, runs))
    (penalty,) = [c for (_, what), c in found.items() if "penalty" in what]
    assert penalty.what == f"ffnn's penalty / sdnn's ({held_out} / {control})"
    # per seed (2 / control) / (0.3 / 0.3): 2 on four seeds, 1 on the fifth
    assert penalty.estimate.value == pytest.approx(2**0.8)
    log_ratios = np.log([2, 2, 2, 2, 1])
    half = 2.776 * log_ratios.std(ddof=1) / np.sqrt(5)  # Student's t, 4 degrees of freedom
    assert penalty.estimate.low == pytest.approx(np.exp(log_ratios.mean() - half), rel=1e-3)
    assert penalty.estimate.high == pytest.approx(np.exp(log_ratios.mean() + half), rel=1e-3)
    assert penalty.verdict == "holds"


def test_the_closed_loop_compares_the_continuous_score_where_records_have_it(tmp_path, make_record):
    def scored(model, tracking, score):
        return [
            dict(
                model=model,
                seed=s,
                rmse=0.1,
                closed_loop={"pd_tracking_score": tracking + s / 100, "pd_normalized_score": score},
            )
            for s in SEEDS
        ]

    table = board(tmp_path, make_record, scored("sdgnn", 0.6, 0.1) + scored("ffnn", 0.2, 0.9))
    (comparison,) = comparisons(table).values()
    assert comparison.what == "sdgnn - ffnn cl_tracking on iid"
    assert comparison.estimate.value == pytest.approx(0.4)
    assert comparison.verdict == "holds"


def test_more_legs_compares_robots_of_one_preset_with_unpaired_seeds(tmp_path, make_record):
    runs = [
        dict(model="ffnn", robot=robot, seed=s, rmse=rmse * (1 + s / 50))
        for robot, rmse in (("magneto", 0.2), ("hexa", 0.4))
        for s in SEEDS
    ]
    (comparison,) = comparisons(board(tmp_path, make_record, runs)).values()
    assert comparison.dataset == "hexa-climb-smoke-v7 / magneto-climb-smoke-v7"
    assert comparison.what == "ffnn nrmse on iid, 6 legs over 4"
    assert comparison.estimate.value == pytest.approx(2.0)
    assert comparison.verdict == "holds"


def test_a_single_seed_gives_no_interval_and_no_verdict(tmp_path, make_record):
    table = board(tmp_path, make_record, unseen("ffnn", [1.0]) + unseen("sdnn", [0.1]))
    (comparison,) = comparisons(table).values()
    assert comparison.verdict == "no interval (one seed)"


def test_the_intervals_are_students_paired_and_welchs_unpaired():
    interval = t_interval([1.0, 2.0, 3.0])
    assert interval.value == 2.0
    assert interval.high - 2.0 == pytest.approx(4.303 / np.sqrt(3), rel=1e-3)  # t(2) = 4.303
    assert np.isnan(t_interval([1.0]).low)
    same = welch_interval([1.0, 2.0, 3.0], [1.0, 2.0, 3.0])
    assert same.value == 0.0 and same.low == pytest.approx(-same.high)
    shifted = welch_interval([11.0, 12.0, 13.0, 14.0], [1.0, 2.0, 3.0])
    assert shifted.value == pytest.approx(10.5) and 0 < shifted.low < 10.5 < shifted.high
    assert welch_interval([2.0, 2.0], [1.0, 1.0]) == Interval(1.0, 1.0, 1.0)


def test_claims_md_is_written_beside_the_summary_per_protocol(tmp_path, make_record):
    records = tmp_path / "records"
    records.mkdir()
    board(records, make_record, unseen("ffnn", [1.0, 1.1, 0.9]) + unseen("sdnn", [0.1] * 3))
    written = write_leaderboard(records, tmp_path)
    page = (tmp_path / "claims.md").read_text()
    assert tmp_path / "claims.md" in written
    assert "# Trained under the " in page
    row = "| hexa-climb-smoke-v7 | ffnn / sdnn on unseen-rotation | 9.97 [7.77, 12.8] | 3 |"
    assert f"{row} **holds** |" in page.splitlines()
    assert page == claims_markdown(aggregate(load_records(records)))
