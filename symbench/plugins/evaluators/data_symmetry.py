"""How symmetric the run's dataset itself is, kept in the record beside the model's error.

Not a property of the model: the same for every model trained on a dataset. It is here so
that a board comparing approximately symmetric robot variants (`hexa-asym-A`) can show,
from the records alone, how far each dataset is from the symmetry the models assume: the
relative error between climbs that are rotated images of each other, after relabelling
(`symbench data symmetry`), and its ratio to the dataset's noise floor.
"""

from __future__ import annotations

from symbench import EvaluationContext, dataset_symmetry

NAME = "data-symmetry"
DESCRIPTION = (
    "the dataset's own symmetry (image climbs compared after relabelling), not the model's"
)


def evaluate(context: EvaluationContext) -> dict:
    report = dataset_symmetry(context.dataset)
    out: dict = {"image_pairs": len(report.pairs), "floor": report.floor_source}
    if not report.pairs:
        return {**out, "reason": "no two climbs of the dataset are rotated images of each other"}
    for group, key in (("torques", "tau"), ("joint states", "joint"), ("base", "base")):
        out[f"{key}_rel_error"] = report.groups[group]["relative_error"]
        out[f"{key}_ratio_to_floor"] = report.groups[group]["ratio"]
    return out
