"""Checks shared by the backends, so that a faulty network is named, not traced back."""

from __future__ import annotations

from typing import Any

from symbench.core.common.errors import SymbenchError
from symbench.core.data.views.model_dims import ModelDims
from symbench.core.plugin.entries import ModelEntry


def check_output(entry: ModelEntry, dims: ModelDims, shape: tuple[int, ...], n: int) -> None:
    expected = (n, dims.n_legs, 3)
    if tuple(shape) != expected:
        raise SymbenchError(
            f"model {entry.name}/{entry.backend} returned torques shaped "
            f"{tuple(shape)}, expected {expected} (N, n_legs, 3)"
        )


def check_params(
    entry: ModelEntry, expected: dict[str, tuple[int, ...]], given: dict[str, Any]
) -> None:
    """Same names and shapes as the freshly built network, or a message naming the difference."""
    missing = sorted(set(expected) - set(given))
    extra = sorted(set(given) - set(expected))
    wrong = sorted(
        k for k in set(expected) & set(given) if tuple(given[k].shape) != tuple(expected[k])
    )
    if missing or extra or wrong:
        parts = [
            f"missing {missing}" if missing else "",
            f"unexpected {extra}" if extra else "",
            "wrong shape "
            + ", ".join(f"{k} {tuple(given[k].shape)} != {tuple(expected[k])}" for k in wrong)
            if wrong
            else "",
        ]
        raise SymbenchError(
            f"parameters do not fit model {entry.name}/{entry.backend}: "
            + "; ".join(p for p in parts if p)
        )


def build_error(entry: ModelEntry, exc: Exception) -> SymbenchError:
    return SymbenchError(
        f"model {entry.name}/{entry.backend} could not be built: {type(exc).__name__}: {exc}"
    )
