"""What the collection hooks return: one small record per registered thing.

Entries are plain frozen dataclasses so that listing them (`symbench list`) never has to
build a network or load a robot. The callables are invoked only when the thing is used, but
every field is checked when the entry is made: a misspelt view, variant or backend fails in
the plugin's own hook, where the plugin host reports it under the plugin's name, instead of
deep inside a training run.
"""

from __future__ import annotations

import os
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field, fields
from pathlib import Path
from typing import Any

from symbench.core.common.errors import SymbenchError
from symbench.core.common.identifiers import IDENTIFIER_LENGTH, is_identifier

# The vocabulary shared by plugins and the core (the data schema keys its layouts by these).
BACKENDS = ("torch", "jax")
VIEWS = ("leg_grouped", "vector", "body_graph")
VARIANTS = ("acc", "next")
# What an evaluator may need from a dataset beyond its test samples (`EvaluatorEntry.needs`);
# a run skips an evaluator whose needs its dataset does not meet, saying which and why.
EVALUATOR_NEEDS = (
    "simulator",  # replays the dataset's scenarios in the simulator (complete scenarios)
    "scenarios",  # every scenario field of every trajectory (imported logs may lack some)
    "variant:next",  # the `next` variant at the standard 6 ms record period
    "raw",  # the raw base and joint states (`test_raw`, `predict_raw`)
    "contact",  # contact flags that are known, not declared unknown by an import
)


class InvalidEntryError(SymbenchError, ValueError):
    """An entry whose fields cannot work; raised when the entry is made."""


def _check_name(kind: str, name: object) -> None:
    if not isinstance(name, str) or not is_identifier(name):
        raise InvalidEntryError(
            f"{kind} name {name!r} is not a name: use at most {IDENTIFIER_LENGTH} letters, "
            "digits and . _ - (no spaces or slashes), starting with a letter or digit"
        )


def _check_choice(kind: str, name: str, field: str, value: object, valid: tuple[str, ...]) -> None:
    if value not in valid:
        raise InvalidEntryError(
            f"{kind} '{name}': {field} {value!r} is not one of {', '.join(valid)}"
        )


def _check_rate(name: str, field: str, rate: object) -> None:
    if isinstance(rate, bool) or not isinstance(rate, (int, float)) or not 0 < rate < 1:
        raise InvalidEntryError(f"model '{name}': {field} must be a number in (0, 1), got {rate!r}")


def _check_callable(kind: str, name: str, field: str, value: object) -> None:
    if not callable(value):
        raise InvalidEntryError(
            f"{kind} '{name}': {field} must be callable (a function or "
            f"Lazy('module:attribute')), got {type(value).__name__}"
        )


@dataclass(frozen=True)
class ModelEntry:
    """A network for one backend, the view it consumes and the symmetry it claims.

    `build(dims, **hyper)` returns the backend's network; `equivariant` says whether the
    model claims equivariance under the robot's symmetry group (checked by the kit).
    `widths` names the build keywords that set the network's width (integers with
    defaults): `symbench tune` scales them together, and `--parameters` scales them to a
    parameter count; empty, the network's size is not searched or matched.
    `learning_rates` maps a robot's name to the learning rate `symbench tune --robot` chose
    for it; a run on that robot (or on its asymmetric variants) trains with it, any other
    robot with `learning_rate`.
    `version` numbers the network's computation: raise it whenever a change alters what the
    network computes, float summation order included. Records carry it, a run's identity
    and resume checkpoints include it, and `symbench verify` never re-runs a record of
    another version (its numbers could not come out the same).
    """

    name: str
    backend: str
    view: str
    variant: str
    equivariant: bool
    build: Callable[..., Any]
    learning_rate: float = 1e-3
    description: str = ""
    widths: tuple[str, ...] = ()
    version: int = 1
    # left out of the hash (a dict has none), so an entry stays usable as a key
    learning_rates: Mapping[str, float] = field(default_factory=dict, hash=False)

    def __post_init__(self) -> None:
        _check_name("model", self.name)
        _check_choice("model", self.name, "backend", self.backend, BACKENDS)
        _check_choice("model", self.name, "view", self.view, VIEWS)
        _check_choice("model", self.name, "variant", self.variant, VARIANTS)
        if not isinstance(self.equivariant, bool):
            raise InvalidEntryError(f"model '{self.name}': equivariant must be True or False")
        _check_callable("model", self.name, "build", self.build)
        _check_rate(self.name, "learning_rate", self.learning_rate)
        if not isinstance(self.learning_rates, Mapping):
            raise InvalidEntryError(
                f"model '{self.name}': learning_rates must map robot names to learning rates, "
                f"got {self.learning_rates!r}"
            )
        for robot, rate in self.learning_rates.items():
            _check_name(f"model '{self.name}': learning_rates robot", robot)
            _check_rate(self.name, f"learning_rates[{robot!r}]", rate)
        object.__setattr__(self, "learning_rates", dict(self.learning_rates))  # a copy of its own
        if isinstance(self.version, bool) or not isinstance(self.version, int) or self.version < 1:
            raise InvalidEntryError(
                f"model '{self.name}': version must be a positive integer, got {self.version!r}"
            )
        if not isinstance(self.widths, tuple) or not all(isinstance(w, str) for w in self.widths):
            raise InvalidEntryError(
                f"model '{self.name}': widths must be a tuple of build keyword names, "
                f"got {self.widths!r}"
            )


@dataclass(frozen=True)
class RobotEntry:
    """A robot whose spec (robot.toml and README.md) lives in `spec_dir`."""

    name: str
    spec_dir: Path
    description: str = ""

    def __post_init__(self) -> None:
        _check_name("robot", self.name)
        if not isinstance(self.spec_dir, (str, os.PathLike)):
            raise InvalidEntryError(
                f"robot '{self.name}': spec_dir must be a path, got {type(self.spec_dir).__name__}"
            )


@dataclass(frozen=True)
class EvaluatorEntry:
    """An evaluator: `evaluate(context)` returns a dict of metrics.

    `needs` names what it needs from a dataset beyond its test samples, from
    `EVALUATOR_NEEDS` (e.g. `("simulator", "variant:next")`); a run whose dataset does not
    provide one skips the evaluator, recording the reason instead of its metrics.

    `trainings(context)`, optional, lists the trainings `evaluate` will ask the context for,
    as (dataset id or None for the run's own, split, variant) triples: a run with more than
    one worker trains them beside its own model, in parallel, before evaluating. Only a
    speed-up: whatever `evaluate` asks for is trained anyway, and the same bit for bit.
    """

    name: str
    evaluate: Callable[..., dict[str, Any]]
    description: str = ""
    needs: tuple[str, ...] = ()
    trainings: Callable[..., Sequence[tuple[str | None, str, str]]] | None = None

    def __post_init__(self) -> None:
        _check_name("evaluator", self.name)
        _check_callable("evaluator", self.name, "evaluate", self.evaluate)
        if self.trainings is not None:
            _check_callable("evaluator", self.name, "trainings", self.trainings)
        needs = self.needs
        if isinstance(needs, str) or not isinstance(needs, (tuple, list)):
            raise InvalidEntryError(
                f"evaluator '{self.name}': needs must be a tuple of names from "
                f"{', '.join(EVALUATOR_NEEDS)}, got {needs!r}"
            )
        for need in needs:
            _check_choice("evaluator", self.name, "need", need, EVALUATOR_NEEDS)
        if len(set(needs)) != len(needs):
            raise InvalidEntryError(f"evaluator '{self.name}': needs names one twice: {needs!r}")
        object.__setattr__(self, "needs", tuple(needs))


@dataclass(frozen=True)
class SplitEntry:
    """A split: `assign(context)` labels each trajectory train, val, test or unused.

    `context` is a `symbench.SplitContext` (scenarios, trajectory ids, sample counts, the
    robot's rotation order and the seed); see docs/writing-plugins.md. `control` names the
    split's size-matched iid control, if it has one (`symbench.control_of`).
    """

    name: str
    assign: Callable[..., Any]
    description: str = ""
    control: str | None = None

    def __post_init__(self) -> None:
        _check_name("split", self.name)
        _check_callable("split", self.name, "assign", self.assign)
        if self.control is not None:
            _check_name(f"split '{self.name}': control", self.control)
            if self.control == self.name:
                raise InvalidEntryError(f"split '{self.name}' cannot be its own control")


def describe(entry: Any) -> dict[str, Any]:
    """The entry's plain fields (no callables), JSON-ready."""
    out = {}
    for f in fields(entry):
        value = getattr(entry, f.name)
        if callable(value):
            continue
        if isinstance(value, Path):
            value = str(value)
        out[f.name] = list(value) if isinstance(value, tuple) else value
    return out
