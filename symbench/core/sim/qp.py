"""A dense QP of fixed structure, solved by proxsuite with warm starts.

min 1/2 x'Hx + g'x  s.t.  A x = b,  l <= C x <= u.  The structure (sizes) never changes
during a rollout: constraints that do not apply are given infinite bounds instead of being
removed, so one solver object is reused and warm-started from the previous solution. The
tolerance is tight and H is strictly convex, so the solution is unique and does not depend
on the order of the variables beyond rounding: that keeps the controller label-equivariant.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from symbench.core.common.errors import SymbenchError

INF = 1e8
EPS_ABS = 1e-10


class DenseQP:
    def __init__(self, n: int, n_eq: int, n_in: int, eps_abs: float = EPS_ABS):
        import proxsuite

        self._proxqp = proxsuite.proxqp
        self._dims, self._eps = (n, n_eq, n_in), eps_abs
        self._solved = proxsuite.proxqp.QPSolverOutput.PROXQP_SOLVED
        self._qp: Any = None  # proxsuite's dense QP, made on the first solve

    def _fresh(self):
        qp = self._proxqp.dense.QP(*self._dims)
        settings = qp.settings
        settings.eps_abs = self._eps
        settings.eps_rel = 0.0
        settings.max_iter = 10_000
        settings.verbose = False
        settings.initial_guess = self._proxqp.InitialGuess.WARM_START_WITH_PREVIOUS_RESULT
        return qp

    def solve(self, H, g, A, b, C, l, u) -> np.ndarray:  # noqa: E741 (the QP's own names)
        """The minimiser; a warm start that fails is retried cold, then InfeasibleQP."""
        if self._qp is not None:
            self._qp.update(H, g, A, b, C, l, u, update_preconditioner=False)
            self._qp.solve()
            if self._qp.results.info.status == self._solved:
                return self._qp.results.x
        self._qp = self._fresh()
        self._qp.init(H, g, A, b, C, l, u, compute_preconditioner=False)
        self._qp.solve()
        if self._qp.results.info.status != self._solved:
            raise InfeasibleQP(f"whole-body QP not solved ({self._qp.results.info.status})")
        return self._qp.results.x


class InfeasibleQP(SymbenchError):
    """The QP has no solution (or the solver did not find one)."""
