"""Parameters from a torch network to the flax twin of the same architecture.

Both backends name layers alike ('enc.linear0', 'enc.norm'), so the conversion is by name:
a torch Linear weight (out, in) is a flax Dense kernel (in, out); a LayerNorm weight is a
flax LayerNorm scale. Used to show that the two backends compute the same function.
"""

from __future__ import annotations

import numpy as np

Params = dict[str, np.ndarray]


def torch_to_flax(params: Params) -> Params:
    out = {}
    for key, value in params.items():
        *path, leaf = key.split(".")
        if leaf == "weight" and value.ndim == 2:
            leaf, value = "kernel", value.T
        elif leaf == "weight" and value.ndim == 1:
            leaf = "scale"
        out["/".join([*path, leaf])] = np.ascontiguousarray(value)
    return out
