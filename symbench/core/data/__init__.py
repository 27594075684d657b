"""Datasets: generation, storage, views, splits and import (see dataset.py for the API).

from symbench.core.data import load_dataset
ds = load_dataset("hexa-climb-small-v5")
train, val, test = ds.split_views("leg_grouped", "acc", "iid", seed=0)
"""

from symbench.core.config.presets import PRESETS, dataset_id
from symbench.core.data.dataset import Dataset, load_dataset
from symbench.core.data.generation.generate import ensure_dataset, generate

__all__ = ["PRESETS", "Dataset", "dataset_id", "ensure_dataset", "generate", "load_dataset"]
