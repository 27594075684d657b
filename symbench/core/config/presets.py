"""The presets: every size, budget and horizon of a benchmark run, one frozen object each.

A preset names the dataset (its scenario grid), the training budget (epoch cap), the
evaluators' budgets (test samples, closed-loop horizon and scenarios) and the shares of the
sample-efficiency curve; `symbench presets` shows them all. Every consumer reads its numbers
from here (`preset(name)`), never from a copy.

A grid is the product of inclinations, slope headings, initial base yaws (evenly covering
the full circle, an even whole number per fundamental sector of the robot's rotation group,
so that `unseen-rotation` can train on every other yaw of one sector and test on the yaws
between them in the other sectors, and `orbit-rotation` on their exact images), step
directions, leg orders and seeds; its order
is fixed, so trajectory k of a preset is always the same scenario. The grid, with the
preset's name and description, is stored in the dataset metadata (and so in its content
hash): bump DATASET_VERSION whenever a grid or the recorded content changes. The budgets
are not part of the dataset.

A noisy variant (`small-noisy`) is the same grid with the expert's executed torques
perturbed (`ScenarioGrid.torque_noise`, see `symbench.core.sim.scene.scenario.Scenario`): data for
control, on which the closed-loop evaluator trains (`ClosedLoop.train_preset`). A grid
without noise stores no `torque_noise`, so the noise-free datasets are what they were.
"""

from __future__ import annotations

import itertools
import math
from dataclasses import asdict, dataclass, replace
from typing import Any

from symbench.core.common.errors import UnknownNameError
from symbench.core.sim.scene.scenario import Scenario

# 2: yaws beyond a symmetry step carry the gait along; 3: small grid; 4: simulated with pinned
# numerics (symbench.core.data.generation.determinism), identical on every x86-64 CPU; 5: an even
# number of yaws per sector (small: at least 24 per turn), smoke's yaws 0, 180 and 250 degrees, so
# that `unseen-rotation` tests yaws between the training yaws (`orbit-rotation` is the old split);
# 6: the climbing loop compiled (numba) and the controller's QP solved by DAQP instead of proxsuite,
# the same controller and physics rounded differently (10x faster generation)
DATASET_VERSION = 6
RECORD_PERIOD = 0.006  # s between recorded samples (the paper kept every 6th 1 kHz step)
LEG_ORDERS = ("default", "reversed")


@dataclass(frozen=True)
class ScenarioGrid:
    """The dataset: one trajectory per combination of these axes, in this order."""

    inclinations_deg: tuple[float, ...]
    headings_deg: tuple[float, ...]
    yaws_per_turn: int  # at least this many, an even number per sector; 0: 0, 180, 250
    directions: tuple[str, ...]
    leg_orders: tuple[str, ...]
    seeds: tuple[int, ...]
    seconds: float  # length of each trajectory
    torque_noise: float = 0.0  # N m, std of the noise on the expert's executed command

    def yaws_deg(self, rotation_order: int) -> tuple[float, ...]:
        """Evenly spaced from 0, an even number per sector: every other one of a sector's yaws
        trains `unseen-rotation`, the ones between are its test yaws in the other sectors (even,
        so that both sets are closed under the robot's mirrors). 0, 180 and 250 (smoke): 180
        is an image of 0 for every even rotation order, 250 lies outside the first sector and
        off every image of 0 for every rotation order from 2 to 12."""
        if self.yaws_per_turn == 0:
            return (0.0, 180.0, 250.0)
        per_sector = 2 * math.ceil(self.yaws_per_turn / (2 * rotation_order))
        n = rotation_order * per_sector
        return tuple(round(360.0 * k / n, 9) for k in range(n))

    def scenarios(self, robot: str, n_legs: int, rotation_order: int) -> list[Scenario]:
        """The grid in its fixed order: the index in this list is the trajectory id."""
        orders = {"default": None, "reversed": tuple(range(n_legs - 1, -1, -1))}
        axes = (
            self.inclinations_deg,
            self.headings_deg,
            self.yaws_deg(rotation_order),
            self.directions,
            self.leg_orders,
            self.seeds,
        )
        return [
            Scenario(
                robot=robot,
                inclination_deg=inc,
                heading_deg=head,
                yaw_deg=yaw,
                direction=direction,
                leg_order=orders[order],
                seed=seed,
                seconds=self.seconds,
                torque_noise=self.torque_noise,
            )
            for inc, head, yaw, direction, order, seed in itertools.product(*axes)
        ]


@dataclass(frozen=True)
class Training:
    """The training budgets of a run, per protocol (symbench.core.training.loop)."""

    max_steps: int  # converge, cosine: gradient steps, for every model and fraction
    eval_every: int  # converge, cosine: gradient steps between validation checks
    patience: int  # converge, cosine: checks without a better validation loss before it stops
    max_epochs: int  # paper: the epoch cap (its rule usually ends earlier; `--max-epochs`)
    val_stride: int = 1  # validation checks use every val_stride-th row of each held-out climb


@dataclass(frozen=True)
class Evaluation:
    """What the transform-based evaluators (equivariance, invariance) spend."""

    max_samples: int  # test rows (whole test trajectories, in order, cut at this many)
    invariance_trials: int  # random rotations about gravity + translations tried


@dataclass(frozen=True)
class ClosedLoop:
    """The closed-loop evaluator: the learned model tracking held-out expert climbs."""

    seconds: float  # cap of the horizon: each reference is tracked over its climb's length
    references: int  # held-out test climbs tracked per run, from distinct symmetry orbits
    pd_fractions: tuple[float, ...]  # joint PD gains, as fractions of the servo gains
    headline_pd: float  # the fraction reported as the headline (`pd_*` metrics)
    # the preset whose dataset (same robot) the model is retrained on for control (its
    # noisy variant); None: the run's own dataset
    train_preset: str | None = None


@dataclass(frozen=True)
class SampleEfficiency:
    """The sample-efficiency curve, whose last point (all of them) is the iid split."""

    fractions: tuple[float, ...]  # shares of the iid training trajectories: the fraction-F splits


@dataclass(frozen=True)
class Preset:
    name: str
    description: str
    dataset: ScenarioGrid
    training: Training
    evaluation: Evaluation
    closed_loop: ClosedLoop
    sample_efficiency: SampleEfficiency

    def scenarios(self, robot: str, n_legs: int, rotation_order: int) -> list[Scenario]:
        """The dataset's scenarios in their fixed order (see `ScenarioGrid.scenarios`)."""
        return self.dataset.scenarios(robot, n_legs, rotation_order)

    def grid(self, rotation_order: int) -> dict[str, Any]:
        """JSON-ready description of the grid, stored in the dataset metadata: part of the
        content hash, so its fields and their order stay as they are (`torque_noise` only
        when there is noise)."""
        grid = asdict(self.dataset)
        if not self.dataset.torque_noise:
            del grid["torque_noise"]
        return {
            "name": self.name,
            "description": self.description,
            **grid,
            "yaws_deg": list(self.dataset.yaws_deg(rotation_order)),
        }


# the budgets every preset shares (they shape the published records: change none)
_EVALUATION = Evaluation(max_samples=4096, invariance_trials=4)
_FRACTIONS = SampleEfficiency(fractions=(0.1, 0.25, 0.5, 0.75))
# closed loop: the horizon is each held-out climb's length (the grid's seconds); the PD at
# these fractions of the servo gains, 0.1 the headline (symbench/plugins/evaluators/closed_loop.py)
_PD_FRACTIONS = (0.0, 0.1, 0.3, 1.0)
# the noisy variants' torque noise (N m): with it SDNN alone held a whole small climb on hexa
# while FFNN fell (issue 18), the expert's own climbs mostly still succeeding
TORQUE_NOISE = 0.5
_SMOKE_GRID = ScenarioGrid(
    inclinations_deg=(90.0,),
    headings_deg=(0.0, 180.0),
    yaws_per_turn=0,
    directions=("forward",),
    leg_orders=("default",),
    seeds=(0,),
    seconds=1.0,
)
# Two headings suffice for the invariance split (on a wall they are exact images);
# 24 yaws a turn (36 for nona) give every robot at least 4 yaws per symmetry sector: 2 that
# train `unseen-rotation`, 2 between them that it tests in the other sectors.
_SMALL_GRID = ScenarioGrid(
    inclinations_deg=(90.0,),
    headings_deg=(0.0, 180.0),
    yaws_per_turn=24,
    directions=("forward", "left"),
    leg_orders=("default",),
    seeds=(0,),
    seconds=2.6,
)

# Transfer: every slope from the floor (0) to the ceiling (180 degrees) and both leg orders,
# so that `unseen-inclination` (train up to the wall, test on overhangs and the ceiling) and
# `unseen-gait` (train on one stepping sequence, test on the reversed one) hold out a band of
# slopes or a gait; smoke's three yaws (two orbits on every robot) keep it small.
_TRANSFER_GRID = ScenarioGrid(
    inclinations_deg=(0.0, 30.0, 60.0, 90.0, 120.0, 150.0, 180.0),
    headings_deg=(0.0,),
    yaws_per_turn=0,
    directions=("forward", "left"),
    leg_orders=LEG_ORDERS,
    seeds=(0,),
    seconds=2.6,
)

SMOKE = Preset(
    "smoke",
    "a few one-second trajectories, for tests (seconds)",
    _SMOKE_GRID,
    Training(max_steps=30, eval_every=10, patience=2, max_epochs=3),
    _EVALUATION,
    ClosedLoop(1.0, 2, _PD_FRACTIONS, 0.1, train_preset="smoke-noisy"),
    _FRACTIONS,
)
SMALL = Preset(
    "small",
    "the default of `symbench run`: minutes on a laptop",
    _SMALL_GRID,
    Training(max_steps=10000, eval_every=500, patience=6, max_epochs=60),
    _EVALUATION,
    ClosedLoop(2.6, 6, _PD_FRACTIONS, 0.1, train_preset="small-noisy"),
    _FRACTIONS,
)
TRANSFER = Preset(
    "transfer",
    "every slope from floor to ceiling and both leg orders: the unseen-inclination and "
    "unseen-gait splits",
    _TRANSFER_GRID,
    SMALL.training,
    _EVALUATION,
    ClosedLoop(2.6, 6, _PD_FRACTIONS, 0.1),
    _FRACTIONS,
)
PAPER = Preset(
    "paper",
    "the full replication: slopes, headings, yaws, gaits and seeds",
    ScenarioGrid(
        inclinations_deg=(57.29577951308232, 90.0),
        headings_deg=(0.0, 90.0, 180.0, 270.0),
        yaws_per_turn=6,
        directions=("forward", "backward", "left", "right"),
        leg_orders=LEG_ORDERS,
        seeds=(0,),
        seconds=10.0,
    ),
    # a check every 5 000 steps on every 4th row of the held-out climbs: one pass over all of
    # hexa's 153 000 validation rows cost sdnn 31 % of the training time at one check per
    # 2 000 steps, 12 % at one per 5 000; patience 4 keeps the same 20 000-step window
    Training(max_steps=200000, eval_every=5000, patience=4, max_epochs=500, val_stride=4),
    _EVALUATION,
    ClosedLoop(10.0, 8, _PD_FRACTIONS, 0.1),
    _FRACTIONS,
)


def _noisy(base: Preset, description: str) -> Preset:
    """Data for control: `base` with the expert's executed torques perturbed (the labels are
    the expert's commands); every budget is the base's, whose closed loop trains on it."""
    return replace(
        base,
        name=f"{base.name}-noisy",
        description=description,
        dataset=replace(base.dataset, torque_noise=TORQUE_NOISE),
    )


PRESETS: dict[str, Preset] = {
    p.name: p
    for p in (
        SMOKE,
        SMALL,
        TRANSFER,
        PAPER,
        _noisy(SMOKE, "smoke's grid with torque noise on the expert's execution, for tests"),
        _noisy(SMALL, "small's grid with torque noise on the expert's execution: data for control"),
    )
}


def preset(name: str) -> Preset:
    if name not in PRESETS:
        raise UnknownNameError("preset", name, PRESETS)
    return PRESETS[name]


def dataset_id(robot: str, preset_name: str) -> str:
    """e.g. hexa-climb-small-v5."""
    preset(preset_name)
    return f"{robot}-climb-{preset_name}-v{DATASET_VERSION}"


def parse_dataset_id(dataset_id_: str) -> tuple[str, str] | None:
    """(robot, preset) of a generated dataset id, or None for other ids (imports); a
    preset's name may hold dashes (hexa-climb-small-noisy-v5), and so may a robot's
    (hexa-asym-0.05-climb-small-v5)."""
    robot, climb, rest = dataset_id_.partition("-climb-")
    name, dash, version = rest.rpartition("-")
    if robot and climb and dash and name in PRESETS and version.startswith("v"):
        return robot, name
    return None
