"""The commands that reproduce a record: `symbench run` with the record's configuration, and
`symbench verify`, which replays all of it and compares every metric."""

from __future__ import annotations

import shlex
from pathlib import Path

from symbench.core.board.leaderboard import protocol_of
from symbench.core.config.presets import PRESETS, dataset_id, known_preset, parse_dataset_id
from symbench.core.config.protocols import STEP_BUDGET
from symbench.core.runs.results import RecordV1


def run_command(record: RecordV1) -> str:
    """`symbench run` with every option the record fixes. The variant and the evaluators are
    always given (a model's default variant is its plugin's business, and may change); the
    dataset only when it is not the robot's standard one of the preset, a budget only when
    it is not the preset's, the build keywords the run set. A standard dataset of an older
    dataset version is made only by the code of its time: the command checks out the
    record's commit first."""
    m, d = record.model, record.dataset
    prefix, args = "", ["symbench", "run", "--model", m.name, "--robot", record.robot]
    if parse_dataset_id(d.id) == (record.robot, d.preset) and d.id != dataset_id(
        record.robot, d.preset
    ):
        prefix = f"git checkout {shlex.quote(record.git_commit.split('+')[0])} && "
    elif d.preset not in PRESETS or d.id != dataset_id(record.robot, d.preset):
        args += ["--dataset", d.id]
    args += ["--split", record.split, "--seed", str(record.seed), "--preset", d.preset]
    args += ["--backend", m.backend, "--variant", m.variant, "--protocol", protocol_of(record)]
    args += ["--evaluators", ",".join(record.metrics)]
    return prefix + shlex.join(args + _budget(record) + _sizes(record))


def _sizes(record: RecordV1) -> list[str]:
    """The size options of the record's run, so that the command's run has the record's key:
    `--parameters N` of a matched size (the search at the record's commit picks the same
    widths, which `verify` replays exactly) with the keywords it set by name (`--size`), or
    at default size `--size NAME=VALUE` for every build keyword it set (a record made before
    the key named them, whose keywords only its training configuration holds, included)."""
    config = getattr(record.training, "config", None)
    hyper = config.hyper if config is not None else {}
    matched = getattr(record.model, "matched_parameters", None)
    if matched is not None:
        hyper = getattr(record.model, "sizes", None) or {}
    size = [] if matched is None else ["--parameters", str(matched)]
    return size + [arg for name in sorted(hyper) for arg in ("--size", f"{name}={hyper[name]}")]


def _budget(record: RecordV1) -> list[str]:
    """--max-steps (converge, cosine) or --max-epochs (paper) when the run's budget was not the
    preset's; schema-1 records kept no budget."""
    config = getattr(record.training, "config", None)
    known = known_preset(record.dataset.preset)
    if config is None or known is None:
        return []
    budget = known.training
    if config.protocol in STEP_BUDGET and config.max_steps != budget.max_steps:
        return ["--max-steps", str(config.max_steps)]
    if config.protocol == "paper" and config.max_epochs != budget.max_epochs:
        return ["--max-epochs", str(config.max_epochs)]
    return []


def verify_command(path: Path) -> str:
    return shlex.join(["symbench", "verify", str(path)])
