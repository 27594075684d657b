"""The run's configuration: its training settings (the protocol's, with the preset's budgets
and matched sizes), the check of every name and number before any minute is spent, and the
configuration a record of the run holds."""

from __future__ import annotations

import functools
import json
from dataclasses import replace
from typing import Any

from symbench.core.common.errors import SymbenchError
from symbench.core.config.presets import preset
from symbench.core.config.protocols import Paper, preset_schedules
from symbench.core.config.provenance import build_hyperparameters
from symbench.core.data.splits import check_split
from symbench.core.data.views.model_dims import dims_for
from symbench.core.plugin import registry
from symbench.core.plugin.entries import ModelEntry
from symbench.core.robot.specs import load_robot, registered_robot, split_variant
from symbench.core.runs.spec import RunSpec, model_entry, resolve_robot
from symbench.core.training.backends import get_backend
from symbench.core.training.buildable import check_buildable
from symbench.core.training.config import TrainConfig
from symbench.core.training.sizes import matched_widths


def check_names(spec: RunSpec) -> None:
    """Every name resolves and every number is valid before any minute is spent (closest
    names otherwise); the dataset exists (or is a standard one, made when missing) and holds
    the run's robot."""
    entry = model_entry(spec)
    unknown = sorted(set(dict(spec.sizes)) - set(build_hyperparameters(entry, {})))
    if unknown:
        raise SymbenchError(
            f"model {entry.name} has no build keyword {', '.join(unknown)} (it has: "
            f"{', '.join(build_hyperparameters(entry, {})) or 'none'})"
        )
    registered_robot(spec.robot)
    check_split(spec.split)  # a registered split, or a column split's name
    for name in spec.evaluators:
        registry.evaluator(name)
    preset(spec.preset)
    if spec.workers < 1:
        raise SymbenchError(f"workers must be at least 1, got {spec.workers}")
    config = train_config(spec)
    if spec.sizes:  # set by hand: the network is built once to see that it can be
        dims = dims_for(entry.view, entry.variant, load_robot(spec.robot).n_legs)
        check_buildable(entry, dims, config.hyper, dict(spec.sizes))
    resolve_robot(spec.robot, spec.dataset_id)


def train_config(spec: RunSpec) -> TrainConfig:
    """The run's training configuration: the protocol's settings with the preset's budgets
    (checked: seed, budgets, ...), or the one it replays (`RunSpec.training`). A budget of
    another protocol is refused, not ignored."""
    budget = preset(spec.preset).training
    own, unused = preset_schedules(spec.protocol, budget, spec.max_steps, spec.max_epochs)
    if spec.training is not None:
        if spec.training.protocol != own.name:
            raise SymbenchError(
                f"the replayed training is of protocol '{spec.training.protocol}', "
                f"the run of '{own.name}'"
            )
        return replace(spec.training, seed=spec.seed, progress=spec.progress)
    hyper = {**(matched_size(spec) if spec.parameters is not None else {}), **dict(spec.sizes)}
    return TrainConfig(
        schedule=own,
        unused=unused,
        seed=spec.seed,
        val_stride=budget.val_stride,
        learning_rate=robot_rate(model_entry(spec), spec.robot),
        hyper=hyper,
        progress=spec.progress,
    )


def robot_rate(entry: ModelEntry, robot: str) -> float | None:
    """The learning rate tuned for `robot` (an asymmetric variant: its robot's), None when
    `entry` has none for it. The configuration names a tuned rate, so changing it changes a
    record's configuration and a resume checkpoint's identity; the model's own rate stays
    None there (`TrainConfig.rate_for`), as in every run made before per-robot rates."""
    rates = entry.learning_rates
    return rates.get(robot, rates.get(split_variant(robot)[0]))


def matched_size(spec: RunSpec) -> dict[str, int]:
    """The width keywords that give the run's model `spec.parameters` parameters on the
    robot's data (its view's shapes follow from the leg count)."""
    assert spec.parameters is not None
    entry = model_entry(spec)
    n_legs = load_robot(spec.robot).n_legs
    return dict(_matched(entry.name, entry.backend, entry.variant, n_legs, spec.parameters))


@functools.lru_cache(maxsize=64)
def _matched(
    model: str, backend: str, variant: str, n_legs: int, parameters: int
) -> tuple[tuple[str, int], ...]:
    """Found once per process: a run asks for its configuration several times (plan,
    record check, training), and each search builds about a dozen networks."""
    entry = replace(registry.model(model, backend), variant=variant)
    dims = dims_for(entry.view, entry.variant, n_legs)
    return tuple(matched_widths(entry, dims, parameters).items())


def budget_text(config: TrainConfig) -> str:
    """The training's budget in words, for plans and tables."""
    steps, epochs = config.steps_and_epochs
    if isinstance(config.schedule, Paper):
        return f"paper protocol, at most {epochs.max_epochs} epochs"
    return (
        f"{config.protocol} protocol, at most {steps.max_steps} steps, patience "
        f"{steps.patience} x {steps.eval_every} steps"
    )


def recorded_config(config: TrainConfig, entry: ModelEntry) -> dict[str, Any]:
    """The TrainConfig as the record keeps it: defaults resolved, the progress bar left out."""
    out = config.to_dict()
    out["val_stride"] = config.val_stride  # to_dict leaves it out at 1; records always say
    out["learning_rate"] = config.rate_for(entry)
    out["compile"] = (
        get_backend(entry.backend).default_compiled if config.compile is None else config.compile
    )
    return out


def configuration(spec: RunSpec, content_hash: str | None = None) -> dict[str, Any]:
    """What the run would record as its configuration (`RecordBody.configuration`); the
    dataset content hash only when given (it is known once the dataset is made)."""
    entry = model_entry(spec)
    config = train_config(spec)
    matched = {} if spec.parameters is None else {"matched parameters": spec.parameters}
    wanted = {
        **matched,
        "dataset": spec.dataset_id,
        "dataset content hash": content_hash,
        "preset": spec.preset,
        "robot": spec.robot,
        "split": spec.split,
        "seed": spec.seed,
        "model": entry.name,
        "model version": entry.version,
        "backend": entry.backend,
        "input variant": entry.variant,
        "evaluators": sorted(spec.evaluators),
        "hyper-parameters": build_hyperparameters(entry, config.hyper),
        **{f"training {k}": v for k, v in recorded_config(config, entry).items()},
    }
    if content_hash is None:
        del wanted["dataset content hash"]
    recorded: dict[str, Any] = json.loads(json.dumps(wanted))  # tuples become lists
    return recorded
