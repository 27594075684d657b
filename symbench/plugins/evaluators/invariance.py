"""Change of the trained model's output when test scenes are rotated about gravity and moved.

The paper's physics invariances: the torques needed for a motion do not depend on where the
scene is or how it is turned about gravity. Views are recomputed from the transformed raw
states. Where the model's view itself does not change (the leg-grouped view is computed in
the base frame), the invariance holds by construction: it is reported as such, with the
measured value, and says nothing about training. Otherwise it is measured, with a control
that must change the output: the robot tilted 30 degrees about a horizontal axis while
gravity stays, which changes the physics, so a model that ignored it could not be measured.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

if TYPE_CHECKING:  # symbench's names load the data stack: when a run evaluates, not with the CLI
    from symbench import EvaluationContext

NAME = "invariance"
DESCRIPTION = "max relative output change under random rotations about gravity + translations"
CONTROL_TILT_RAD = np.radians(30.0)
CONTROL_MIN_CHANGE = 1e-3


def evaluate(context: EvaluationContext) -> dict:
    from symbench import build_view, relative_error, rotate_scene, rotate_scene_about_gravity

    raw, ids = context.test_raw()
    entry, frames = context.entry, context.dataset.frames
    inputs = build_view(raw, ids, frames, entry.view, entry.variant).inputs
    base = context.predict_raw(raw, ids)
    rng = np.random.default_rng([context.seed, 7])
    trials, view_change = [], 0.0
    for _ in range(context.preset.evaluation.invariance_trials):
        angle = float(rng.uniform(0, 2 * np.pi))
        shift = rng.uniform(-1.0, 1.0, size=3)
        moved = rotate_scene_about_gravity(raw, angle)
        moved["base_pos"] = moved["base_pos"] + shift
        moved_inputs = build_view(moved, ids, frames, entry.view, entry.variant).inputs
        view_change = max([view_change, *(_change(moved_inputs[k], inputs[k]) for k in inputs)])
        change = relative_error(context.predict_raw(moved, ids), base)
        trials.append({"angle_rad": angle, "shift_m": shift.tolist(), "rel_change": change})
    tilted = rotate_scene(raw, float(CONTROL_TILT_RAD), (1.0, 0.0, 0.0))
    control = relative_error(context.predict_raw(tilted, ids), base)
    by_construction = view_change <= 1e-12
    out = {
        "max_rel_change": max(t["rel_change"] for t in trials),
        "by_construction": by_construction,
        "reason": (
            f"the {entry.view} view does not change under the moves (max relative change "
            f"{view_change:.1e}): it is computed in the base frame"
            if by_construction
            else f"the {entry.view} view changes under the moves (max relative change "
            f"{view_change:.1e}): it holds world-frame state, so the model must learn it"
        ),
        "view_rel_change": view_change,
        "control": {
            "transform": "robot tilted 30 degrees about world x, gravity kept",
            "rel_change": control,
            "failed_as_it_must": bool(control > CONTROL_MIN_CHANGE),
        },
        "trials": trials,
    }
    return out


def _change(actual: np.ndarray, expected: np.ndarray) -> float:
    scale = float(np.max(np.abs(expected))) if np.size(expected) else 0.0
    diff = float(np.max(np.abs(np.asarray(actual) - expected))) if np.size(expected) else 0.0
    return diff / scale if scale > 0 else diff
