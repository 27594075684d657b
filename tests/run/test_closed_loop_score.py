"""The closed loop's continuous score: 0 at the floor, 1 at the oracle, linear in the
model's tracking cost, and an interval over references that holds its mean."""

from __future__ import annotations

import pytest

from symbench.plugins.evaluators.closed_loop_score import MIN_SPAN, mean_interval, reference_score


def test_the_score_runs_from_the_floor_to_the_oracle():
    floor, oracle = 0.9, 0.1
    assert reference_score(floor, floor, oracle) == 0.0
    assert reference_score(oracle, floor, oracle) == 1.0
    costs = [0.95, 0.9, 0.7, 0.5, 0.3, 0.1]
    scores = [reference_score(c, floor, oracle) for c in costs]
    assert scores == sorted(scores)  # a lower tracking cost never scores lower
    assert scores[0] < 0.0  # worse than the PD alone
    assert reference_score(0.5, floor, oracle) == pytest.approx(0.5)


def test_no_score_where_the_pd_alone_tracks():
    assert reference_score(0.1, 0.1 + MIN_SPAN / 2, 0.1) is None


def test_the_interval_holds_the_mean_of_the_defined_scores():
    scores = [0.2, None, 0.4, 0.9, 0.5, 0.6]
    mean, (low, high) = mean_interval(scores)
    assert mean == pytest.approx(0.52)
    assert 0.2 <= low < mean < high <= 0.9
    assert mean_interval(scores) == (mean, [low, high])  # a fixed seed: the same interval
    assert mean_interval([None]) == (None, None)
    assert mean_interval([0.3]) == (0.3, [0.3, 0.3])
