"""Per-sample input shapes of a view: what a network builder needs to size its layers.

`dims_for` derives them from the schema alone (the equivariance kit builds networks without
data); `dims_of` reads them from data and checks them against the schema, so a dataset of the
wrong shape is named before any network sees it.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from symbench.core.common.arrays import ViewArrays
from symbench.core.common.errors import SymbenchError, UnknownNameError
from symbench.core.data.views import schema


@dataclass(frozen=True)
class ModelDims:
    view: str
    variant: str
    n_legs: int
    inputs: tuple[tuple[str, tuple[int, ...]], ...]  # (key, per-sample shape), in call order

    def shape(self, key: str) -> tuple[int, ...]:
        return dict(self.inputs)[key]

    @property
    def keys(self) -> tuple[str, ...]:
        return tuple(k for k, _ in self.inputs)

    def to_dict(self) -> dict[str, Any]:
        return {
            "view": self.view,
            "variant": self.variant,
            "n_legs": self.n_legs,
            "inputs": {k: list(s) for k, s in self.inputs},
        }

    @classmethod
    def from_dict(cls, d: dict[str, Any]) -> ModelDims:
        return dims_for(d["view"], d["variant"], int(d["n_legs"]))


def dims_for(view: str, variant: str, n_legs: int) -> ModelDims:
    """The shapes the schema declares for `view` of an `n_legs` robot."""
    inputs: tuple[tuple[str, tuple[int, ...]], ...]
    if view == "leg_grouped":
        inputs = (("x", (n_legs, schema.leg_grouped_input(variant).size)),)
    elif view == "vector":
        inputs = (("x", (schema.vector_input(n_legs, variant).size,)),)
    elif view == "body_graph":
        g = schema.body_graph(n_legs, variant)
        inputs = (
            ("nodes", (g.n_nodes, len(g.node_columns))),
            ("edges", (g.n_edges, len(g.edge_columns))),
            ("globals", (len(g.global_columns),)),
        )
    else:
        raise UnknownNameError("view", view, schema.VIEWS)
    return ModelDims(view, variant, n_legs, inputs)


def dims_of(arrays: ViewArrays) -> ModelDims:
    """The dims of `arrays`, after checking every input against the schema."""
    dims = dims_for(arrays.view, arrays.variant, arrays.n_legs)
    if set(arrays.inputs) != set(dims.keys):
        raise SymbenchError(
            f"{arrays.view}/{arrays.variant} data has inputs {sorted(arrays.inputs)}, "
            f"expected {list(dims.keys)}"
        )
    for key, shape in dims.inputs:
        got = tuple(arrays.inputs[key].shape[1:])
        if got != shape:
            raise SymbenchError(
                f"{arrays.view}/{arrays.variant} input '{key}' has per-sample shape "
                f"{got}, the schema says {shape} for {arrays.n_legs} legs"
            )
    return dims
