"""How the boards write numbers: '0.0150 [0.0141, 0.0162]', a mean over seeds and its 95 %
bootstrap interval (`statistics.mean_interval`), the same on every page and the site.

Numbers are plain fixed decimals to a number of significant digits, never '1e+04' or
'3.067e-07': thousands are grouped with a narrow no-break space ('10 000'), an interval's
bounds take the mean's decimals (so they line up), and only a mean below 0.001 (the float
rounding of an exact equivariance) is written on a power of ten ('3.07 x 10⁻⁷' with a times
sign), its bounds on the same power.
"""

from __future__ import annotations

import math

import numpy as np
import pandas as pd

GROUP = "\u202f"  # narrow no-break space: '10 000' never breaks across lines
SMALLEST_PLAIN = 1e-3  # below it, '0.000000307' is harder to read than '3.07 x 10⁻⁷'
TIMES = "\u00d7"  # the multiplication sign
_SUPERSCRIPT = str.maketrans("-0123456789", "⁻⁰¹²³⁴⁵⁶⁷⁸⁹")


def grouped(value: float, decimals: int) -> str:
    """`value` with `decimals` fixed decimals and its thousands grouped: '9 667', '0.0150'."""
    text = f"{value:,.{decimals}f}".replace(",", GROUP)
    return "0" if decimals == 0 and text == "-0" else text


def decimals_for(value: float, digits: int) -> int:
    """The decimals that show `value` to `digits` significant digits (none for integers
    beyond them: 9667 stays 9667)."""
    if value == 0 or not math.isfinite(value):
        return 0
    return max(0, digits - 1 - math.floor(math.log10(abs(value))))


def _power(value: float) -> int:
    """The power of ten a mean is written on: 0 (plain) unless it is a small nonzero one."""
    if value == 0 or not math.isfinite(value) or abs(value) >= SMALLEST_PLAIN:
        return 0
    return math.floor(math.log10(abs(value)))


def metric_parts(mean: float, low: float, high: float, digits: int = 3) -> tuple[str, str]:
    """The mean over seeds and its interval as two texts, ('0.0150', '[0.0141, 0.0162]');
    the interval is '' with one seed (NaN bounds) or when every seed gave the mean; the
    mean is '-' when missing."""
    if np.isnan(mean):
        return "-", ""
    power = _power(mean)
    scale = 10.0**power
    decimals = decimals_for(mean / scale, digits)

    def written(value: float) -> str:
        text = grouped(value / scale, decimals)
        return f"{text} {TIMES} 10{str(power).translate(_SUPERSCRIPT)}" if power else text

    shown = written(mean)
    if np.isnan(low) or low == high == mean:  # one seed, or every seed gave the mean
        return shown, ""
    return shown, f"[{written(low)}, {written(high)}]"


def metric_cell(mean: float, low: float, high: float, digits: int = 3) -> str:
    """'0.0150 [0.0141, 0.0162]': the mean over seeds and its 95 % interval (`metric_parts`)."""
    return " ".join(part for part in metric_parts(mean, low, high, digits) if part)


def cell_of(row: pd.Series, metric: str, digits: int = 3) -> str:
    """A metric of an aggregate row as `metric_cell` writes it."""
    return metric_cell(
        row[f"{metric}_mean"], row[f"{metric}_ci_low"], row[f"{metric}_ci_high"], digits
    )


def number(value: float, digits: int = 3) -> str:
    """One value as the boards write a mean: integers whole and grouped ('12 346'), floats
    to `digits` significant digits, a power of ten below 0.001."""
    if isinstance(value, int):
        return grouped(value, 0)
    return metric_parts(value, np.nan, np.nan, digits)[0]


def count(number: int, noun: str, plural: str | None = None) -> str:
    """'1 dataset', '3 datasets', '10 000 steps': a count with its noun in the right number."""
    word = noun if number == 1 else (plural or f"{noun}s")
    return f"{grouped(number, 0)} {word}"
