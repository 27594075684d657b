"""How the boards write a mean over seeds: '0.0996 [0.0634, 0.135]', the mean and its
95 % bootstrap interval (`statistics.mean_interval`), the same on every page and the site."""

from __future__ import annotations

import numpy as np
import pandas as pd


def metric_cell(mean: float, low: float, high: float, digits: int = 4) -> str:
    """'0.0996 [0.0634, 0.135]': the mean over seeds and its 95 % interval (none with one
    seed), all to the same significant digits."""
    if np.isnan(mean):
        return "-"
    if np.isnan(low):
        return f"{mean:.{digits}g}"
    return f"{mean:.{digits}g} [{low:.{digits}g}, {high:.{digits}g}]"


def cell_of(row: pd.Series, metric: str, digits: int = 4) -> str:
    """A metric of an aggregate row as `metric_cell` writes it."""
    return metric_cell(
        row[f"{metric}_mean"], row[f"{metric}_ci_low"], row[f"{metric}_ci_high"], digits
    )
