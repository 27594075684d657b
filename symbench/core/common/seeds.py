"""The seeds symbench accepts: 0 to 2**32 - 1, which numpy, torch and JAX all take, so that
a seed means the same run on every backend instead of overflowing in one of them."""

from __future__ import annotations

from numbers import Integral

from symbench.core.common.errors import SymbenchError

SEED_MAX = 2**32 - 1


def check_seed(seed: int, what: str = "seed") -> int:
    """`seed` itself, or an error naming `what` and the valid range."""
    if isinstance(seed, bool) or not isinstance(seed, Integral) or not 0 <= seed <= SEED_MAX:
        raise SymbenchError(f"{what} must be an integer from 0 to {SEED_MAX}, got {seed!r}")
    return seed
