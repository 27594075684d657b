"""The trained model's equivariance error under the robot's group, on test scenes.

Each group element acts on the raw test states (rotate the base, relabel the legs); the
model's own view is recomputed from them, so every representation gets the same question:
does f(g . x) equal g . f(x)? Zero to float precision for models built to be equivariant.
"""

from __future__ import annotations

from symbench import EvaluationContext, act, act_on_raw, relative_error, schema

NAME = "equivariance"
DESCRIPTION = "max relative error |f(g.x) - g.f(x)| / |g.f(x)| over the robot's group"


def evaluate(context: EvaluationContext) -> dict:
    raw, ids = context.test_raw()
    frames = context.dataset.frames
    base = context.predict_raw(raw, ids)
    per_element = {}
    for g in context.robot.group:
        moved = context.predict_raw(act_on_raw(g, raw, frames), ids)
        per_element[g.name] = relative_error(moved, act(g, base, schema.TARGET.reflection_signs))
    return {
        "max_rel_error": max(per_element.values()),
        "per_element": per_element,
        "group": context.robot.group.name,
        "samples": int(len(base)),
    }
