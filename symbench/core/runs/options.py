"""The command-line options of a run, declared once: `symbench run` and `symbench sweep` (and
`tune`) take theirs from `RUN_OPTIONS` by name, and `spec_fields` turns the parsed values
into `RunSpec` keywords, so no command restates an option or a RunSpec field."""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass, fields
from pathlib import Path
from typing import Any, TypeVar

import click

from symbench.core.common.cli_types import EPOCHS, SEED, WORKERS, CommaList, WritableFolder
from symbench.core.config.presets import PRESETS
from symbench.core.config.protocols import PROTOCOLS
from symbench.core.runs.spec import DEFAULT_EVALUATORS, FIRST_RESULT_EVALUATORS, RunSpec

F = TypeVar("F", bound=Callable[..., Any])


@dataclass(frozen=True)
class RunOption:
    """One option: its flags and click settings; `help` may name `{subject}` ("the run",
    "every run"). The parameter's name is its key in `RUN_OPTIONS`, a RunSpec field where
    the option sets one."""

    flags: tuple[str, ...]
    help: str
    settings: Mapping[str, Any]


def _option(*flags: str, help: str, **settings: Any) -> RunOption:
    return RunOption(flags, help, settings)


PROTOCOL_HELP = (
    "Training protocol of {subject}: converge (early stopping on validation loss within a "
    "budget of gradient steps, the same for every model), cosine (the same, the learning rate "
    "decayed to zero at the budget) or paper (the paper's overfitting rule)."
)
RUN_OPTIONS: dict[str, RunOption] = {
    "model": _option("--model", help="Registered model, e.g. sdnn.", required=True),
    "robot": _option(
        "--robot",
        help="Registered robot, e.g. hexa: trains on its standard dataset of the preset "
        "(with --dataset: the dataset's robot, may be left out).",
        default=None,
    ),
    "dataset": _option(
        "--dataset",
        help="A cached dataset id, generated or imported (see `symbench list datasets`); "
        "default: the robot's standard dataset of the preset.",
        default=None,
    ),
    "backend": _option("--backend", help="torch or jax.", default="torch", show_default=True),
    "split": _option("--split", help="A registered split (default: iid).", default=None),
    "split_by": _option(
        "--split-by",
        help="Split by a scenario column instead: heading, yaw, inclination, direction or "
        "seed (with --train and --test).",
        default=None,
    ),
    "train_values": _option(
        "--train",
        help="With --split-by: the column's values to train on, e.g. 0,90.",
        default=None,
        type=CommaList(),
    ),
    "test_values": _option(
        "--test",
        help="With --split-by: the column's values to test on, e.g. 180,270 (others are unused).",
        default=None,
        type=CommaList(),
    ),
    "seed": _option("--seed", help="", default=0, show_default=True, type=SEED),
    "preset": _option(
        "--preset",
        help=f"{', '.join(PRESETS)}: epoch cap, evaluation budgets, horizons of {{subject}} "
        "(see `symbench presets`); default: a standard dataset's own preset, else small.",
        default=None,
    ),
    "variant": _option(
        "--variant",
        help="Input variant of {subject} (default: the model's; closed-loop control uses next).",
        type=click.Choice(["acc", "next"]),
        default=None,
    ),
    "evaluators": _option(
        "--evaluators",
        help="Comma-separated evaluator names (see `symbench list evaluators`); default: "
        f"{', '.join(FIRST_RESULT_EVALUATORS)}, which need one training.",
        default=None,
        type=CommaList(),
    ),
    "full": _option(
        "--full",
        help=f"The full evaluation of sweeps and boards: {', '.join(DEFAULT_EVALUATORS)} "
        "(three more trainings and closed-loop rollouts).",
        is_flag=True,
    ),
    "output": _option(
        "--output",
        help="Folder for the records, checkpoints and plots.",
        type=WritableFolder(),
        default=Path("results"),
        show_default=True,
    ),
    "workers": _option(
        "--workers",
        help="Worker processes at once, simulating the dataset when it is missing.",
        default=2,
        show_default=True,
        type=WORKERS,
    ),
    "protocol": _option(
        "--protocol",
        help=PROTOCOL_HELP,
        type=click.Choice(PROTOCOLS),
        default="converge",
        show_default=True,
    ),
    "max_steps": _option(
        "--max-steps",
        help="Override the preset's budget of gradient steps of {subject} (converge, cosine).",
        type=EPOCHS,
        default=None,
    ),
    "max_epochs": _option(
        "--max-epochs",
        help="Override the preset's epoch cap of {subject} (paper).",
        type=EPOCHS,
        default=None,
    ),
    "parameters": _option(
        "--parameters",
        help="Scale the model's widths of {subject} to the parameter count nearest this "
        "(compare models at matched size).",
        type=EPOCHS,
        default=None,
    ),
    "sizes": _option(
        "--size",
        help="A build keyword of the model, e.g. ring=1 (sdnn: each leg also sees its "
        "neighbours); repeatable, applied after --parameters. The record keeps it; the run's "
        "key does not name it, so give such runs their own --output.",
        multiple=True,
        metavar="NAME=INT",
    ),
    "overwrite": _option(
        "--overwrite",
        help="Run again and replace a record of another configuration at a record's path "
        "(refused otherwise).",
        is_flag=True,
    ),
}
SPEC_FIELDS = frozenset(f.name for f in fields(RunSpec))


def run_options(*names: str, subject: str = "the run", **changes: Any) -> Callable[[F], F]:
    """Decorates a command with the options `names` of `RUN_OPTIONS`, shown in this order;
    `changes` replaces an option's click settings by name (`workers={"default": 1}`)."""

    def decorate(command: F) -> F:
        for name in reversed(names):
            option = RUN_OPTIONS[name]
            settings = {**option.settings, **changes.get(name, {})}
            text = settings.pop("help", option.help).replace("{subject}", subject)
            command = click.option(*option.flags, name, help=text or None, **settings)(command)
        return command

    return decorate


def spec_fields(values: Mapping[str, Any]) -> dict[str, Any]:
    """The RunSpec keywords among a command's parsed option values: lists become tuples,
    `--size` pairs build keywords; the options a command reads itself are left out."""
    out = {k: v for k, v in values.items() if k in SPEC_FIELDS}
    if "sizes" in out:
        out["sizes"] = tuple(sizes_from(out["sizes"]).items())
    if out.get("evaluators") is not None:
        out["evaluators"] = tuple(out["evaluators"])
    return out


def size_option(help_text: str) -> Callable[[F], F]:
    """`--size NAME=INT` alone, with its own help (`symbench check-equivariance`)."""
    return run_options("sizes", sizes={"help": help_text})


def sizes_from(pairs: tuple[str, ...]) -> dict[str, int]:
    """NAME=INT pairs as build keywords; a malformed one is a usage error naming it."""
    out = {}
    for pair in pairs:
        name, _, value = pair.partition("=")
        if not name.isidentifier() or not value.lstrip("-").isdigit():
            raise click.BadParameter(f"{pair!r} is not NAME=INT", param_hint="'--size'")
        out[name] = int(value)
    return out
