"""An example symbench plugin: registers one model, `leg-attention`, for both backends
(PyTorch in `leg_attention`, Flax in `leg_attention_flax`).

The hook returns plain entries; torch or JAX is imported only when a network is built.
"""

from symbench import Lazy, ModelEntry, hookimpl


@hookimpl
def symbench_models() -> list:
    return [
        ModelEntry(
            name="leg-attention",
            backend="torch",
            view="leg_grouped",  # per-leg features; the robot's rotations permute legs
            variant="acc",
            equivariant=True,  # claimed, so the equivariance kit holds it to it
            build=Lazy("symbench_example_plugin.leg_attention:build"),
            learning_rate=5e-4,
            description="per-leg MLP, self-attention across legs, per-leg decoder",
            widths=("latent",),  # what `symbench tune` scales (the heads must divide it)
        ),
        ModelEntry(
            name="leg-attention",  # one name, one entry per backend
            backend="jax",
            view="leg_grouped",
            variant="acc",
            equivariant=True,
            build=Lazy("symbench_example_plugin.leg_attention_flax:build"),
            learning_rate=5e-4,
            description="per-leg MLP, self-attention across legs, per-leg decoder (Flax)",
            widths=("latent",),
        ),
    ]
