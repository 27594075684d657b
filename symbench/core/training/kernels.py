"""Training gives the same numbers on every x86-64 CPU with AVX2: torch and XLA are held to
their AVX2 kernels.

Why: like the simulator's libraries (see `symbench.core.data.generation.determinism`), torch picks
its kernels by CPU at run time: ATen's vectorized loops (AVX2 or AVX-512), MKL's matrix products and
oneDNN; XLA compiles for the host's widest instructions. Each rounds float32 differently,
and sixty epochs of Adam grow a last-bit difference into different metrics (measured: the
same smoke record retrained with ATen's default kernels instead of its AVX2 ones changed 11
of its 14 metric values), so `symbench verify` on another CPU would disagree with an honest
record. Capping every library at AVX2 (which every x86-64 CPU made since 2015 has) costs
nothing on AVX2 machines and lets an AVX-512 machine compute what they compute. Measured
here (AMD EPYC, AVX2): the pins change no bit of training, so records made before them stay
verifiable.

The pins are environment variables read when torch, MKL and XLA load, so they are set when
symbench is imported, before any of those; a process that imported torch first keeps its
own kernels, and `training_kernel_problems` says so. One torch thread (the default, see
the torch backend) keeps reductions in one order.
"""

from __future__ import annotations

import os
import sys

TORCH_PINS = {
    "ATEN_CPU_CAPABILITY": "avx2",
    "MKL_CBWR": "AVX2,STRICT",
    "ONEDNN_MAX_CPU_ISA": "AVX2",
}
XLA_PIN = "--xla_cpu_max_isa=AVX2"


def _cpu_has_avx2() -> bool:
    """AVX2 and FMA, read from the kernel's CPU flags (x86-64 Linux); False elsewhere."""
    try:
        with open("/proc/cpuinfo") as info:
            flags = next((line for line in info if line.startswith("flags")), "").split()
    except OSError:
        return False
    return "avx2" in flags and "fma" in flags


def pin_training_kernels() -> None:
    """Set the pins for libraries not loaded yet (never on a CPU without AVX2: an AVX2 cap
    there would select instructions it cannot run)."""
    if not _cpu_has_avx2():
        return
    if "torch" not in sys.modules:
        os.environ.update(TORCH_PINS)
    if "jax" not in sys.modules and XLA_PIN not in os.environ.get("XLA_FLAGS", ""):
        os.environ["XLA_FLAGS"] = f"{os.environ.get('XLA_FLAGS', '')} {XLA_PIN}".strip()


def training_kernel_problems() -> list[str]:
    """Why training here may not reproduce a record made on another CPU (empty: it should)."""
    if not _cpu_has_avx2():
        return ["this CPU has no AVX2, so torch runs other kernels than the reference"]
    problems = [
        f"{name} is {os.environ.get(name)!r}, not {value!r}"
        for name, value in TORCH_PINS.items()
        if os.environ.get(name) != value
    ]
    if "torch" in sys.modules:
        import torch

        capability = torch.backends.cpu.get_cpu_capability()
        if capability != "AVX2":
            problems.append(
                f"torch runs its {capability} kernels (torch was imported before symbench)"
            )
        if torch.get_num_threads() != 1:
            problems.append(f"torch uses {torch.get_num_threads()} threads")
    return problems
