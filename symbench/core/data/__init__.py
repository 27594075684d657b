"""Datasets: generation, storage, views, splits and import (see dataset.py for the API).

from symbench.core.data import load_dataset
ds = load_dataset("hexa-climb-small-v5")
train, val, test = ds.split_views("leg_grouped", "acc", "iid", seed=0)

The names below load on first use (PEP 562), so that importing one of the package's light
modules (`views.schema`, say) does not load the whole data stack: every command of the CLI
imports the schema when it registers the built-in models.
"""

from __future__ import annotations

import importlib
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from symbench.core.config.presets import PRESETS as PRESETS
    from symbench.core.config.presets import dataset_id as dataset_id
    from symbench.core.data.dataset import Dataset as Dataset
    from symbench.core.data.dataset import load_dataset as load_dataset
    from symbench.core.data.generation.generate import ensure_dataset as ensure_dataset
    from symbench.core.data.generation.generate import generate as generate

_WHERE = {
    "PRESETS": "symbench.core.config.presets",
    "dataset_id": "symbench.core.config.presets",
    "Dataset": "symbench.core.data.dataset",
    "load_dataset": "symbench.core.data.dataset",
    "ensure_dataset": "symbench.core.data.generation.generate",
    "generate": "symbench.core.data.generation.generate",
}
__all__ = sorted(_WHERE)


def __getattr__(name: str) -> Any:
    if name not in _WHERE:
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    value = getattr(importlib.import_module(_WHERE[name]), name)
    globals()[name] = value
    return value
