"""How symmetric the run's dataset itself is, kept in the record beside the model's error.

Not a property of the model: the same for every model trained on a dataset. It is here so
that a board comparing approximately symmetric robot variants (`hexa-asym-A`) can show,
from the records alone, how far each dataset is from the symmetry the models assume: the
relative error between climbs that are rotated images of each other, after relabelling
(`symbench data symmetry`), and its ratio to the dataset's noise floor. Climbs drawn from
continuous distributions (dataset v7) hold no such pairs: for a generated dataset they are
then constructed (`symbench data symmetry ID --twins N`: `TWINS` climbs simulated again,
turned by one symmetry step; seconds, cached with the data) and the record says so
(`"pairs": "constructed"`, else `"found"`).
"""

from __future__ import annotations

from typing import Any

from symbench import EvaluationContext, NoImagePairsError, dataset_symmetry, twin_symmetry

NAME = "data-symmetry"
DESCRIPTION = (
    "the dataset's own symmetry (image climbs compared after relabelling), not the model's"
)
TWINS = 8  # climbs simulated again turned when the dataset holds no image pairs (at most)


def evaluate(context: EvaluationContext) -> dict[str, Any]:
    dataset = context.dataset
    out: dict[str, Any] = {"pairs": "found"}
    try:
        report = dataset_symmetry(dataset)
    except NoImagePairsError:
        if dataset.metadata.get("source") != "generated":
            return {
                "image_pairs": 0,
                "reason": "no two climbs of the dataset are rotated images of each other, "
                "and an imported dataset cannot be simulated again to construct some",
            }
        n = min(TWINS, len(dataset.trajectory_ids))
        report, out = twin_symmetry(dataset, n), {"pairs": "constructed", "twins": n}
    out.update(image_pairs=len(report.pairs), floor=report.floor_source)
    for group, key in (("torques", "tau"), ("joint states", "joint"), ("base", "base")):
        out[f"{key}_rel_error"] = report.groups[group]["relative_error"]
        out[f"{key}_ratio_to_floor"] = report.groups[group]["ratio"]
    return out
