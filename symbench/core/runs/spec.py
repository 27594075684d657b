"""What one run is (`RunSpec`) and how its names resolve: model entry, dataset, robot, the
folders it writes; every other part of a run starts from here.

The data and the budgets are chosen apart: the dataset (`RunSpec.dataset`, any cached id,
generated or imported; by default the standard dataset of the robot and preset) names the
trajectories, the preset the epoch cap and the evaluators' budgets. The record's file name is
the run's key (`results.run_key`), which holds both.
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from pathlib import Path
from typing import TYPE_CHECKING

from symbench.core.common.errors import SymbenchError, UnknownNameError
from symbench.core.common.identifiers import IDENTIFIER_LENGTH, is_identifier
from symbench.core.config.presets import dataset_id, parse_dataset_id, preset
from symbench.core.data.dataset import Dataset, load_dataset, missing_hint
from symbench.core.data.generation.generate import ensure_dataset as ensure
from symbench.core.data.storage.metadata import METADATA, dataset_dir, read_metadata
from symbench.core.data.views.schema import VARIANTS
from symbench.core.plugin import registry
from symbench.core.plugin.entries import ModelEntry
from symbench.core.runs.results import run_key

if TYPE_CHECKING:
    from symbench.core.training.config import TrainConfig

# The full evaluation (sweeps, boards); `symbench run` starts with the first-result set, which
# needs one training only: generalization trains twice more and closed-loop once more.
DEFAULT_EVALUATORS = (
    "torque-error",
    "equivariance",
    "invariance",
    "generalization",
    "closed-loop",
    "image-overlap",
    "generalization-gap",
)
FIRST_RESULT_EVALUATORS = ("torque-error", "equivariance", "invariance", "image-overlap")


@dataclass(frozen=True)
class RunSpec:
    """One run as asked for (the command line's options, a sweep's point, a replayed record):
    checked by `run_config.check_names` before any minute is spent."""

    model: str
    robot: str  # must be the dataset's robot
    backend: str = "torch"
    split: str = "iid"  # a registered split, or a column split (`splits.column_split`) name
    seed: int = 0
    preset: str = "small"
    variant: str | None = None  # None: the model's registered input variant
    evaluators: tuple[str, ...] = DEFAULT_EVALUATORS
    output: Path = Path("results")
    workers: int = 2
    progress: bool = True
    protocol: str = "converge"  # the training protocol (symbench.core.config.protocols)
    # the protocol's own budget, replacing the preset's: one of another protocol is refused
    max_steps: int | None = None  # converge, cosine: `Converge.max_steps`
    max_epochs: int | None = None  # paper: `Paper.max_epochs`
    parameters: int | None = None  # the model's widths scaled to this parameter count
    sizes: tuple[tuple[str, int], ...] = ()  # build keywords set by name (`--size`), last
    # a whole training configuration replayed as recorded (`symbench verify`), its seed and
    # progress bar this spec's; None: the protocol's, with the preset's budgets
    training: TrainConfig | None = None
    dataset: str | None = None  # a cached dataset id; None: the robot's standard one (preset's)
    overwrite: bool = False  # replace a record of another configuration at `record_path`

    @property
    def dataset_id(self) -> str:
        """The data the run trains on: `dataset`, else the standard dataset of the preset."""
        return self.dataset if self.dataset is not None else dataset_id(self.robot, self.preset)

    def key(self, split: str | None = None, variant: str | None = None) -> str:
        """Matches `ResultRecord.key()`: the variant is resolved from the registry. With
        `split` (and `variant`): the key of the run that trains on them as its own, whose
        checkpoint folder this run's retraining on them shares (`checkpoint_root`)."""
        return run_key(
            self.dataset_id,
            self.preset,
            split or self.split,
            self.model,
            variant or model_entry(self).variant,
            self.backend,
            self.protocol,
            self.seed,
            self.parameters,
            dict(self.sizes),
        )

    @property
    def record_path(self) -> Path:
        return self.output / f"{self.key()}.json"


def checkpoint_root(output: Path, key: str, content_hash: str) -> Path:
    """Where a run keeps its checkpoints: per run key and dataset version (its content hash),
    so a regenerated dataset trains afresh instead of resuming; a retraining on another
    dataset lies under `<dataset id>-<hash>/`, each training in `<split>__<variant>/`.

    A retraining on another split (or variant) of the run's own dataset lies under the key
    of the run that trains it as its own (`RunSpec.key(split, variant)`): the same seed,
    configuration and data make the same network bit for bit, so the runs of one output
    folder share it and a sweep trains it once (the `generalization` evaluator's three
    splits, `generalization-gap`'s control), whichever run asks first. On another dataset
    the run's own test climbs are left out, so that training stays the run's."""
    return Path(output) / "checkpoints" / key / content_hash[:12]


def model_entry(spec: RunSpec) -> ModelEntry:
    """The registered model, with the run's input variant when it names one."""
    entry = registry.model(spec.model, spec.backend)
    if spec.variant is None:
        return entry
    if spec.variant not in VARIANTS:
        raise UnknownNameError("input variant", spec.variant, VARIANTS)
    return replace(entry, variant=spec.variant)


def is_standard(did: str) -> bool:
    """Whether `did` is the id this code generates for a robot and preset (made when missing)."""
    parsed = parse_dataset_id(did)
    return parsed is not None and dataset_id(*parsed) == did


def default_preset(did: str | None) -> str:
    """The preset of a run that names none: a standard dataset's own (by name: an earlier
    version's dataset runs under today's budgets of that name), else `small`."""
    parsed = parse_dataset_id(did) if did is not None else None
    return preset(parsed[1]).name if parsed is not None else "small"


def dataset_robot(did: str) -> str:
    """The robot whose trajectories dataset `did` holds: its metadata's when it is cached, a
    standard id's robot otherwise; an error for any other id missing from the cache."""
    if not is_identifier(did):
        raise SymbenchError(
            f"dataset id '{did}' cannot name a result record (at most {IDENTIFIER_LENGTH} "
            "letters, digits, '.', '_' and '-', not starting with '.')"
        )
    if (dataset_dir(did) / METADATA).is_file():
        return str(read_metadata(did, missing_hint(did))[1]["robot"])
    if is_standard(did):
        return str(parse_dataset_id(did)[0])  # type: ignore[index]  # standard: parsed
    raise SymbenchError(f"dataset '{did}' is not in the cache; {missing_hint(did)}")


def resolve_robot(robot: str | None, did: str) -> str:
    """The robot of a run on dataset `did`: the dataset's; `robot`, when given, must be it."""
    holds = dataset_robot(did)
    if robot is not None and robot != holds:
        raise SymbenchError(
            f"dataset '{did}' holds trajectories of {holds}, not {robot}; "
            "leave --robot out or give the dataset's robot"
        )
    return holds


def ensure_dataset(spec: RunSpec) -> Dataset:
    """The run's dataset: a standard one is generated first when it is not in the cache (or
    its robot spec changed); any other (imported) must be in the cache."""
    did = spec.dataset_id
    if is_standard(did):
        robot, grid = parse_dataset_id(did)  # type: ignore[misc]  # standard: parsed
        dataset = ensure(robot, grid, spec.workers, show_progress=spec.progress)
    else:
        dataset = load_dataset(did)
    if dataset.robot != spec.robot:
        raise SymbenchError(
            f"dataset '{did}' holds trajectories of {dataset.robot}, not {spec.robot}"
        )
    return dataset
