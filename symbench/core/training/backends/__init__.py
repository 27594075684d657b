"""The two training backends behind one interface, imported only when asked for.

Parameters cross this interface as flat dicts of numpy arrays (the checkpoint format), so
training, checkpoints, the equivariance kit and the benchmarks are written once for every
backend. Each backend turns a `ModelEntry`'s network into a predictor (normalization
included) and a trainer (Adam, MSE on normalized targets).
"""

from __future__ import annotations

import importlib
from collections.abc import Callable
from typing import Any, Protocol

import numpy as np

from symbench.core.common.errors import UnknownNameError
from symbench.core.data.views.model_dims import ModelDims
from symbench.core.plugin.entries import BACKENDS, ModelEntry
from symbench.core.training.normalization import Normalizer

Params = dict[str, np.ndarray]
Predictor = Callable[[dict[str, np.ndarray]], np.ndarray]


class Trainer(Protocol):
    def set_data(
        self,
        train_inputs: dict[str, np.ndarray],
        train_target: np.ndarray,
        val_inputs: dict[str, np.ndarray],
        val_target: np.ndarray,
    ) -> None: ...
    def train_epoch(self, order: np.ndarray, rate_scale: np.ndarray | None = None) -> float:
        """One pass over the (n_batches, batch_size) sample indices, step i at the learning
        rate times `rate_scale[i]` (None: times 1); the mean batch loss."""

    def val_loss(self) -> float: ...
    def params(self) -> Params: ...
    def load_params(self, params: Params) -> None: ...
    def optimizer_state(self) -> Params: ...
    def load_optimizer_state(self, state: Params) -> None: ...


class Backend(Protocol):
    name: str
    default_compiled: bool  # the faster choice for training and prediction on this backend

    def init_params(
        self, entry: ModelEntry, dims: ModelDims, hyper: dict[str, Any], seed: int
    ) -> Params: ...

    def parameter_shapes(
        self, entry: ModelEntry, dims: ModelDims, hyper: dict[str, Any]
    ) -> dict[str, tuple[int, ...]]:
        """The names and shapes `init_params` would give, found without allocating them: a
        size search or a size check may look at networks of gigabytes."""

    def make_predictor(
        self,
        entry: ModelEntry,
        dims: ModelDims,
        hyper: dict[str, Any],
        params: Params,
        normalizer: Normalizer,
        dtype: Any = np.float32,
        compiled: bool = ...,
    ) -> Predictor:
        """inputs (raw units, numpy) -> torques (N, n_legs, 3) float64, computed in `dtype`."""

    def make_trainer(
        self,
        entry: ModelEntry,
        dims: ModelDims,
        hyper: dict[str, Any],
        params: Params,
        learning_rate: float,
        compiled: bool = ...,
    ) -> Trainer: ...


_MODULES = {
    "torch": "symbench.core.training.backends.torch_backend",
    "jax": "symbench.core.training.backends.jax_backend",
}


def get_backend(name: str) -> Backend:
    if name not in _MODULES:
        raise UnknownNameError("backend", name, BACKENDS)
    return importlib.import_module(_MODULES[name]).BACKEND
