"""Exact equivariance checks: f(g . x) == g . f(x) for every element g of a robot's group.

Many random inputs, the model evaluated in float64 and in float32, the group action applied
in float64 on both sides. The relative error of an element is
max |f(g . x) - g . f(x)| / max |g . f(x)| over all samples. Networks are checked with random
parameters (every parameter perturbed, so that zero-initialized biases or embeddings cannot
hide a broken symmetry) and random normalization statistics of the structure training uses,
so the whole prediction path, normalization included, is tested.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from symbench.core.data import schema
from symbench.core.data.model_dims import dims_for
from symbench.core.plugin.entries import ModelEntry
from symbench.core.runs.evaluation import relative_error
from symbench.core.symmetry.groups import LegGroup
from symbench.core.training.backends import get_backend
from symbench.core.training.normalization import Normalizer

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
class EquivarianceReport:
    model: str
    backend: str
    group: str
    n_legs: int
    claims: bool  # the model claims equivariance under the robot's group
    elements: tuple[ElementError, ...] = ()  # empty when the view has no group action
    note: str = ""
    tolerances: dict[str, float] = field(default_factory=lambda: dict(TOLERANCES))

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

    @property
    def verdict(self) -> str:
        if self.claims:
            return (
                "equivariant" if self.equivariant else "BROKEN: claims equivariance and breaks it"
            )
        if self.measured and self.equivariant:
            return "equivariant, though it claims no equivariance"
        return "not equivariant (claims none)"

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
    """Errors of `predictors` (dtype name -> function of leg-grouped inputs) for each element.

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


def check_model(
    entry: ModelEntry,
    group: LegGroup,
    n_samples: int = 32,
    seed: int = 0,
    hyper: dict[str, Any] | None = None,
    params: dict[str, np.ndarray] | None = None,
    normalizer: Normalizer | None = None,
) -> EquivarianceReport:
    """Check a registered model (random or given parameters) under every element of `group`."""

    def report(elements=(), note=""):
        return EquivarianceReport(
            entry.name,
            entry.backend,
            group.name,
            group.n_legs,
            entry.equivariant,
            tuple(elements),
            note,
        )

    if entry.view != "leg_grouped":
        return report(note=f"the {entry.view} view has no leg-permutation action; not measured")
    dims = dims_for(entry.view, entry.variant, group.n_legs)
    rng = np.random.default_rng([seed, 1])
    backend = get_backend(entry.backend)
    if params is None:
        params = {
            k: v + 0.1 * rng.standard_normal(v.shape)
            for k, v in backend.init_params(entry, dims, hyper or {}, seed).items()
        }
    normalizer = normalizer or Normalizer.random(dims, rng)
    predictors = {}
    for name, dtype in DTYPES.items():
        predict = backend.make_predictor(
            entry, dims, hyper or {}, params, normalizer, dtype, backend.default_compiled
        )
        predictors[name] = lambda x, predict=predict: predict({"x": x})
    layout = schema.leg_grouped_input(entry.variant)
    return report(
        element_errors(
            predictors,
            group,
            layout.size,
            layout.reflection_signs,
            schema.TARGET.reflection_signs,
            n_samples,
            seed,
        )
    )


def assert_equivariant(entry: ModelEntry, group: LegGroup, **kwargs: Any) -> EquivarianceReport:
    """`check_model`, failing the calling test with the per-element table when it breaks."""
    report = check_model(entry, group, **kwargs)
    if not report.equivariant:
        raise AssertionError("equivariance broken\n" + report.table())
    return report


def _json_float(x: float) -> float | None:
    return None if np.isnan(x) else x
