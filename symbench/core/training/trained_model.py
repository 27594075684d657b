"""A trained network with its normalization: predict in N m, save and load without pickle.

A saved model is a folder: `model.safetensors` (parameters under 'params/', normalization
statistics under 'normalization/', the JSON description as safetensors metadata and the
content hash, all in one atomically written file, see `checkpoints`) and `model.json` (the
same description, human-readable). Loading checks the hash: a damaged file is refused.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np
from pydantic import ValidationError

from symbench.core.common.errors import SymbenchError
from symbench.core.common.validation import explain
from symbench.core.common.version import __version__
from symbench.core.data.views.model_dims import ModelDims
from symbench.core.plugin.entries import ModelEntry
from symbench.core.training.backends import Predictor, get_backend
from symbench.core.training.checkpoints import encode, read_tensors, write_json, write_tensors
from symbench.core.training.model_description import ModelDescription
from symbench.core.training.normalization import Normalizer

FORMAT = "symbench-model/1"
TENSORS, DESCRIPTION = "model.safetensors", "model.json"


@dataclass
class TrainedModel:
    entry: ModelEntry
    dims: ModelDims
    hyper: dict[str, Any]
    normalizer: Normalizer
    params: dict[str, np.ndarray]
    history: dict[str, list[float]]  # train_loss and val_loss per check (normalized MSE)
    best_epoch: int  # the validation check of the best parameters (an epoch under `paper`)
    config: dict[str, Any]  # the TrainConfig as a dict
    stopped: str = ""  # why training ended, a sentence
    stopped_by: str = ""  # why training ended: a protocols.StoppedBy
    steps: int = 0  # gradient steps taken
    best_step: int = 0  # gradient steps taken when the best parameters were
    _predictor: Predictor | None = field(default=None, repr=False, compare=False)

    @property
    def n_params(self) -> int:
        return int(sum(v.size for v in self.params.values()))

    def predict(self, inputs: dict[str, np.ndarray]) -> np.ndarray:
        """Torques (N, n_legs, 3) in N m, float64, from raw (unnormalized) view inputs."""
        n = self._check_inputs(inputs)
        if n == 0:
            return np.zeros((0, self.dims.n_legs, 3))
        if self._predictor is None:
            backend = get_backend(self.entry.backend)
            self._predictor = backend.make_predictor(
                self.entry,
                self.dims,
                self.hyper,
                self.params,
                self.normalizer,
                np.float32,
                backend.default_compiled,
            )
        return self._predictor(inputs)

    def _check_inputs(self, inputs: dict[str, np.ndarray]) -> int:
        if set(inputs) != set(self.dims.keys):
            raise SymbenchError(
                f"{self.entry.name} expects inputs {list(self.dims.keys)} "
                f"({self.dims.view} view), got {sorted(inputs)}"
            )
        sizes = {len(inputs[k]) for k in self.dims.keys}
        for key, shape in self.dims.inputs:
            a = np.asarray(inputs[key])
            if a.shape[1:] != shape:
                raise SymbenchError(
                    f"{self.entry.name}: input '{key}' has per-sample shape "
                    f"{a.shape[1:]}, expected {shape}"
                )
            if not np.isfinite(a).all():
                raise SymbenchError(
                    f"{self.entry.name}: input '{key}' holds NaN or infinite values"
                )
        if len(sizes) != 1:
            raise SymbenchError(
                f"{self.entry.name}: inputs have different sample counts {sorted(sizes)}"
            )
        return sizes.pop()

    def describe(self) -> dict[str, Any]:
        return {
            "format": FORMAT,
            "model": self.entry.name,
            "backend": self.entry.backend,
            "view": self.entry.view,
            "variant": self.entry.variant,
            "dims": self.dims.to_dict(),
            "hyper": self.hyper,
            "config": self.config,
            "history": self.history,
            "best_epoch": self.best_epoch,
            "stopped": self.stopped,
            "stopped_by": self.stopped_by,
            "steps": self.steps,
            "best_step": self.best_step,
            "n_params": self.n_params,
            "symbench_version": __version__,
        }

    def _contents(self) -> tuple[dict[str, np.ndarray], dict[str, Any]]:
        arrays = {f"params/{k}": v for k, v in self.params.items()}
        arrays.update(self.normalizer.to_arrays())
        return arrays, self.describe()

    def sha256(self) -> str:
        """The content hash its checkpoint carries once saved (`checkpoints.checkpoint_sha256`
        of `model.safetensors`), computed without writing: the model's identity in records."""
        return encode(*self._contents())[1]

    def save(self, folder: Path) -> None:
        folder = Path(folder)
        arrays, description = self._contents()
        write_tensors(folder / TENSORS, arrays, description)
        write_json(folder / DESCRIPTION, description)

    @classmethod
    def load(cls, folder: Path, entry: ModelEntry | None = None) -> TrainedModel:
        """The model saved in `folder`; `entry` defaults to the registered model it names."""
        arrays, d = read_tensors(Path(folder) / TENSORS)
        if not isinstance(d, dict) or d.get("format") != FORMAT:
            raise SymbenchError(f"{folder}/{TENSORS} is not a symbench model ({FORMAT})")
        try:
            ModelDescription.model_validate(d)
        except ValidationError as exc:
            raise explain(exc, f"{folder}/{TENSORS}: malformed model description") from None
        try:
            if entry is None:
                from symbench.core.plugin import registry

                entry = registry.model(d["model"], d["backend"])
            dims, normalizer = ModelDims.from_dict(d["dims"]), Normalizer.from_arrays(arrays)
        except SymbenchError as exc:
            raise SymbenchError(f"{folder}/{TENSORS}: {exc}") from None
        if (entry.name, entry.backend) != (d["model"], d["backend"]):
            raise SymbenchError(
                f"{folder} holds {d['model']}/{d['backend']}, not {entry.name}/{entry.backend}"
            )
        params = {
            k.removeprefix("params/"): v for k, v in arrays.items() if k.startswith("params/")
        }
        return cls(
            entry,
            dims,
            d["hyper"],
            normalizer,
            params,
            d["history"],
            d["best_epoch"],
            d["config"],
            d["stopped"],
            d.get("stopped_by", ""),
            d.get("steps", 0),
            d.get("best_step", 0),
        )
