"""A symbench plugin built on an equivariance library: registers `e2cnn-mlp` (torch).

The hook returns plain entries; e2cnn and torch are imported only when the network is built.
"""

from symbench import Lazy, ModelEntry, hookimpl


@hookimpl
def symbench_models() -> list:
    return [
        ModelEntry(
            name="e2cnn-mlp",
            backend="torch",
            view="leg_grouped",  # per-leg features in leg frames: a rotation relabels legs
            variant="acc",
            equivariant=True,  # the library's layers make it so; the kit holds it to it
            build=Lazy("symbench_e2cnn.network:build"),
            learning_rate=1e-3,
            # `symbench tune --model e2cnn-mlp --robot hexa --width-scales 1` on hexa-climb-small-v7
            learning_rates={"hexa": 3e-3},
            description="MLP of e2cnn's C_n-equivariant linear maps on regular fields (legs)",
            widths=("fields",),
        )
    ]
