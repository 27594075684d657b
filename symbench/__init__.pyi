"""symbench: a benchmark for learned dynamics of symmetric legged robots.

This module is the public API for plugin authors: everything a model, robot, evaluator or
split plugin needs is importable from here (`from symbench import hookimpl, ModelEntry`),
and nothing under `symbench.core` is promised to stay where it is. Names load on first use,
so `import symbench` stays light (no torch, JAX or MuJoCo until a name that needs them).
The equivariance kit is `symbench.testing` (also a pytest plugin).
"""

# The one list of public names, grouped by role: `from .module import name as public` each.
# Type checkers and editors read this stub as the module; symbench/__init__.py reads it for
# `__all__`, for where each name loads from on first use, and for the roles in its docstring
# (each `# ...` line above a group of imports is that group's role).
# The imports are grouped by role, not sorted by module:
# ruff: noqa: I001

# The installed version
from .core.common.version import __version__ as __version__

# Registering plugins
from .core.plugin.hookspecs import hookimpl as hookimpl
from .core.plugin.entries import (
    ModelEntry as ModelEntry,
    RobotEntry as RobotEntry,
    EvaluatorEntry as EvaluatorEntry,
    SplitEntry as SplitEntry,
    BACKENDS as BACKENDS,
    VIEWS as VIEWS,
    VARIANTS as VARIANTS,
    EVALUATOR_NEEDS as EVALUATOR_NEEDS,
    InvalidEntryError as InvalidEntryError,
)
from .core.common.lazy import Lazy as Lazy
from .core.common.errors import SymbenchError as SymbenchError

# Building models
from .core.data.views.model_dims import ModelDims as ModelDims
from .core.common.arrays import ViewArrays as ViewArrays
from .core.symmetry.groups import LegGroup as LegGroup, act as act
from .core.data.views import schema as schema

# Writing evaluators
from .core.runs.evaluation import (
    EvaluationContext as EvaluationContext,
    TrainedOnSplit as TrainedOnSplit,
)
from .core.common.fit_errors import rmse as rmse, relative_error as relative_error
from .core.data.symmetry.raw_action import (
    act_on_raw as act_on_raw,
    rotate_scene_about_gravity as rotate_scene_about_gravity,
    rotate_scene as rotate_scene,
)
from .core.data.symmetry.overlap import split_overlap as split_overlap
from .core.sim.scene.scenario import Scenario as Scenario
from .core.sim.scene.push import Push as Push
from .core.sim.climb.rollout import simulate as simulate
from .core.sim.tracking.learned_control import (
    track as track,
    track_batch as track_batch,
    TrackJob as TrackJob,
)
from .core.runs.control_policy import feedforward_policy as feedforward_policy
from .core.runs.closed_loop import ClosedLoopSetup as ClosedLoopSetup
from .core.data.views.transforms import build_view as build_view
from .core.board.plots import sample_efficiency_png as sample_efficiency_png
from .core.sim.tracking.references import (
    held_out_scenarios as held_out_scenarios,
    reference_scenarios as reference_scenarios,
    reference_push as reference_push,
    oracle_policy as oracle_policy,
    model_jobs as model_jobs,
)
from .core.data.symmetry.report import (
    NoImagePairsError as NoImagePairsError,
    dataset_symmetry as dataset_symmetry,
)
from .core.data.twins import (
    symmetry_report as symmetry_report,
    twin_symmetry as twin_symmetry,
)

# Writing splits
from .core.data.splits import (
    SplitContext as SplitContext,
    carve_validation as carve_validation,
    control_of as control_of,
)

# Reading a preset's sizes, budgets and horizons (`symbench presets`)
from .core.config.presets import Preset as Preset, PRESETS as PRESETS, preset as preset

# Using symbench from Python (a plugin's own tests)
from .core.plugin.registry import model_entry as model_entry
from .core.robot.specs import load_robot as load_robot
from .core.training.config import TrainConfig as TrainConfig
from .core.training.loop import train as train
from .core.config.protocols import Converge as Converge, Cosine as Cosine, Paper as Paper
