"""How much of the run's test (and validation) side the model has seen in a symmetric form:
the share of those climbs that are images of a training climb, per symmetry class of model.

Not a property of the model: the same for every model on a dataset, split and seed, so the
context measures it once per output folder (`EvaluationContext.image_overlap`). It is in
every record so that a reader can tell, from the record alone, whether the model's test error
measures generalization or recall: on dataset v6's grids nearly every `iid` test climb was a
rotated image of a training climb for an equivariant model; on v7 none should be
(`symbench data info` shows the same figures per split).
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:  # symbench's names load the data stack: when a run evaluates, not with the CLI
    from symbench import EvaluationContext

NAME = "image-overlap"
DESCRIPTION = (
    "the split's own overlap: shares of test and validation climbs that are images of a "
    "training climb per symmetry class (none, heading, group, mirror), and distinct motions"
)


def evaluate(context: EvaluationContext) -> dict[str, Any]:
    overlap = context.image_overlap().to_dict()
    out: dict[str, Any] = {
        "exact_tolerance": overlap["exact_tolerance"],
        "near_tolerance": overlap["near_tolerance"],
    }
    for side, figures in overlap["sides"].items():
        out[f"{side}_climbs"] = figures["climbs"]
        # distinct motions up to the robot's group: how much a split's side really holds
        out[f"{side}_group_motions"] = figures["classes"]["group"]["distinct_motions_exact"]
        for name, c in figures["classes"].items():
            if "exact_image_share" in c:  # the training side is compared with nothing
                out[f"{side}_{name}_exact_image_share"] = c["exact_image_share"]
                out[f"{side}_{name}_near_image_share"] = c["near_image_share"]
    return out
