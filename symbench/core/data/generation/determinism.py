"""Bit-for-bit identical simulation on every x86-64 CPU: the generator's numerics are pinned.

Why: the same scenario gave different trajectories on an Intel Xeon (AVX-512) and an AMD
EPYC (AVX2), because several libraries on the simulation path pick their kernels by CPU at
run time, and each kernel rounds differently in the last bit:
- numpy's bundled OpenBLAS (every `@` product: rotations, Jacobians, the controller's mass
  matrix products): FMA kernels on Haswell/Zen, AVX-512 kernels on SkylakeX, no FMA on
  Sandybridge. Measured on one AMD machine, kernel alone changed: the first differences are
  the joint torques and accelerations of the controller's first QP at t = 0 (~1e-13 N m).
- numpy's own ufunc loops (`arccos`, `arctan2`, `sin`, `cos` in the kinematics), which
  switch to AVX-512 (SVML) code on CPUs that have it;
- glibc's libm (used by MuJoCo, `math` and numpy's scalar paths), whose `sin`, `cos`, `exp`,
  `atan2`, `pow` ... have separate FMA and SSE2 builds chosen per CPU (measured: all of them
  round differently between the two);
- numba, which compiles the climbing loop for the host CPU (its features decide which
  instructions LLVM may use);
- pyarrow (Parquet writing), which dispatches SIMD code by CPU.
The controller's feedback then grows last-bit differences into different files.

The fix: dataset trajectories are simulated only in worker processes started with the
environment below, which fixes every one of these to a kernel that every x86-64 CPU able to
run this numpy (its baseline is x86-64-v2) executes identically; numba compiles for the
generic x86-64 CPU, and its code is IEEE arithmetic without fast-math (no reassociation, no
FMA contraction). `require_pinned_numerics` checks, inside the worker, that each pin took
effect, and generation refuses to simulate a standard dataset otherwise.
Limits: identity holds for the same library versions (recorded in the dataset metadata and
its hash) and the same glibc (its libm implementation differs between releases).
MuJoCo and DAQP (the controller's QP solver) have no CPU dispatch.
"""

from __future__ import annotations

import os
from collections.abc import Iterator
from contextlib import contextmanager

from symbench.core.common.errors import SymbenchError

OPENBLAS_CORE = "Nehalem"  # SSE4.2, no FMA: part of numpy's x86-64-v2 baseline
GLIBC_HWCAPS = "glibc.cpu.hwcaps=-AVX,-AVX2,-FMA,-FMA4,-AVX512F"  # libm's SSE2 builds
NUMBA_CPU = "generic"  # numba's code for the baseline x86-64 CPU, whatever the host


def _numpy_dispatch_targets() -> list[str]:
    """numpy's optional CPU targets (beyond its baseline), as named by this numpy."""
    from numpy._core._multiarray_umath import __cpu_dispatch__

    return list(__cpu_dispatch__)


def pinned_environment() -> dict[str, str]:
    """The environment variables a worker needs before it loads any numerical library."""
    return {
        "OPENBLAS_CORETYPE": OPENBLAS_CORE,
        "OPENBLAS_NUM_THREADS": "1",
        "OPENBLAS_L2_SIZE": "262144",
        "OMP_NUM_THREADS": "1",
        "NPY_DISABLE_CPU_FEATURES": " ".join(_numpy_dispatch_targets()),
        "GLIBC_TUNABLES": GLIBC_HWCAPS,
        "ARROW_USER_SIMD_LEVEL": "NONE",
        "NUMBA_CPU_NAME": NUMBA_CPU,
    }


@contextmanager
def pinned_worker_environment() -> Iterator[None]:
    """Processes started inside this block inherit the pinned environment; restored after."""
    pins = pinned_environment()
    saved = {name: os.environ.get(name) for name in pins}
    os.environ.update(pins)
    try:
        yield
    finally:
        for name, value in saved.items():
            if value is None:
                os.environ.pop(name, None)
            else:
                os.environ[name] = value


def numerics_problems() -> list[str]:
    """What in this process is not pinned (empty when simulating here is reproducible)."""
    from numpy._core._multiarray_umath import __cpu_features__
    from threadpoolctl import threadpool_info

    problems = [
        f"numpy dispatches {f} loops" for f in _numpy_dispatch_targets() if __cpu_features__.get(f)
    ]
    for lib in threadpool_info():
        if lib.get("internal_api") != "openblas":
            continue
        core = str(lib.get("architecture", ""))
        if core.lower() != OPENBLAS_CORE.lower():
            problems.append(
                f"OpenBLAS {lib['filepath']} runs {core or 'unknown'} kernels, not {OPENBLAS_CORE}"
            )
        if lib.get("num_threads") != 1:
            problems.append(f"OpenBLAS {lib['filepath']} uses {lib.get('num_threads')} threads")
    pins = pinned_environment()
    for name in ("GLIBC_TUNABLES", "ARROW_USER_SIMD_LEVEL", "OPENBLAS_L2_SIZE"):
        if os.environ.get(name) != pins[name]:
            problems.append(f"{name} is {os.environ.get(name)!r} (set before the process started)")
    from numba import config

    cpu = getattr(config, "CPU_NAME", None)
    if cpu != NUMBA_CPU:
        problems.append(f"numba compiles for {cpu or 'the host CPU'!r}, not {NUMBA_CPU}")
    return problems


def require_pinned_numerics() -> None:
    """Refuse to simulate a standard dataset with CPU-dependent kernels."""
    problems = numerics_problems()
    if problems:
        raise SymbenchError(
            "refusing to generate data with CPU-dependent numerics ("
            + "; ".join(problems)
            + "): standard datasets are simulated in "
            "worker processes that symbench.core.data.generation.generate starts pinned"
        )
