"""symbench: a benchmark for learned dynamics of symmetric legged robots.

This module is the public API for plugin authors: everything a model, robot, evaluator or
split plugin needs is importable from here (`from symbench import hookimpl, ModelEntry`),
and nothing under `symbench.core` is promised to stay where it is. Names load on first use,
so `import symbench` stays light (no torch, JAX or MuJoCo until a name that needs them).

Registering plugins
    hookimpl, ModelEntry, RobotEntry, EvaluatorEntry, SplitEntry, Lazy, BACKENDS, VIEWS,
    VARIANTS, EVALUATOR_NEEDS, SymbenchError, InvalidEntryError
Building models
    ModelDims, ViewArrays, LegGroup, act, schema
Writing evaluators
    EvaluationContext, TrainedOnSplit, rmse, relative_error, act_on_raw,
    rotate_scene_about_gravity, rotate_scene, Scenario, simulate, track, track_batch,
    TrackJob, feedforward_policy, build_view, ClosedLoopSetup,
    sample_efficiency_png, held_out_scenarios, reference_scenarios, oracle_policy, model_jobs,
    dataset_symmetry
Writing splits
    SplitContext, carve_validation
Reading a preset's sizes, budgets and horizons (`symbench presets`)
    Preset, PRESETS, preset
Using symbench from Python (a plugin's own tests)
    model_entry, load_robot, TrainConfig, train
The equivariance kit is `symbench.testing` (also a pytest plugin); `__version__` is the
installed version.
"""

from __future__ import annotations

import importlib
from typing import TYPE_CHECKING, Any

from symbench.core.common.version import __version__
from symbench.core.training.kernels import pin_training_kernels

pin_training_kernels()  # before torch, MKL or XLA load: same training numbers on every CPU

from symbench.core.plugin.hookspecs import hookimpl  # noqa: E402  (the marker plugin authors use)

# public name -> "module:attribute" ("module" alone for a module), imported on first use
_PUBLIC: dict[str, str] = {
    "ModelEntry": "symbench.core.plugin.entries:ModelEntry",
    "RobotEntry": "symbench.core.plugin.entries:RobotEntry",
    "EvaluatorEntry": "symbench.core.plugin.entries:EvaluatorEntry",
    "SplitEntry": "symbench.core.plugin.entries:SplitEntry",
    "BACKENDS": "symbench.core.plugin.entries:BACKENDS",
    "VIEWS": "symbench.core.plugin.entries:VIEWS",
    "VARIANTS": "symbench.core.plugin.entries:VARIANTS",
    "EVALUATOR_NEEDS": "symbench.core.plugin.entries:EVALUATOR_NEEDS",
    "InvalidEntryError": "symbench.core.plugin.entries:InvalidEntryError",
    "Lazy": "symbench.core.common.lazy:Lazy",
    "SymbenchError": "symbench.core.common.errors:SymbenchError",
    "ModelDims": "symbench.core.data.views.model_dims:ModelDims",
    "ViewArrays": "symbench.core.common.arrays:ViewArrays",
    "LegGroup": "symbench.core.symmetry.groups:LegGroup",
    "act": "symbench.core.symmetry.groups:act",
    "schema": "symbench.core.data.views.schema",
    "EvaluationContext": "symbench.core.runs.evaluation:EvaluationContext",
    "TrainedOnSplit": "symbench.core.runs.evaluation:TrainedOnSplit",
    "rmse": "symbench.core.runs.evaluation:rmse",
    "relative_error": "symbench.core.runs.evaluation:relative_error",
    "act_on_raw": "symbench.core.data.symmetry.raw_action:act_on_raw",
    "rotate_scene_about_gravity": (
        "symbench.core.data.symmetry.raw_action:rotate_scene_about_gravity"
    ),
    "rotate_scene": "symbench.core.data.symmetry.raw_action:rotate_scene",
    "Scenario": "symbench.core.sim.scene.scenario:Scenario",
    "simulate": "symbench.core.sim.climb.rollout:simulate",
    "track": "symbench.core.sim.tracking.learned_control:track",
    "track_batch": "symbench.core.sim.tracking.learned_control:track_batch",
    "TrackJob": "symbench.core.sim.tracking.learned_control:TrackJob",
    "feedforward_policy": "symbench.core.runs.control_policy:feedforward_policy",
    "held_out_scenarios": "symbench.core.sim.tracking.references:held_out_scenarios",
    "reference_scenarios": "symbench.core.sim.tracking.references:reference_scenarios",
    "oracle_policy": "symbench.core.sim.tracking.references:oracle_policy",
    "model_jobs": "symbench.core.sim.tracking.references:model_jobs",
    "ClosedLoopSetup": "symbench.core.runs.closed_loop:ClosedLoopSetup",
    "build_view": "symbench.core.data.views.transforms:build_view",
    "dataset_symmetry": "symbench.core.data.symmetry.report:dataset_symmetry",
    "sample_efficiency_png": "symbench.core.board.plots:sample_efficiency_png",
    "SplitContext": "symbench.core.data.splits:SplitContext",
    "carve_validation": "symbench.core.data.splits:carve_validation",
    "Preset": "symbench.core.config.presets:Preset",
    "PRESETS": "symbench.core.config.presets:PRESETS",
    "preset": "symbench.core.config.presets:preset",
    "model_entry": "symbench.core.plugin.registry:model",
    "load_robot": "symbench.core.robot.specs:load_robot",
    "TrainConfig": "symbench.core.training.loop:TrainConfig",
    "train": "symbench.core.training.loop:train",
}

__all__ = [
    "BACKENDS",
    "EVALUATOR_NEEDS",
    "PRESETS",
    "VARIANTS",
    "VIEWS",
    "ClosedLoopSetup",
    "EvaluationContext",
    "EvaluatorEntry",
    "InvalidEntryError",
    "Lazy",
    "LegGroup",
    "ModelDims",
    "ModelEntry",
    "Preset",
    "RobotEntry",
    "Scenario",
    "SplitContext",
    "SplitEntry",
    "SymbenchError",
    "TrackJob",
    "TrainConfig",
    "TrainedOnSplit",
    "ViewArrays",
    "__version__",
    "act",
    "act_on_raw",
    "build_view",
    "carve_validation",
    "dataset_symmetry",
    "feedforward_policy",
    "held_out_scenarios",
    "hookimpl",
    "load_robot",
    "model_entry",
    "model_jobs",
    "oracle_policy",
    "preset",
    "reference_scenarios",
    "relative_error",
    "rmse",
    "rotate_scene",
    "rotate_scene_about_gravity",
    "sample_efficiency_png",
    "schema",
    "simulate",
    "track",
    "track_batch",
    "train",
]
assert set(__all__) == {"__version__", "hookimpl", *_PUBLIC}


def __getattr__(name: str) -> Any:
    """Load a public name on first use (PEP 562) and keep it."""
    if name not in _PUBLIC:
        raise AttributeError(f"module 'symbench' has no attribute '{name}'")
    module, _, attribute = _PUBLIC[name].partition(":")
    value = importlib.import_module(module)
    if attribute:
        value = getattr(value, attribute)
    globals()[name] = value
    return value


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(__all__))


if TYPE_CHECKING:  # what type checkers and editors see
    from symbench.core.board.plots import sample_efficiency_png
    from symbench.core.common.arrays import ViewArrays
    from symbench.core.common.errors import SymbenchError
    from symbench.core.common.lazy import Lazy
    from symbench.core.config.presets import PRESETS, Preset, preset
    from symbench.core.data.splits import SplitContext, carve_validation
    from symbench.core.data.symmetry.raw_action import (
        act_on_raw,
        rotate_scene,
        rotate_scene_about_gravity,
    )
    from symbench.core.data.views import schema
    from symbench.core.data.views.model_dims import ModelDims
    from symbench.core.data.views.transforms import build_view
    from symbench.core.plugin.entries import (
        BACKENDS,
        EVALUATOR_NEEDS,
        VARIANTS,
        VIEWS,
        EvaluatorEntry,
        InvalidEntryError,
        ModelEntry,
        RobotEntry,
        SplitEntry,
    )
    from symbench.core.plugin.registry import model as model_entry
    from symbench.core.robot.specs import load_robot
    from symbench.core.runs.closed_loop import ClosedLoopSetup
    from symbench.core.runs.control_policy import feedforward_policy
    from symbench.core.runs.evaluation import (
        EvaluationContext,
        TrainedOnSplit,
        relative_error,
        rmse,
    )
    from symbench.core.sim.climb.rollout import simulate
    from symbench.core.sim.scene.scenario import Scenario
    from symbench.core.sim.tracking.learned_control import TrackJob, track, track_batch
    from symbench.core.sim.tracking.references import (
        held_out_scenarios,
        model_jobs,
        oracle_policy,
        reference_scenarios,
    )
    from symbench.core.training.loop import TrainConfig, train
