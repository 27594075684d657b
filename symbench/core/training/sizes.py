"""A network's size through its width keywords (`ModelEntry.widths`): scaled together, or
scaled to a parameter count, so that models can be compared at matched size.

The width keywords are scaled by one factor from their defaults and rounded (at least 1),
so the network keeps its proportions; the parameter count grows with the factor, and the
factor whose count is nearest the target is found by doubling, then bisection, on the first
width. A count the nearest network misses by more than MATCH_TOLERANCE is refused, naming the
count that can be built: such a run would not be at the size it claims (`--parameters 3`
would build 54 parameters).
"""

from __future__ import annotations

import math

from symbench.core.common.errors import SymbenchError
from symbench.core.config.provenance import build_hyperparameters
from symbench.core.data.views.model_dims import ModelDims
from symbench.core.plugin.entries import ModelEntry
from symbench.core.training.backends import get_backend

MAX_SCALE = 64  # the largest width factor tried when matching a parameter count
MIN_SCALE = 1e-3  # the smallest width factor `symbench tune` takes (every width is then 1)
# The relative miss a matched size may have: one step of the first width moves a small graph
# network's count by about 5 % (gnn at 20 000 parameters misses by 5.1 %), so 10 % leaves
# every built-in model matchable from a few thousand parameters up.
MATCH_TOLERANCE = 0.10


def scaled_widths(entry: ModelEntry, scale: float) -> dict[str, int]:
    """The model's width keywords at `scale` x their defaults (at least 1 each)."""
    defaults = _width_defaults(entry)
    return {w: max(1, round(d * scale)) for w, d in defaults.items()}


def parameter_count(entry: ModelEntry, dims: ModelDims, hyper: dict[str, int]) -> int:
    """Counted from shapes, nothing allocated: the search looks at networks up to MAX_SCALE x
    wider, gigabytes for `--parameters 1e12`."""
    shapes = get_backend(entry.backend).parameter_shapes(entry, dims, hyper)
    return sum(math.prod(shape) for shape in shapes.values())


def matched_widths(entry: ModelEntry, dims: ModelDims, target: int) -> dict[str, int]:
    """The width keywords whose network has the parameter count nearest `target`, within
    MATCH_TOLERANCE of it."""
    if target < 1:
        raise SymbenchError(f"a parameter count must be at least 1, got {target}")
    if not entry.widths:
        raise SymbenchError(
            f"model '{entry.name}' declares no widths (ModelEntry.widths), so its size "
            "cannot be matched to a parameter count"
        )
    first = _width_defaults(entry)[entry.widths[0]]

    def sized(width: int) -> tuple[dict[str, int], int]:
        hyper = scaled_widths(entry, width / first)
        return hyper, parameter_count(entry, dims, hyper)

    low, high = 1, first
    while sized(high)[1] < target:  # doubling from the defaults: huge networks are never built
        if high >= first * MAX_SCALE:
            raise SymbenchError(
                f"model '{entry.name}' stays below {target} parameters at {MAX_SCALE} x its widths"
            )
        low, high = high, 2 * high
    while high - low > 1:  # the smallest first width whose count reaches the target
        middle = (low + high) // 2
        low, high = (middle, high) if sized(middle)[1] < target else (low, middle)
    hyper, count = min((sized(w) for w in (low, high)), key=lambda c: abs(c[1] - target))
    if abs(count - target) > MATCH_TOLERANCE * target:
        widths = ", ".join(f"{k}={v}" for k, v in hyper.items())
        raise SymbenchError(
            f"--parameters {target}: the nearest {entry.name} has {count} parameters ({widths}), "
            f"{abs(count - target) / target:.0%} off, beyond the {MATCH_TOLERANCE:.0%} a matched "
            f"size allows; nearest buildable: --parameters {count}"
        )
    return hyper


def _width_defaults(entry: ModelEntry) -> dict[str, int]:
    defaults = build_hyperparameters(entry, {})
    missing = [w for w in entry.widths if not isinstance(defaults.get(w), int)]
    if missing:
        raise SymbenchError(
            f"model '{entry.name}' names widths {', '.join(missing)} that its build function "
            "has no integer default for"
        )
    return {w: defaults[w] for w in entry.widths}
