"""Loading a cached dataset: verified files, raw trajectories, views and splits.

ds = load_dataset("hexa-climb-small-v5")
split = ds.split_indices("unseen-rotation", seed=0)      # trajectory ids
train, val, test = ds.split_views("leg_grouped", "acc", "unseen-rotation", seed=0)
"""

from __future__ import annotations

from dataclasses import dataclass, field
from functools import cached_property
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from symbench.core.common.arrays import ViewArrays
from symbench.core.common.errors import SymbenchError
from symbench.core.config.presets import parse_dataset_id
from symbench.core.data.splits import SplitContext, SplitIndices, resolve
from symbench.core.data.storage.files import read_trajectory
from symbench.core.data.storage.metadata import read_metadata, verify
from symbench.core.data.views.frames import LegFrames
from symbench.core.data.views.transforms import build_view, require_known

if TYPE_CHECKING:
    from symbench.core.robot.specs import RobotSpec


@dataclass
class Dataset:
    """A verified dataset in the cache. Raw data is read once, on first use."""

    id: str
    root: Path
    metadata: dict[str, Any]
    _raw: tuple[dict[str, np.ndarray], np.ndarray] | None = field(default=None, repr=False)

    @property
    def robot(self) -> str:
        return self.metadata["robot"]

    @property
    def n_legs(self) -> int:
        return int(self.metadata["n_legs"])

    @property
    def content_hash(self) -> str:
        return self.metadata["content_hash"]

    @property
    def trajectory_ids(self) -> np.ndarray:
        return np.array([rec["id"] for rec in self.metadata["trajectories"]], dtype=np.int64)

    @property
    def scenarios(self) -> tuple[dict[str, Any], ...]:
        return tuple(rec["scenario"] for rec in self.metadata["trajectories"])

    @property
    def n_samples(self) -> np.ndarray:
        """Samples per trajectory in every view (its steps but the last)."""
        return np.array([rec["n_steps"] - 1 for rec in self.metadata["trajectories"]])

    @cached_property
    def spec(self) -> RobotSpec:
        from symbench.core.robot.specs import load_robot

        try:
            spec = load_robot(self.robot)
        except SymbenchError as exc:
            raise SymbenchError(f"dataset '{self.id}': {exc}") from None
        if spec.spec_hash() != self.metadata["robot_spec_hash"] or spec.n_legs != self.n_legs:
            raise SymbenchError(
                f"dataset '{self.id}' was made with another version of robot "
                f"'{self.robot}' (its robot.toml changed since); rebuild it with: "
                f"{self.metadata['repair_command']}"
            )
        return spec

    @property
    def frames(self) -> LegFrames:
        return LegFrames.from_spec(self.spec)

    def raw(self) -> tuple[dict[str, np.ndarray], np.ndarray]:
        """All raw columns stacked over trajectories, and the trajectory id of each row."""
        if self._raw is None:
            parts = [
                read_trajectory(self.root / rec["file"], self.n_legs)
                for rec in self.metadata["trajectories"]
            ]
            raw = {k: np.concatenate([p[k] for p in parts]) for k in parts[0]}
            ids = np.repeat(self.trajectory_ids, [len(p["t"]) for p in parts])
            self._raw = (raw, ids)
        return self._raw

    def view(self, view: str = "leg_grouped", variant: str = "acc") -> ViewArrays:
        """Every sample of the dataset in `view` ("leg_grouped", "vector", "body_graph")."""
        require_known(self.metadata, view)
        frames = self.frames  # a dataset of another robot is refused before its files are read
        raw, ids = self.raw()
        return build_view(raw, ids, frames, view, variant)

    def split_context(self, seed: int) -> SplitContext:
        return SplitContext(
            self.id,
            self.trajectory_ids,
            self.scenarios,
            self.n_samples,
            self.spec.group.rotation_order,
            int(seed),
        )

    def split_indices(self, split: str, seed: int = 0) -> SplitIndices:
        """Train, validation and test trajectory ids of a registered split."""
        return resolve(split, self.split_context(seed))

    def split_views(
        self, view: str, variant: str, split: str, seed: int = 0
    ) -> tuple[ViewArrays, ViewArrays, ViewArrays]:
        """(train, val, test) samples of `view` under `split`."""
        arrays = self.view(view, variant)
        parts = self.split_indices(split, seed)
        return tuple(
            arrays.take(np.isin(arrays.trajectory, ids))  # type: ignore[return-value]
            for ids in (parts.train, parts.val, parts.test)
        )


def missing_hint(dataset_id: str) -> str:
    parsed = parse_dataset_id(dataset_id)
    if parsed:
        return f"generate it with: symbench data generate --robot {parsed[0]} --preset {parsed[1]}"
    return "see `symbench list datasets`, `symbench data generate` and `symbench data import`"


def load_dataset(dataset_id: str, verify_files: bool = True) -> Dataset:
    """The cached dataset `dataset_id`, its files checked against their SHA-256."""
    root, meta = read_metadata(dataset_id, missing_hint(dataset_id))
    if verify_files:
        verify(root, meta)
    if not meta["trajectories"]:
        raise SymbenchError(
            f"dataset '{dataset_id}' has no trajectories ({len(meta['failures'])} failed)"
        )
    return Dataset(dataset_id, root, meta)
