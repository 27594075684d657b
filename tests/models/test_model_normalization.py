"""Normalization statistics are shared across legs and commute with the group action."""

from __future__ import annotations

import numpy as np

from symbench.core.data.views import schema
from symbench.core.training.normalization import Normalizer
from symbench.testing.synthetic import synthetic_views


def test_statistics_are_shared_across_legs_and_blind_to_leg_order():
    data = synthetic_views(6, 300, seed=4)["leg_grouped"]
    norm = Normalizer.fit(data)
    mean, std = norm.stats["x"]
    assert mean.shape == std.shape == (data.inputs["x"].shape[-1],)
    rolled = data.take(np.arange(len(data)))
    rolled.inputs["x"][:] = np.roll(data.inputs["x"], 2, axis=1)
    np.testing.assert_allclose(Normalizer.fit(rolled).stats["x"][0], mean, atol=1e-12)
    assert norm.stats["target"][0].shape == (3,)


def test_mirror_flipped_columns_and_coxa_torque_get_zero_mean():
    data = synthetic_views(4, 300, seed=5)["leg_grouped"]
    data.inputs["x"][:] += 1.0  # every column has a nonzero mean
    data.target[:] += 1.0
    norm = Normalizer.fit(data)
    flipped = schema.leg_grouped_input("acc").reflection_signs < 0
    assert np.all(norm.stats["x"][0][flipped] == 0) and np.all(norm.stats["x"][0][~flipped] != 0)
    assert norm.stats["target"][0][0] == 0 and np.all(norm.stats["target"][0][1:] != 0)


def test_round_trip_through_arrays():
    norm = Normalizer.fit(synthetic_views(3, 50)["body_graph"])
    again = Normalizer.from_arrays(norm.to_arrays())
    for key, (mean, std) in norm.stats.items():
        np.testing.assert_array_equal(again.stats[key][0], mean)
        np.testing.assert_array_equal(again.stats[key][1], std)
