"""The trained model's equivariance error under the robot's group, on test scenes.

Each group element acts on the raw test states (rotate the base, relabel the legs); the
model's own view is recomputed from them, so every representation gets the same question:
does f(g . x) equal g . f(x)? Zero to float precision for models built to be equivariant.

The robot's group (its rotations, the board's column) gives `max_rel_error`. Where the
robot's geometry also has mirrors (hexa's D6 beside its C6), they are measured too, as
`mirror_max_rel_error`: near zero only for a model built for the larger group (sdnn with
`mirror=1`), so the board shows which models respect the mirrors, not only that they could.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

if TYPE_CHECKING:  # symbench's names load the data stack: when a run evaluates, not with the CLI
    from symbench import EvaluationContext

NAME = "equivariance"
DESCRIPTION = (
    "max relative error |f(g.x) - g.f(x)| / |g.f(x)| over the robot's group, and over the "
    "mirrors of its geometry"
)


def evaluate(context: EvaluationContext) -> dict:
    from symbench import act, act_on_raw, relative_error, schema

    raw, ids = context.test_raw()
    frames = context.dataset.frames
    base = context.predict_raw(raw, ids)

    def error(g) -> float:
        moved = context.predict_raw(act_on_raw(g, raw, frames), ids)
        return relative_error(moved, act(g, base, schema.TARGET.reflection_signs))

    group, geometry = context.robot.group, context.robot.geometry_group
    per_element = {g.name: error(g) for g in group}
    out = {
        "max_rel_error": max(per_element.values()),
        "per_element": per_element,
        "group": group.name,
        "samples": int(len(base)),
    }
    mirrors = {g.name: error(g) for g in geometry if g not in group}
    if mirrors:
        out["geometry_group"] = geometry.name
        out["mirror_max_rel_error"] = max(mirrors.values())
        out["mirror_per_element"] = mirrors
    return out
