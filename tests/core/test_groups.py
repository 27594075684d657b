"""Group axioms and the action, exhaustively over all pairs and triples of elements."""

from __future__ import annotations

import numpy as np
import pytest

from symbench.core.common.errors import SymbenchError
from symbench.core.data.views.schema import TARGET, leg_grouped_input
from symbench.core.symmetry import groups
from symbench.core.symmetry.checks import axiom_violations, homomorphism_violations
from symbench.core.symmetry.groups import GroupElement, LegGroup, act

GROUPS = {
    "C2 (magneto: 4 legs, shift 2)": (lambda: groups.cyclic(4, 2), 2, 4),
    "C6 (hexa)": (lambda: groups.cyclic(6), 6, 6),
    "C9 (nona)": (lambda: groups.cyclic(9), 9, 9),
    "D6": (lambda: groups.dihedral(6), 12, 6),
    "K4": (groups.klein4, 4, 4),
}


@pytest.fixture(params=sorted(GROUPS), ids=sorted(GROUPS))
def group_case(request):
    make, order, legs = GROUPS[request.param]
    return make(), order, legs


def test_order_and_legs(group_case):
    group, order, legs = group_case
    assert group.order == order
    assert group.n_legs == legs
    assert group.elements[0] == group.identity
    assert len(set(group.elements)) == order


def test_axioms_hold(group_case):
    group, _, _ = group_case
    assert axiom_violations(group.elements) == []


def test_cayley_table_is_a_latin_square(group_case):
    group, order, _ = group_case
    table = group.cayley_table()
    for row in (*table, *table.T):
        assert sorted(row) == list(range(order))


@pytest.mark.parametrize("dtype", [np.float64, np.float32])
@pytest.mark.parametrize(
    "layout",
    [leg_grouped_input("acc"), leg_grouped_input("next"), TARGET],
    ids=lambda lay: lay.name,
)
def test_action_is_a_homomorphism(group_case, layout, dtype):
    group, _, legs = group_case
    x = np.random.default_rng(0).normal(size=(5, legs, layout.size)).astype(dtype)
    assert homomorphism_violations(group.elements, act, x, layout.reflection_signs) == []


def test_rotation_relabels_legs_only():
    hexa = groups.cyclic(6)
    r = groups.shift(6, 1)
    x = np.arange(6 * 3, dtype=float).reshape(6, 3)
    y = hexa.act(r, x)
    np.testing.assert_array_equal(y[1], x[0])  # leg 0's state is now carried by leg 1
    np.testing.assert_array_equal(y[0], x[5])


def test_reflection_flips_by_feature_type():
    d6 = groups.dihedral(6)
    s = groups.mirror(6, 0)
    layout = leg_grouped_input("acc")
    x = np.random.default_rng(1).normal(size=(6, layout.size))
    y = d6.act(s, x, layout.reflection_signs)
    w = layout.slice("w")
    np.testing.assert_array_equal(y[0, w], x[0, w] * np.array([-1, 1, -1]))  # leg 0 on the mirror
    np.testing.assert_array_equal(y[1, layout.slice("q")], x[5, layout.slice("q")] * [-1, 1, 1])
    np.testing.assert_array_equal(y[1, layout.slice("contact")], x[5, layout.slice("contact")])


def test_magneto_group_matches_klein4_rotation():
    k4 = groups.klein4()
    assert groups.shift(4, 2) in k4
    assert set(groups.cyclic(4, 2).elements) <= set(k4.elements)


def test_action_on_torch_and_jax_matches_numpy():
    import jax.numpy as jnp
    import torch

    d6 = groups.dihedral(6)
    layout = leg_grouped_input("next")
    x = np.random.default_rng(2).normal(size=(3, 6, layout.size))
    for g in d6:
        want = act(g, x, layout.reflection_signs)
        got_t = act(g, torch.from_numpy(x), layout.reflection_signs)
        got_j = act(g, jnp.asarray(x, dtype=jnp.float32), layout.reflection_signs)
        assert isinstance(got_t, torch.Tensor) and got_t.dtype == torch.float64
        np.testing.assert_array_equal(got_t.numpy(), want)
        np.testing.assert_allclose(np.asarray(got_j), want, rtol=1e-6)


# --- the checks catch what is wrong --------------------------------------------------------
def test_checks_fail_for_a_wrong_permutation():
    """A 'C6' whose generator swaps two legs is not the rotation group: the checks say so."""
    wrong = LegGroup("not-C6", [GroupElement((1, 0, 2, 3, 4, 5))])
    assert wrong.order == 2  # the swap and the identity
    # an element set that mixes in a wrong permutation is not closed and lacks inverses
    c6 = groups.cyclic(6).elements
    elements = [*c6[:-1], GroupElement((1, 0, 2, 3, 4, 5))]
    violations = axiom_violations(elements)
    assert f"not closed: {c6[1]!r} * {c6[4]!r} = {c6[5]!r}" in violations  # r^5 left out
    assert f"not closed: {c6[1]!r} * {elements[-1]!r} = {c6[1] * elements[-1]!r}" in violations
    assert [v for v in violations if not v.startswith("not closed: ")] == [
        f"no inverse for {c6[1]!r}"  # r^1, whose inverse r^5 was left out
    ]


def test_homomorphism_check_fails_for_a_wrong_action():
    """Indexing with the permutation instead of its inverse breaks the homomorphism on D6."""

    def wrong_act(g, x, signs):
        y = x[..., np.asarray(g.perm), :]
        return y * signs if g.reflect else y

    d6 = groups.dihedral(6)
    layout = leg_grouped_input("acc")
    x = np.random.default_rng(3).normal(size=(2, 6, layout.size))
    assert homomorphism_violations(d6.elements, wrong_act, x, layout.reflection_signs)


def test_homomorphism_check_fails_for_wrong_reflection_signs():
    """Signs that are not an involution (a 2 instead of a 1) break act(s, act(s, x)) == x."""
    d6 = groups.dihedral(6)
    layout = leg_grouped_input("acc")
    bad = layout.reflection_signs.copy()
    bad[0] = 2.0
    x = np.random.default_rng(4).normal(size=(2, 6, layout.size))
    assert homomorphism_violations(d6.elements, act, x, bad)


def test_bad_input_is_named():
    with pytest.raises(SymbenchError, match="not a permutation"):
        GroupElement((0, 0, 1))
    with pytest.raises(SymbenchError, match="6 legs"):
        act(groups.shift(6, 1), np.zeros((4, 3)))
    with pytest.raises(SymbenchError, match="reflection signs"):
        act(groups.mirror(6, 0), np.zeros((6, 3)))
    with pytest.raises(SymbenchError, match="identity"):
        groups.cyclic(6, 6)
    with pytest.raises(SymbenchError, match="unknown symmetry group kind"):
        groups.from_spec(6, "icosahedral")
    with pytest.raises(SymbenchError, match="not an element"):
        groups.cyclic(6).act(groups.mirror(6, 0), np.zeros((6, 3)), [1, 1, 1])


@pytest.mark.parametrize(
    "kind,n,k,order",
    [("cyclic", 4, 2, 2), ("cyclic", 6, 1, 6), ("dihedral", 6, 1, 12), ("klein4", 4, 2, 4)],
)
def test_from_spec(kind, n, k, order):
    assert groups.from_spec(n, kind, k).order == order


def test_element_names():
    assert [g.name for g in groups.cyclic(4, 2)] == ["identity", "shift 2"]
    names = {g.name for g in groups.dihedral(6)}
    assert {"identity", "shift 1", "shift 5", "mirror 0", "mirror 3"} <= names and len(names) == 12
