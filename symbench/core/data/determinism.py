"""Bit-for-bit reproducible simulation: pin proxsuite to its portable (non-SIMD) build.

proxsuite's AVX2 and AVX-512 builds return solutions whose last bits vary from call to call
for identical inputs (measured: two distinct results over 60 solves of one dense QP), and the
controller's feedback lets such differences grow, so one scenario gave different files in
different processes. The portable build gives one result and is as fast for the controller's
small QPs (hexa, 4 x 1 s: 2.01 s against 1.97 s). proxsuite picks its build when first
imported (the controller imports it lazily), so the pin must come before that.
"""

from __future__ import annotations

import sys
import types

PORTABLE = "proxsuite.proxsuite_pywrap"


def pin_portable_qp_build() -> None:
    """Make the next `import proxsuite` load the portable build (no-op once imported)."""
    if "proxsuite" in sys.modules:
        return
    stub = types.ModuleType("proxsuite.instructionset")
    stub.has_AVX512F = stub.has_AVX2 = lambda: False
    sys.modules["proxsuite.instructionset"] = stub


def portable_qp_in_process() -> bool:
    """Whether simulating in this process is reproducible (proxsuite portable or not loaded)."""
    loaded = sys.modules.get("proxsuite")
    if loaded is None:
        return True
    sub = getattr(loaded, "_submodule", None)
    return getattr(sub, "__name__", "") == PORTABLE
