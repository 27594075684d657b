"""The controller's QP binding solves what DAQP's own Python interface solves.

DenseQP calls DAQP's C entry point on structures that mirror DAQP's headers and forms the
least-distance problem itself; a layout mistake or a wrong transform would give another
answer (or crash) here, on random strictly convex problems of the controller's shape.
"""

from __future__ import annotations

import daqp
import numpy as np
import pytest

from symbench.core.sim.control.qp import EQUALITY, DenseQP, InfeasibleQP


def _problem(rng, n=27, dense=9, n_eq=6, m=54):
    block = rng.normal(size=(dense, dense))
    H = np.zeros((n, n))
    H[:dense, :dense] = block @ block.T + 0.1 * np.eye(dense)
    H[dense:, dense:] = np.diag(rng.uniform(1e-3, 1.0, n - dense))
    g = rng.normal(size=n)
    C = rng.normal(size=(m, n))
    center = C @ rng.normal(size=n)  # a feasible point: every bound holds there
    lower = center - rng.uniform(0.0, 1.0, m)
    upper = center + rng.uniform(0.0, 1.0, m)
    lower[:n_eq] = upper[:n_eq] = center[:n_eq]
    upper[n_eq : n_eq + 5] = 1e30  # absent bounds
    return H, g, C, lower, upper


@pytest.mark.parametrize("seed", range(5))
def test_the_binding_agrees_with_daqp_solve(seed):
    H, g, C, lower, upper = _problem(np.random.default_rng(seed))
    qp = DenseQP(H, g, C, lower, upper, n_eq=6, dense=9)
    x = qp.solve().copy()
    sense = np.zeros(len(lower), dtype=np.int32)
    sense[:6] = EQUALITY
    expected, _, flag, _ = daqp.solve(H, g, C, upper, lower, sense, primal_tol=1e-9)
    assert flag >= 1
    np.testing.assert_allclose(x, expected, rtol=1e-8, atol=1e-9)
    # the arrays are the QP: rewritten in place, solved again
    g[:] = np.random.default_rng(seed + 100).normal(size=len(g))
    expected, _, _, _ = daqp.solve(H, g, C, upper, lower, sense, primal_tol=1e-9)
    np.testing.assert_allclose(qp.solve(), expected, rtol=1e-8, atol=1e-9)


def test_an_infeasible_problem_is_refused():
    H, g, C, lower, upper = _problem(np.random.default_rng(9))
    lower[10], upper[10] = 1.0, -1.0
    with pytest.raises(InfeasibleQP, match="not solved"):
        DenseQP(H, g, C, lower, upper, n_eq=6, dense=9).solve()
