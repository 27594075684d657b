"""The published board's logarithms: numpy's values (within a last bit), numpy's answers at 0,
below 0 and at NaN, and the same bits in a process whose numpy cannot use AVX-512."""

from __future__ import annotations

import math
import os
import subprocess
import sys

import numpy as np
from cpu_features import WITHOUT_AVX512

from symbench.core.common import portable_math

VALUES = np.random.default_rng(0).uniform(1e-6, 1e3, 2000)
PRINT_BITS = (
    "import numpy as np; from symbench.core.common import portable_math as p; "
    "v = np.random.default_rng(0).uniform(1e-6, 1e3, 2000); "
    "print(p.log(v).tobytes().hex()); print([p.log10(float(x)).hex() for x in v[:200]])"
)


def test_the_logarithms_are_numpys_within_a_last_bit():
    assert np.allclose(portable_math.log(VALUES), np.log(VALUES), rtol=4e-16, atol=0)
    tens = np.array([portable_math.log10(float(v)) for v in VALUES])
    assert np.allclose(tens, np.log10(VALUES), rtol=4e-16, atol=4e-16)
    assert portable_math.log(np.ones((2, 3))).shape == (2, 3)


def test_zero_negative_and_nan_give_numpys_answers():
    logs = portable_math.log([0.0, -1.0, math.nan, math.inf])
    assert logs[0] == -math.inf and math.isnan(logs[1]) and math.isnan(logs[2])
    assert logs[3] == math.inf
    assert portable_math.log10(0.0) == -math.inf
    assert math.isnan(portable_math.log10(-2.0)) and math.isnan(portable_math.log10(math.nan))


def _bits(env: dict[str, str]) -> list[str]:
    done = subprocess.run(
        [sys.executable, "-c", PRINT_BITS], env=env, check=True, capture_output=True, text=True
    )
    return done.stdout.splitlines()


def test_the_same_bits_without_numpys_avx512_kernels():
    """On a CPU with AVX-512 numpy's own log gives other bits in the two processes (for these
    values on an Intel Xeon), the portable one must not; elsewhere both take one path."""
    here = _bits(dict(os.environ))
    without = _bits({**os.environ, **WITHOUT_AVX512})
    assert here == without
