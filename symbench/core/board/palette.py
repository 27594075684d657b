"""Each model's colour and each of its entries' line and bar style, the same on every plot of
the boards and the site: a reader who learns that sdnn is blue on one plot finds it blue on
all of them. The colours are the Okabe-Ito palette (Okabe and Ito 2008), told apart by
readers with any common colour-vision deficiency, less vermillion: no plot shows a red model
beside a green one. A model is coloured by its name, never by its place in a list, so adding
a model to a board changes no other model's colour."""

from __future__ import annotations

import hashlib
from dataclasses import dataclass

OKABE_ITO = {
    "black": "#000000",
    "orange": "#E69F00",
    "sky blue": "#56B4E9",
    "bluish green": "#009E73",
    "yellow": "#F0E442",
    "blue": "#0072B2",
    "vermillion": "#D55E00",
    "reddish purple": "#CC79A7",
}
# the built-in models; the symmetric ones in blues, the graph network in green
MODEL_COLOURS = {
    "sdnn": OKABE_ITO["blue"],
    "sdgnn": OKABE_ITO["sky blue"],
    "gnn": OKABE_ITO["bluish green"],
    "ffnn": OKABE_ITO["orange"],
    "ffnn-leg": OKABE_ITO["reddish purple"],
}
# any other model: vermillion is left out, it would be a red beside gnn's green
OTHER_COLOURS = (OKABE_ITO["black"], OKABE_ITO["yellow"])


def colour_of(model: str) -> str:
    """The model's colour: a built-in model's own, any other's drawn from the rest of the
    palette by a hash of its name (sha256: Python's `hash` of a string changes per process)."""
    if model in MODEL_COLOURS:
        return MODEL_COLOURS[model]
    digest = int.from_bytes(hashlib.sha256(model.encode()).digest()[:8], "big")
    return OTHER_COLOURS[digest % len(OTHER_COLOURS)]


@dataclass(frozen=True)
class Style:
    """How one entry of a model (a variant, backend or protocol) differs from the model's
    other entries on a plot of the same colour."""

    marker: str
    linestyle: str
    hatch: str


MARKERS = ("o", "s", "^", "D", "v", "P")
LINESTYLES = ("-", "--", ":", "-.")
HATCHES = ("", "//", "..", "xx", "\\\\")


def styles_of(models: list[str]) -> list[Style]:
    """The style of each entry of a plot, given each one's model in the plot's order: a
    model's first entry is plain (solid, round, filled), its second the next style, and so
    on; markers, lines and hatches cycle at different lengths, so a dozen entries all differ."""
    seen: dict[str, int] = {}
    styles = []
    for model in models:
        i = seen[model] = seen.get(model, -1) + 1
        styles.append(
            Style(
                MARKERS[i % len(MARKERS)],
                LINESTYLES[i % len(LINESTYLES)],
                HATCHES[i % len(HATCHES)],
            )
        )
    return styles
