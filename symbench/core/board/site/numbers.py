"""How the entry pages write a number: 3 significant digits in fixed notation ('0.0996',
'2.00'), a larger number's integer part whole ('12346', never '1.23e+04'), and a power of
ten only below 10⁻⁴, where fixed notation would be a row of zeros; and counts with their
noun's proper plural."""

from __future__ import annotations

import math

SIGNIFICANT = 3
SMALLEST_FIXED = -4  # the lowest power of ten written in fixed notation
_SUPERSCRIPT = str.maketrans("-0123456789", "⁻⁰¹²³⁴⁵⁶⁷⁸⁹")
TIMES = "\N{MULTIPLICATION SIGN}"  # between the digits and the power of ten


def number(value: float) -> str:
    """`value` for a reader: integers whole, floats to SIGNIFICANT digits or to the unit."""
    if isinstance(value, int) or not math.isfinite(value):
        return str(value)
    rounded = float(f"{value:.{SIGNIFICANT}g}")  # 0.09996 -> 0.1: its digits, not 0.09996's
    if rounded == 0:
        return "0"
    exponent = math.floor(math.log10(abs(rounded)))
    if exponent < SMALLEST_FIXED:
        mantissa = rounded / 10.0**exponent
        return f"{mantissa:.{SIGNIFICANT - 1}f} {TIMES} 10{str(exponent).translate(_SUPERSCRIPT)}"
    decimals = SIGNIFICANT - 1 - exponent
    return f"{rounded:.{decimals}f}" if decimals > 0 else f"{value:.0f}"


def count(n: int, noun: str, plural: str | None = None) -> str:
    """'1 seed', '3 seeds', '2 entries' (give `plural` where adding 's' is wrong)."""
    return f"{n} {noun if n == 1 else plural or noun + 's'}"
