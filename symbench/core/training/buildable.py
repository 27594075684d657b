"""Build keywords set by hand (`--size NAME=INT`) checked by building the network's shapes
once, before any work (nothing allocated): torch builds a zero-width layer with only a warning
and trains it to nothing, a negative step count silently means none, and a value the build
function refuses would otherwise surface mid-run. A value that cannot build the asked network
is refused in one line naming it and the nearest value that builds.

The rule, for any model: a width keyword (`ModelEntry.widths`) is at least 1, every other
build keyword at least 0 (sizes are counts, switches are 0 or 1); none is above MAX_SCALE x
its default (at least 1), the ceiling `--parameters` searches under, so that no value asks
for a network too large to allocate or too deep to run; and the network builds, with no
parameter tensor of zero elements. A `symbench tune` width scale is held to the same rule:
its widths at most MAX_SCALE x their defaults, and a network that builds.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence

from symbench.core.common.errors import SymbenchError
from symbench.core.config.provenance import build_hyperparameters
from symbench.core.data.views.model_dims import ModelDims
from symbench.core.plugin.entries import ModelEntry
from symbench.core.training.backends import get_backend
from symbench.core.training.sizes import MAX_SCALE, MIN_SCALE, scaled_widths

NEAREST_SEARCH = 8  # how far from a refused value the nearest buildable one is looked for


def check_buildable(
    entry: ModelEntry, dims: ModelDims, hyper: Mapping[str, int], given: Mapping[str, int]
) -> None:
    """Refuses the build keywords `given` by hand (a subset of `hyper`, the network's whole
    set) when the network cannot be built with them, naming the value and the nearest one
    that builds."""
    bounds = {name: _bounds(entry, name) for name in given}
    # every value moved into its bounds: the search for the nearest builds nothing out of them
    bounded = {**hyper, **{k: min(max(v, bounds[k][0]), bounds[k][1]) for k, v in given.items()}}
    for name, value in given.items():
        low, high = bounds[name]
        if value > high:  # not built: a network that large is what the bound avoids
            raise SymbenchError(
                f"--size {name}={value}: model {_named(entry)} allows at most {MAX_SCALE} x "
                f"its default; the nearest allowed: {name}={high}"
            )
        if value < low:
            least = f"{'a width' if low else 'a size'} of model {_named(entry)} is at least {low}"
            raise _refusal(name, value, least, _nearest(entry, dims, bounded, name, value))
    why = _why_not(entry, dims, hyper) if given else None
    if why is not None:
        for name, value in given.items():  # the first keyword that builds when moved a little
            nearest = _nearest(entry, dims, hyper, name, value)
            if nearest is not None:
                raise _refusal(name, value, why, nearest)
        raise SymbenchError(
            f"--size {_keywords(given)}: {why}, nor does any value within {NEAREST_SEARCH} of them"
        )


def check_width_scales(entry: ModelEntry, dims: ModelDims, scales: Sequence[float]) -> None:
    """Refuses a width scale (`symbench tune --width-scales`) outside [MIN_SCALE, MAX_SCALE]
    or whose network cannot be built, naming it and the nearest scale that builds: a scale
    of 1000 asked torch for 590 GB mid-search."""
    for scale in scales:
        if not MIN_SCALE <= scale <= MAX_SCALE:
            allowed = min(max(scale, MIN_SCALE), MAX_SCALE)
            raise SymbenchError(
                f"--width-scales {scale:g}: a width scale of model {_named(entry)} is in "
                f"[{MIN_SCALE:g}, {MAX_SCALE}]; the nearest allowed: {allowed:g}"
            )
        widths = scaled_widths(entry, scale)
        why = _why_not(entry, dims, widths)
        if why is not None:
            nearest = _nearest_scale(entry, dims, scale)
            hint = (
                f"nearest buildable: {nearest:.4g} ({_keywords(scaled_widths(entry, nearest))})"
                if nearest is not None
                else f"no scale builds within {NEAREST_SEARCH} steps of its first width"
            )
            raise SymbenchError(f"--width-scales {scale:g} ({_keywords(widths)}): {why}; {hint}")


def _nearest_scale(entry: ModelEntry, dims: ModelDims, scale: float) -> float | None:
    """The width scale nearest `scale` whose network builds, in steps of one on the first
    width (the nearest first, the smaller of two as near), within NEAREST_SEARCH steps and
    within [MIN_SCALE, MAX_SCALE]; None if there is none."""
    base = scaled_widths(entry, 1.0)[entry.widths[0]]
    start = scaled_widths(entry, scale)[entry.widths[0]]
    steps = sorted(range(-NEAREST_SEARCH, NEAREST_SEARCH + 1), key=lambda d: (abs(d), d))
    tries = [(start + d) / base for d in steps if d and start + d >= 1]
    return next(
        (
            s
            for s in tries
            if MIN_SCALE <= s <= MAX_SCALE
            and _why_not(entry, dims, scaled_widths(entry, s)) is None
        ),
        None,
    )


def _bounds(entry: ModelEntry, name: str) -> tuple[int, int]:
    """The least and greatest value keyword `name` may take."""
    default = build_hyperparameters(entry, {}).get(name)
    scale = abs(default) if isinstance(default, int) and not isinstance(default, bool) else 1
    return (1 if name in entry.widths else 0), MAX_SCALE * max(scale, 1)


def _why_not(entry: ModelEntry, dims: ModelDims, hyper: Mapping[str, int]) -> str | None:
    """Why the network of `hyper` cannot be built (None: it can). A plugin's build function
    may raise anything, so every exception is a reason."""
    try:
        shapes = get_backend(entry.backend).parameter_shapes(entry, dims, dict(hyper))
    except Exception as error:  # the plugin's error, whatever it is, reported in words
        if isinstance(error, SymbenchError):  # the backend's, naming the model
            return str(error)
        return f"model {_named(entry)} could not be built: {type(error).__name__}: {error}"
    empty = sorted(k for k, shape in shapes.items() if 0 in shape)
    return f"model {_named(entry)} would have no elements in {empty[0]}" if empty else None


def _nearest(
    entry: ModelEntry, dims: ModelDims, hyper: Mapping[str, int], name: str, value: int
) -> int | None:
    """The value of keyword `name` nearest `hyper[name]` (the smaller of two as near), other
    than the refused `value`, with which the network builds, within NEAREST_SEARCH of it and
    within its bounds; None if there is none."""
    (low, high), start = _bounds(entry, name), hyper[name]
    tries = sorted(
        (v for v in range(start - NEAREST_SEARCH, start + NEAREST_SEARCH + 1) if low <= v <= high),
        key=lambda v: (abs(v - start), v),
    )
    return next(
        (v for v in tries if v != value and _why_not(entry, dims, {**hyper, name: v}) is None),
        None,
    )


def _refusal(name: str, value: int, why: str, nearest: int | None) -> SymbenchError:
    hint = (
        f"nearest buildable: {name}={nearest}"
        if nearest is not None
        else f"no value within {NEAREST_SEARCH} of it builds"
    )
    return SymbenchError(f"--size {name}={value}: {why}; {hint}")


def _keywords(values: Mapping[str, int]) -> str:
    return ", ".join(f"{k}={v}" for k, v in values.items())


def _named(entry: ModelEntry) -> str:
    return f"{entry.name}/{entry.backend}"
