"""Leg-grouped layouts: sizes, names, slicing, feature types and their reflection signs."""

from __future__ import annotations

import numpy as np
import pytest

from symbench.core.common.errors import UnknownNameError
from symbench.core.data.views.schema import (
    TARGET,
    FeatureType,
    body_graph,
    leg_grouped_input,
    vector_input,
    vector_target,
)


def test_variant_layouts():
    acc, nxt = leg_grouped_input("acc"), leg_grouped_input("next")
    assert acc.feature_names == ("q", "qd", "qdd", "w", "a", "g", "p", "contact", "magnet")
    assert nxt.feature_names == (
        "q",
        "qd",
        "q_next",
        "qd_next",
        "w",
        "a",
        "g",
        "p",
        "contact",
        "magnet",
    )
    assert acc.size == 3 * 7 + 2 and nxt.size == 3 * 8 + 2
    assert TARGET.column_names == ("tau.coxa", "tau.femur", "tau.tibia")
    assert len(set(acc.column_names)) == acc.size


def test_slicing_by_name():
    layout = leg_grouped_input("acc")
    x = np.arange(2 * layout.size).reshape(2, layout.size)
    assert layout.slice("g") == slice(15, 18)
    np.testing.assert_array_equal(x[:, layout.slice("contact")], x[:, 21:22])
    np.testing.assert_array_equal(layout.select(x, ["magnet", "q"]), x[:, [22, 0, 1, 2]])


def test_declared_types_drive_reflection_signs():
    layout = leg_grouped_input("acc")
    assert layout.feature("w").type is FeatureType.PSEUDOVECTOR
    assert layout.feature("a").type is FeatureType.VECTOR
    assert layout.feature("contact").type is FeatureType.FLAG
    signs = layout.reflection_signs
    assert list(signs[layout.slice("q")]) == [-1, 1, 1]  # coxa yaw flips under a leg mirror
    assert list(signs[layout.slice("p")]) == [1, -1, 1]
    assert list(signs[layout.slice("w")]) == [-1, 1, -1]
    assert list(signs[layout.slice("magnet")]) == [1]


def test_unknown_names_suggest_the_closest():
    with pytest.raises(UnknownNameError, match="did you mean next"):
        leg_grouped_input("nxt")
    with pytest.raises(UnknownNameError, match="did you mean qdd"):
        leg_grouped_input("acc").slice("qddd")


def test_vector_and_graph_layouts():
    vec = vector_input(6, "acc")
    assert vec.size == 16 + 6 * 9 + 12
    assert len(set(vec.columns)) == vec.size
    assert vector_target(6).size == 18
    graph = body_graph(6, "next")
    edges = graph.edges()
    assert graph.n_nodes == 19 and edges.shape == (18, 2)
    assert edges[0].tolist() == [0, 1] and edges[3].tolist() == [0, 4]  # coxa of legs 0 and 1
    assert edges[:, 1].max() == graph.n_nodes - 1
