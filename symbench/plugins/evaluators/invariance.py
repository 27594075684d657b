"""Change of the trained model's output when test scenes are rotated about gravity and moved.

The paper's physics invariances: the torques needed for a motion do not depend on where the
scene is or how it is turned about gravity. Views are recomputed from the transformed raw
states, so the leg-grouped view is invariant by construction and the vector view is not.
"""

from __future__ import annotations

import numpy as np

from symbench import EvaluationContext, relative_error, rotate_scene_about_gravity

NAME = "invariance"
DESCRIPTION = "max relative output change under random rotations about gravity + translations"


def evaluate(context: EvaluationContext) -> dict:
    raw, ids = context.test_raw()
    base = context.predict_raw(raw, ids)
    rng = np.random.default_rng([context.seed, 7])
    trials = []
    for _ in range(context.preset.evaluation.invariance_trials):
        angle = float(rng.uniform(0, 2 * np.pi))
        shift = rng.uniform(-1.0, 1.0, size=3)
        moved = rotate_scene_about_gravity(raw, angle)
        moved["base_pos"] = moved["base_pos"] + shift
        change = relative_error(context.predict_raw(moved, ids), base)
        trials.append({"angle_rad": angle, "shift_m": shift.tolist(), "rel_change": change})
    return {"max_rel_change": max(t["rel_change"] for t in trials), "trials": trials}
