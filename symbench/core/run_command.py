"""`symbench run`: train and evaluate one model on one robot."""

from __future__ import annotations

import click

from symbench.core import registry
from symbench.core.errors import SymbenchError


@click.command("run")
@click.option("--model", "model_name", required=True, help="Registered model name, e.g. sdnn.")
@click.option("--robot", "robot_name", required=True, help="Registered robot, e.g. hexa.")
@click.option("--backend", default="torch", show_default=True, help="torch or jax.")
@click.option("--preset", default="small", show_default=True, help="smoke, small or paper.")
def run(model_name: str, robot_name: str, backend: str, preset: str) -> None:
    """Train and evaluate MODEL on ROBOT (generating the dataset when missing)."""
    missing = []
    for kind, name in (("models", model_name), ("robots", robot_name)):
        if not registry.collect(kind):
            missing.append(f"no {kind} are registered yet")
    if missing:
        raise SymbenchError(
            "symbench run is not built yet: " + "; ".join(missing)
            + ". The simulator, datasets, models and training land in issues 3 to 6."
        )
    registry.model(model_name, backend)
    registry.robot(robot_name)
    raise SymbenchError(f"symbench run: training and evaluation (preset {preset}) are not built yet")
