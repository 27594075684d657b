"""How symmetric the run's dataset itself is, kept in the record beside the model's error.

Not a property of the model: the same for every model trained on a dataset. It is here so
that a board comparing approximately symmetric robot variants (`hexa-asym-A`) can show,
from the records alone, how far each dataset is from the symmetry the models assume: the
relative error between climbs that are rotated images of each other, after relabelling
(`symbench data symmetry`), and its ratio to the dataset's noise floor. Climbs drawn from
continuous distributions (dataset v7) hold no such pairs: for a generated dataset they are
then constructed on purpose, as `symbench data symmetry ID` does (a few of its climbs
simulated again under every rotation of the group; seconds, cached with the data), and the
record says so (`"pairs": "constructed"` with `twins`, the climbs simulated again; else
`"found"`).
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:  # symbench's names load the data stack: when a run evaluates, not with the CLI
    from symbench import EvaluationContext

NAME = "data-symmetry"
DESCRIPTION = (
    "the dataset's own symmetry (image climbs compared after relabelling), not the model's"
)


def evaluate(context: EvaluationContext) -> dict[str, Any]:
    from symbench import NoImagePairsError, symmetry_report

    try:
        report = symmetry_report(context.dataset)
    except NoImagePairsError:  # imported: nothing to simulate again
        return {
            "image_pairs": 0,
            "reason": "no two climbs of the dataset are rotated images of each other, "
            "and an imported dataset cannot be simulated again to construct some",
        }
    twins = report.constructed
    out: dict[str, Any] = (
        {"pairs": "found"} if twins is None else {"pairs": "constructed", "twins": twins.climbs}
    )
    out.update(image_pairs=len(report.pairs), floor=report.floor_source)
    for group, key in (("torques", "tau"), ("joint states", "joint"), ("base", "base")):
        out[f"{key}_rel_error"] = report.groups[group]["relative_error"]
        out[f"{key}_ratio_to_floor"] = report.groups[group]["ratio"]
    return out
