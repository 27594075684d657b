"""Exact equivariance checks of the physical claim: turning the robot by a symmetry step and
relabelling its legs relabels the model's torques.

For every element g of the robot's group the kit acts on plausible raw states (the base
turned about its normal, the legs relabelled: `act_on_raw`), recomputes the model's own view
from them, and compares f(view(g . raw)) with g . f(view(raw)), in float64 and in float32
(the comparison itself in float64). The relative error of an element is
max |f(g . x) - g . f(x)| / max |g . f(x)| over all samples. Every view is measured, so a
model that claims no equivariance gets its measured error.

Known-wrong transformations run beside the true ones as controls and must fail: the base
turned but the legs not relabelled, the inverse rotation (where it differs from the element)
and the legs relabelled one leg too far. A control that passes means the check could not
have failed, and the kit raises `ControlPassedError`.

Networks are checked with random parameters (every parameter perturbed, so that
zero-initialized biases or embeddings cannot hide a broken symmetry) and random
normalization statistics of the structure training uses, so the whole prediction path,
normalization included, is tested.

`element_errors` is the older, weaker view-level permutation check (permute the legs of
random leg-grouped inputs): necessary, not sufficient, since it never looks at frames.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from symbench.core.common.errors import SymbenchError
from symbench.core.common.fit_errors import relative_error
from symbench.core.data.symmetry import raw_action
from symbench.core.data.views import schema
from symbench.core.data.views.frames import LegFrames
from symbench.core.data.views.model_dims import dims_for
from symbench.core.data.views.transforms import build_view
from symbench.core.plugin.entries import ModelEntry
from symbench.core.symmetry.groups import GroupElement, LegGroup
from symbench.core.training.backends import get_backend
from symbench.core.training.normalization import Normalizer
from symbench.testing.raw_states import (
    RawStates,
    regular_frames,
    robot_frames,
    synthetic_raw_states,
)

TOLERANCES = {"float64": 1e-10, "float32": 1e-5}
DTYPES = {"float64": np.float64, "float32": np.float32}
Predict = Callable[[np.ndarray], np.ndarray]  # (N, legs, F) -> (N, legs, 3)


@dataclass(frozen=True)
class ElementError:
    element: str
    perm: tuple[int, ...]
    reflect: bool
    errors: dict[str, float]  # dtype name -> max relative error


@dataclass(frozen=True)
class ControlError:
    """A known-wrong transformation, compared as if it were `element`: it must fail."""

    control: str
    element: str
    errors: dict[str, float]  # dtype name -> max relative error

    def failed(self, tolerances: Mapping[str, float]) -> bool:
        return all(self.errors[d] > t for d, t in tolerances.items())


class ControlPassedError(SymbenchError):
    """A control transformation passed: the check could not have failed."""


@dataclass(frozen=True)
class EquivarianceReport:
    model: str
    backend: str
    group: str
    n_legs: int
    claims: bool  # the model claims equivariance under the robot's group
    elements: tuple[ElementError, ...] = ()  # empty when the view has no group action
    note: str = ""
    tolerances: dict[str, float] = field(default_factory=lambda: dict(TOLERANCES))
    controls: tuple[ControlError, ...] = ()
    view: str = ""

    @property
    def measured(self) -> bool:
        return bool(self.elements)

    def max_error(self, dtype: str) -> float:
        return max((e.errors[dtype] for e in self.elements), default=float("nan"))

    @property
    def equivariant(self) -> bool:
        """Every element within tolerance in every dtype (False when not measured)."""
        return self.measured and all(
            e.errors[d] <= self.tolerances[d] for e in self.elements for d in self.tolerances
        )

    @property
    def passed(self) -> bool:
        """A model that claims no equivariance cannot fail; one that claims it must hold it."""
        return not self.claims or self.equivariant

    def over_tolerance(self) -> list[tuple[ElementError, str]]:
        """The (element, dtype) pairs over tolerance, furthest over first."""
        found = [(e, d) for e in self.elements for d in self.tolerances if self._ratio(e, d) > 1]
        return sorted(found, key=lambda pair: -self._ratio(*pair))

    def _ratio(self, element: ElementError, dtype: str) -> float:
        return element.errors[dtype] / self.tolerances[dtype]

    def _worst(self) -> str:
        """' under <element> (...)' of the element furthest over, '' when none is over."""
        over = self.over_tolerance()
        if not over:
            return ""
        (worst, dtype), others = over[0], len({e.element for e, _ in over}) - 1
        more = f"; {others} more elements break it" if others else ""
        return (
            f" under {worst.element} (legs -> {list(worst.perm)}): {dtype} error "
            f"{worst.errors[dtype]:.2e} > {self.tolerances[dtype]:g}{more}"
        )

    @property
    def verdict(self) -> str:
        """One line; a broken claim names the element that breaks it furthest (relative to
        the tolerance), so that the line alone says where to look."""
        if self.claims and self.equivariant:
            return "equivariant"
        if self.claims:
            return "BROKEN: claims equivariance and breaks it" + self._worst()
        if self.measured and self.equivariant:
            return "equivariant, though it claims no equivariance"
        if self.measured:
            return (
                "not equivariant (claims none): measured max error "
                f"{self.max_error('float64'):.2e} (float64)"
            )
        return "not equivariant (claims none)"

    @property
    def controls_failed(self) -> bool:
        """Every control transformation failed, as it must."""
        return all(c.failed(self.tolerances) for c in self.controls)

    def to_dict(self) -> dict[str, Any]:
        return {
            "model": self.model,
            "backend": self.backend,
            "group": self.group,
            "n_legs": self.n_legs,
            "claims_equivariance": self.claims,
            "equivariant": self.equivariant,
            "passed": self.passed,
            "verdict": self.verdict,
            "note": self.note,
            "tolerances": self.tolerances,
            "max_error": {d: _json_float(self.max_error(d)) for d in self.tolerances},
            "elements": [
                {
                    "element": e.element,
                    "perm": list(e.perm),
                    "reflect": e.reflect,
                    **{d: e.errors[d] for d in self.tolerances},
                }
                for e in self.elements
            ],
            "controls": [
                {
                    "control": c.control,
                    "element": c.element,
                    "failed_as_it_must": c.failed(self.tolerances),
                    **{d: c.errors[d] for d in self.tolerances},
                }
                for c in self.controls
            ],
        }

    def table(self) -> str:
        """Plain-text table, for assertion messages."""
        lines = [
            f"{self.model}/{self.backend} on {self.group} ({self.n_legs} legs): {self.verdict}"
        ]
        if self.note:
            lines.append(f"  {self.note}")
        for e in self.elements:
            cells = "  ".join(
                f"{d} {e.errors[d]:.2e}" + ("" if e.errors[d] <= self.tolerances[d] else " (over)")
                for d in self.tolerances
            )
            lines.append(f"  {e.element:>9}  {cells}")
        for c in self.controls:
            cells = "  ".join(f"{d} {c.errors[d]:.2e}" for d in self.tolerances)
            state = "fails, as it must" if c.failed(self.tolerances) else "PASSES: no check"
            lines.append(f"  control {c.control} ({c.element}): {cells}  {state}")
        return "\n".join(lines)


def element_errors(
    predictors: Mapping[str, Predict],
    group: LegGroup,
    n_features: int,
    input_signs: np.ndarray | None = None,
    target_signs: np.ndarray | None = None,
    n_samples: int = 32,
    seed: int = 0,
) -> tuple[ElementError, ...]:
    """The view-level permutation check (necessary, not sufficient): errors of `predictors`
    (dtype name -> function of leg-grouped inputs) for each element, on random leg-grouped
    inputs whose legs are permuted. Any network with weights shared across legs passes it; it
    never turns a base, so it cannot see a wrong frame (`check_model` does).

    One call per dtype: x and every g . x are stacked into one batch. The action (and the
    comparison) happen in float64; the predictor receives its dtype's cast of the inputs.
    """
    rng = np.random.default_rng(seed)
    x = rng.normal(size=(n_samples, group.n_legs, n_features))
    batch = np.concatenate([x] + [group.act(g, x, input_signs) for g in group])
    found: dict[Any, dict[str, float]] = {g: {} for g in group}
    for name, predict in predictors.items():
        y_all = np.asarray(predict(batch.astype(DTYPES[name])), dtype=np.float64)
        y = y_all[:n_samples]
        for k, g in enumerate(group, start=1):
            actual = y_all[k * n_samples : (k + 1) * n_samples]
            found[g][name] = relative_error(actual, group.act(g, y, target_signs))
    return tuple(ElementError(g.name, g.perm, g.reflect, found[g]) for g in group)


Inputs = dict[str, np.ndarray]


def resolve_robot(
    group: LegGroup | str, frames: LegFrames | None = None
) -> tuple[LegGroup, LegFrames, str | LegFrames]:
    """(group, leg frames, what `synthetic_raw_states` takes) for a robot name or a group.

    A registered robot's name gives its own group and frames; a bare group is checked on
    `frames` or, without them, on a regular robot with that many legs."""
    if isinstance(group, str):
        from symbench.testing.groups import robot_group

        return robot_group(group), robot_frames(group), group
    frames = frames if frames is not None else regular_frames(group.n_legs)
    return group, frames, frames


def model_predictors(
    entry: ModelEntry,
    n_legs: int,
    seed: int = 0,
    hyper: dict[str, Any] | None = None,
    params: dict[str, np.ndarray] | None = None,
    normalizer: Normalizer | None = None,
    dtypes: tuple[str, ...] = tuple(DTYPES),
) -> dict[str, Callable[[Inputs], np.ndarray]]:
    """dtype name -> the model's prediction (view inputs -> torques (N, legs, 3)), with random
    parameters (every one perturbed) and normalization statistics unless given."""
    dims = dims_for(entry.view, entry.variant, n_legs)
    rng = np.random.default_rng([seed, 1])
    backend = get_backend(entry.backend)
    if params is None:
        params = {
            k: v + 0.1 * rng.standard_normal(v.shape)
            for k, v in backend.init_params(entry, dims, hyper or {}, seed).items()
        }
    normalizer = normalizer or Normalizer.random(dims, rng)
    predictors: dict[str, Callable[[Inputs], np.ndarray]] = {}
    for name in dtypes:
        predict = backend.make_predictor(
            entry, dims, hyper or {}, params, normalizer, DTYPES[name], backend.default_compiled
        )

        def run(inputs: Inputs, predict=predict, dtype=DTYPES[name]) -> np.ndarray:
            cast = {k: np.asarray(v).astype(dtype) for k, v in inputs.items()}
            return np.asarray(predict(cast), dtype=np.float64)

        predictors[name] = run
    return predictors


def predict_stacked(
    predict: Callable[[Inputs], np.ndarray], batches: list[Inputs]
) -> list[np.ndarray]:
    """One call for many input batches of the same view (stacked on the sample axis)."""
    sizes = [len(next(iter(b.values()))) for b in batches]
    stacked = {k: np.concatenate([b[k] for b in batches]) for k in batches[0]}
    return np.split(predict(stacked), np.cumsum(sizes)[:-1])


def view_of(entry: ModelEntry, raw: Mapping[str, np.ndarray], states: RawStates) -> Inputs:
    return build_view(raw, states.trajectory, states.frames, entry.view, entry.variant).inputs


def control_transforms(
    group: LegGroup, frames: LegFrames, raw: Mapping[str, np.ndarray]
) -> list[tuple[str, GroupElement, dict[str, np.ndarray]]]:
    """Known-wrong transformations of `raw`, each paired with the element it pretends to be.

    For every rotation other than the identity: the base turned but the legs not relabelled;
    the legs relabelled but the base turned the other way (only where that is a different
    turn: a half turn is its own inverse); the base turned but the legs relabelled one leg
    too far. For every mirror: the scene mirrored and the legs relabelled, but the legs'
    coxa angles, velocities and torques left unflipped."""
    out = []
    for g in group:
        if g == group.identity:
            continue
        if g.reflect:
            mirrored = raw_action.act_on_raw(g, raw, frames)
            unflipped = raw_action.relabel_legs(
                mirrored,
                np.arange(group.n_legs),
                np.asarray(schema.FeatureType.JOINT.reflection_signs),
            )
            out.append(("mirrored, coxa columns not flipped", g, unflipped))
            continue
        angle = raw_action.rotation_angle(frames, g)
        src = g.source_legs()
        relabelled = raw_action.relabel_legs(raw, src)
        out.append(("base turned, legs not relabelled", g, raw_action.turn_base(raw, -angle)))
        if abs(np.sin(angle)) > 1e-9:
            out.append(("inverse rotation", g, raw_action.turn_base(relabelled, angle)))
        one_too_far = raw_action.relabel_legs(raw, np.roll(src, 1))
        out.append(("legs relabelled one too far", g, raw_action.turn_base(one_too_far, -angle)))
    return out


def check_model(
    entry: ModelEntry,
    group: LegGroup | str,
    n_samples: int = 32,
    seed: int = 0,
    hyper: dict[str, Any] | None = None,
    params: dict[str, np.ndarray] | None = None,
    normalizer: Normalizer | None = None,
    frames: LegFrames | None = None,
) -> EquivarianceReport:
    """The physical check of a registered model (random or given parameters) under every
    element of `group` (a `LegGroup`, or a registered robot's name: its group and frames),
    with the control transformations. Raises `ControlPassedError` when a control passes."""
    group, frames, source = resolve_robot(group, frames)
    states = synthetic_raw_states(source, n_samples, seed)
    raw = states.raw
    controls = control_transforms(group, frames, raw)
    moved = [raw_action.act_on_raw(g, raw, frames) for g in group]
    batches = [view_of(entry, r, states) for r in [raw, *moved, *(c[2] for c in controls)]]
    predictors = model_predictors(entry, group.n_legs, seed, hyper, params, normalizer)
    found: dict[GroupElement, dict[str, float]] = {g: {} for g in group}
    control_found: list[dict[str, float]] = [{} for _ in controls]
    signs = schema.TARGET.reflection_signs
    for name, predict in predictors.items():
        y, *rest = predict_stacked(predict, batches)
        for g, actual in zip(group, rest[: group.order], strict=True):
            found[g][name] = relative_error(actual, group.act(g, y, signs))
        for k, ((_, g, _), actual) in enumerate(zip(controls, rest[group.order :], strict=True)):
            control_found[k][name] = relative_error(actual, group.act(g, y, signs))
    report = EquivarianceReport(
        entry.name,
        entry.backend,
        group.name,
        group.n_legs,
        entry.equivariant,
        tuple(ElementError(g.name, g.perm, g.reflect, found[g]) for g in group),
        f"raw states turned and relabelled, the {entry.view} view recomputed",
        controls=tuple(
            ControlError(c[0], c[1].name, errs) for c, errs in zip(controls, control_found)
        ),
        view=entry.view,
    )
    if not report.controls_failed:
        raise ControlPassedError(
            "a control transformation passed, so this check could not have failed\n"
            + report.table()
        )
    return report


def assert_equivariant(
    entry: ModelEntry, group: LegGroup | str, **kwargs: Any
) -> EquivarianceReport:
    """`check_model`, failing the calling test with the per-element table when it breaks."""
    report = check_model(entry, group, **kwargs)
    if not report.equivariant:
        raise AssertionError("equivariance broken\n" + report.table())
    return report


def _json_float(x: float) -> float | None:
    return None if np.isnan(x) else x
