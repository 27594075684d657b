"""The whole-body QP, solved by DAQP: a dual active-set solver made for small dense QPs.

min 1/2 x'Hx + g'x  s.t.  lower <= C x <= upper, the first `n_eq` rows equalities. The
structure (sizes) never changes during a rollout: constraints that do not apply get infinite
bounds instead of being removed. H is strictly convex, so the solution is unique and does
not depend on the order of the variables beyond rounding: that keeps the controller
label-equivariant. DAQP is plain C without CPU dispatch, so the same inputs give the same
bits on every x86-64 CPU.

Two things make it cheap enough for every 1 kHz step:
- H is block diagonal, a dense k x k block (base and swing accelerations) and a diagonal
  rest (the foot forces). With H = R'R, z = R x + R^-T g turns the QP into DAQP's native
  least-distance problem min 1/2 |z|^2 s.t. lower + C R^-1 R^-T g <= C R^-1 z <= ...,
  which is formed here (compiled) with the structure used, instead of DAQP factoring and
  multiplying dense matrices at every call (~10 us of its ~16 us).
- The solver is called through its C entry point `daqp_quadprog` (see `native`), on
  structures that point at preallocated arrays, from compiled code: the Python wrapper
  `daqp.solve` copies and validates every array and builds a result dict, costing more
  than the solve itself. The structures below mirror DAQP 0.11's `types.h` and `api.h`;
  `tests/sim/control/test_qp.py` checks the whole against `daqp.solve`.
"""

from __future__ import annotations

import ctypes

import numpy as np
from numba import njit

from symbench.core.common.errors import SymbenchError
from symbench.core.sim.climb import native

EQUALITY = 5  # DAQP's constraint sense: active and immutable
PRIMAL_TOL = 1e-9  # constraint violation accepted at the solution
NO_EQ_REDUCTION = -1  # equalities stay constraints (DAQP would eliminate them at every call)
_DOUBLE_P = ctypes.POINTER(ctypes.c_double)
_INT_P = ctypes.POINTER(ctypes.c_int)


class _Problem(ctypes.Structure):
    _fields_ = [
        ("n", ctypes.c_int),
        ("m", ctypes.c_int),
        ("ms", ctypes.c_int),
        ("H", _DOUBLE_P),
        ("f", _DOUBLE_P),
        ("A", _DOUBLE_P),
        ("bupper", _DOUBLE_P),
        ("blower", _DOUBLE_P),
        ("sense", _INT_P),
        ("break_points", _INT_P),
        ("nh", ctypes.c_int),
        ("problem_type", ctypes.c_int),
    ]


class _Settings(ctypes.Structure):
    _fields_ = [
        *((name, ctypes.c_double) for name in ("primal_tol", "dual_tol", "zero_tol")),
        *((name, ctypes.c_double) for name in ("pivot_tol", "progress_tol")),
        ("cycle_tol", ctypes.c_int),
        ("iter_limit", ctypes.c_int),
        *(
            (name, ctypes.c_double)
            for name in (
                "fval_bound",
                "eps_prox",
                "eta_prox",
                "rho_soft",
                "rel_subopt",
                "abs_subopt",
                "sing_tol",
                "refactor_tol",
                "time_limit",
                "w_soft",
            )
        ),
        ("eq_reduction", ctypes.c_int),
        ("presolve", ctypes.c_int),
    ]


class _Result(ctypes.Structure):
    _fields_ = [
        ("x", _DOUBLE_P),
        ("lam", _DOUBLE_P),
        ("fval", ctypes.c_double),
        ("soft_slack", ctypes.c_double),
        ("exitflag", ctypes.c_int),
        ("iter", ctypes.c_int),
        ("nodes", ctypes.c_int),
        ("solve_time", ctypes.c_double),
        ("setup_time", ctypes.c_double),
    ]


@njit(cache=True)
def to_ldp(H, g, C, lower, upper, k, r_inv, scale, v, M, ldp_lower, ldp_upper):
    """The least-distance form of the QP (module docstring): r_inv = R_k^-1 of the dense
    block's Cholesky factor, scale = 1 / sqrt of the diagonal rest, v = R^-T g,
    M = C R^-1 and the shifted bounds."""
    n = g.shape[0]
    chol = np.zeros((k, k))  # upper triangular, H_k = chol' chol
    for j in range(k):
        s = H[j, j]
        for p in range(j):
            s -= chol[p, j] * chol[p, j]
        chol[j, j] = np.sqrt(s)
        for c in range(j + 1, k):
            s = H[j, c]
            for p in range(j):
                s -= chol[p, j] * chol[p, c]
            chol[j, c] = s / chol[j, j]
    r_inv[:, :] = 0.0
    for j in range(k):  # back substitution, column by column of the identity
        r_inv[j, j] = 1.0 / chol[j, j]
        for r in range(j - 1, -1, -1):
            s = 0.0
            for p in range(r + 1, j + 1):
                s += chol[r, p] * r_inv[p, j]
            r_inv[r, j] = -s / chol[r, r]
    for j in range(k, n):
        scale[j - k] = 1.0 / np.sqrt(H[j, j])
    for j in range(k):  # v = R^-T g
        s = 0.0
        for p in range(j + 1):
            s += r_inv[p, j] * g[p]
        v[j] = s
    for j in range(k, n):
        v[j] = g[j] * scale[j - k]
    for row in range(C.shape[0]):
        shift = 0.0
        for j in range(k):
            s = 0.0
            for p in range(j + 1):
                s += C[row, p] * r_inv[p, j]
            M[row, j] = s
            shift += s * v[j]
        for j in range(k, n):
            M[row, j] = C[row, j] * scale[j - k]
            shift += M[row, j] * v[j]
        ldp_lower[row] = lower[row] + shift
        ldp_upper[row] = upper[row] + shift


@njit(cache=True)
def from_ldp(z, v, r_inv, scale, k, x):
    """x = R^-1 (z - v)."""
    for r in range(k):
        s = 0.0
        for j in range(r, k):
            s += r_inv[r, j] * (z[j] - v[j])
        x[r] = s
    for j in range(k, x.shape[0]):
        x[j] = (z[j] - v[j]) * scale[j - k]


@njit(cache=True)
def solve_in_place(qp) -> int:
    """Solve the QP that `DenseQP.kernel_args` describes: its minimiser goes to the x
    array given there; returns DAQP's exit flag (>= 1: solved)."""
    to_ldp_args, from_ldp_args, addresses, status_words, status_index = qp
    to_ldp(*to_ldp_args)
    native.daqp_quadprog(*addresses)
    status = status_words[status_index]
    if status >= 1:
        from_ldp(*from_ldp_args)
    return status


class DenseQP:
    """One QP of fixed sizes whose data live in the arrays given here: the caller rewrites
    them in place and calls `solve` (or, from compiled code, `solve_in_place` on
    `kernel_args`). H must be block diagonal: dense in its leading `dense` x `dense`
    block, diagonal after it (zeros elsewhere are not read). Arrays must be C-contiguous
    float64."""

    def __init__(self, H, g, C, lower, upper, n_eq: int, dense: int):
        arrays = (H, g, C, lower, upper)
        if any(a.dtype != np.float64 or not a.flags.c_contiguous for a in arrays):
            raise SymbenchError("the QP's arrays must be C-contiguous float64")
        n, m = len(g), len(lower)
        self.sense = np.zeros(m, dtype=np.int32)
        self.sense[:n_eq] = EQUALITY
        self.x, self._z, self._lam = np.zeros(n), np.zeros(n), np.zeros(m)
        r_inv, scale, v = np.zeros((dense, dense)), np.zeros(n - dense), np.zeros(n)
        M, ldp_lower, ldp_upper = np.zeros((m, n)), np.zeros(m), np.zeros(m)

        def ptr(a: np.ndarray, kind=_DOUBLE_P):
            return a.ctypes.data_as(kind)

        null = ctypes.POINTER(ctypes.c_double)()  # H = I, f = 0: a least-distance problem
        self._problem = _Problem(
            n, m, 0, null, null, ptr(M), ptr(ldp_upper), ptr(ldp_lower),
            ptr(self.sense, _INT_P), None, 0, 0,
        )  # fmt: skip
        self._settings = _Settings()
        native.DAQP.daqp_default_settings(ctypes.byref(self._settings))
        self._settings.primal_tol = PRIMAL_TOL
        self._settings.eq_reduction = NO_EQ_REDUCTION
        # the result structure lives in a numpy array, so that compiled code reads its flag
        words = np.zeros(-(-ctypes.sizeof(_Result) // 4), dtype=np.int32)
        self._result = _Result.from_buffer(words.data)
        self._result.x, self._result.lam = ptr(self._z), ptr(self._lam)
        self.kernel_args = (
            (H, g, C, lower, upper, dense, r_inv, scale, v, M, ldp_lower, ldp_upper),
            (self._z, v, r_inv, scale, dense, self.x),
            tuple(ctypes.addressof(s) for s in (self._result, self._problem, self._settings)),
            words,
            _Result.exitflag.offset // 4,
        )

    def solve(self) -> np.ndarray:
        """The minimiser of the arrays' current contents (a view, overwritten by the next
        solve), or InfeasibleQP."""
        status = solve_in_place(self.kernel_args)
        if status < 1:
            raise InfeasibleQP(f"whole-body QP not solved (DAQP exit flag {status})")
        return self.x


class InfeasibleQP(SymbenchError):
    """The QP has no solution (or the solver did not find one)."""
