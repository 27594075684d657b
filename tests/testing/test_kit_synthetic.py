"""Synthetic smoke data: every view holds the same samples, and the target is equivariant."""

from __future__ import annotations

import numpy as np

from symbench.core.data.views.model_dims import dims_of
from symbench.core.symmetry.groups import cyclic
from symbench.testing import equivariant_target, synthetic_views


def test_views_match_the_schema_and_share_targets():
    views = synthetic_views(6, 40, variant="next", seed=2)
    for arrays in views.values():
        dims_of(arrays)  # raises on a shape the schema does not declare
        np.testing.assert_array_equal(arrays.target, views["leg_grouped"].target)


def test_target_is_equivariant_and_shared_across_seeds():
    z = np.random.default_rng(0).normal(size=(10, 6, 5))
    group = cyclic(6)
    for g in group:
        np.testing.assert_allclose(
            equivariant_target(group.act(g, z)), group.act(g, equivariant_target(z)), atol=1e-12
        )
    a, b = synthetic_views(4, 10, seed=0), synthetic_views(4, 10, seed=1)
    assert not np.allclose(a["vector"].inputs["x"], b["vector"].inputs["x"])
