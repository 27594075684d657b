"""Training gives the same numbers on every CPU of one *kernel class*: torch and XLA are held
to their AVX2 kernels where they can be, and a record names the class it was trained in.

Why: like the simulator's libraries (see `symbench.core.data.generation.determinism`), torch picks
its kernels by CPU at run time: ATen's vectorized loops (AVX2 or AVX-512), MKL's matrix products and
oneDNN; XLA compiles for the host's widest instructions. Each rounds float32 differently,
and sixty epochs of Adam grow a last-bit difference into different metrics (measured: the
same smoke record retrained with ATen's default kernels instead of its AVX2 ones changed 11
of its 14 metric values), so `symbench verify` on another CPU would disagree with an honest
record. The pins below cap every library at AVX2 where the library lets them:

- torch: ATen's loops and oneDNN obey their caps on every x86-64 CPU. MKL's matrix products
  obey `MKL_CBWR=AVX2` on Intel CPUs only: MKL's reproducibility branches other than AUTO and
  COMPATIBLE exist for Intel processors, and elsewhere MKL silently runs its AUTO branch
  (Intel's oneMKL developer guide, "Getting started with conditional numerical
  reproducibility"). The COMPATIBLE branch, the one that is the same on Intel and AMD, runs
  SSE2 kernels: 33 against 87 GFLOP/s on one core here, too slow to train a board with. So
  torch training reproduces bit for bit across Intel CPUs with AVX2, and across CPUs that
  run the same MKL AUTO branch, not between the two: a v6 record made on an AMD EPYC
  retrained on an Intel Xeon gave fraction-0.1 ffnn RMSE 0.6191 against 0.6122 recorded.
- JAX: `--xla_cpu_max_isa=AVX2` caps the code XLA compiles, but not its matrix-product
  library, which runs the host's widest vector unit (measured: 165 GFLOP/s on one AVX-512
  core with the cap, above AVX2's peak). JAX training reproduces across CPUs with the same
  vector width. XLA also compiles a step by the size of its CPU thread pool, which it takes
  from `NPROC` or else from the cores the process may use: with one thread it splits no
  loop across threads and fuses differently, and hexa's sdnn and gnn trained to other
  numbers on one core than on two (2, 3, 4 and 16 threads: the same as 2). `NPROC` is pinned
  at 2 (XLA_POOL), what the board's JAX records were trained with on 2-core machines.

`training_kernels` names the class of this process for a backend; the runner stores it in the
record's `hardware`, and `verify` warns when a record was trained in another class, where
only a tolerance can be asked for.

The pins are environment variables read when torch, MKL and XLA load, so they are set when
symbench is imported, before any of those; a process that imported torch first keeps its
own kernels, and `training_kernel_problems` says so. One torch thread (the default, see
the torch backend) keeps reductions in one order.
"""

from __future__ import annotations

import os
import sys
from pathlib import Path

TORCH_PINS = {
    "ATEN_CPU_CAPABILITY": "avx2",
    "MKL_CBWR": "AVX2,STRICT",
    "ONEDNN_MAX_CPU_ISA": "AVX2",
}
XLA_PIN = "--xla_cpu_max_isa=AVX2"
XLA_POOL = {"NPROC": "2"}  # the threads of XLA's CPU pool, which shape its compiled steps
ENV_PINS = {**TORCH_PINS, **XLA_POOL}  # every pin set through an environment variable


# MKL's reproducibility branches (mkl_cbwr.h), as `mkl_serv_cbwr_get` reports them
MKL_BRANCHES = {
    2: "auto",
    3: "compatible",
    4: "sse2",
    6: "ssse3",
    7: "sse4_1",
    8: "sse4_2",
    9: "avx",
    10: "avx2",
    12: "avx512",
    14: "avx512_e1",
}
MKL_STRICT = 0x10000


def _cpu_field(name: str) -> str:
    """A field of the first CPU in /proc/cpuinfo (x86-64 Linux); empty elsewhere."""
    try:
        lines = Path("/proc/cpuinfo").read_text().splitlines()
    except OSError:
        return ""
    found = (line.split(":", 1)[1] for line in lines if line.split(":", 1)[0].strip() == name)
    return next(found, "").strip()


def _cpu_flags() -> list[str]:
    return _cpu_field("flags").split()


def _cpu_has_avx2() -> bool:
    """AVX2 and FMA."""
    flags = _cpu_flags()
    return "avx2" in flags and "fma" in flags


def _mkl_branch() -> str:
    """The branch torch's MKL runs, e.g. "avx2 strict", or "auto (avx512_e1)" where MKL
    ignored the pin; "unknown" when torch's library does not expose MKL's query."""
    import ctypes

    import torch

    lib = Path(torch.__file__).parent / "lib" / "libtorch_cpu.so"
    try:
        mkl = ctypes.CDLL(str(lib))
        get, auto = mkl.mkl_serv_cbwr_get, mkl.mkl_serv_cbwr_get_auto_branch
    except (OSError, AttributeError):
        return "unknown"
    get.restype, get.argtypes, auto.restype = ctypes.c_int, [ctypes.c_int], ctypes.c_int
    mode = get(-1)  # MKL_CBWR_ALL: the branch and the strict flag
    name = MKL_BRANCHES.get(mode & 0xFFFF, str(mode & 0xFFFF))
    if name == "auto":
        name = f"auto ({MKL_BRANCHES.get(auto(), str(auto()))})"
    return f"{name} strict" if mode & MKL_STRICT else name


def training_kernels(backend: str) -> str:
    """The kernel class a training in `backend` runs in on this machine: two trainings
    reproduce each other bit for bit only within one class (see the module's docstring)."""
    vendor = _cpu_field("vendor_id") or "unknown vendor"
    if backend == "torch":
        import torch

        return (
            f"torch {torch.__version__}: aten {torch.backends.cpu.get_cpu_capability().lower()}, "
            f"mkl {_mkl_branch()}, {torch.get_num_threads()} thread(s); {vendor}"
        )
    import jax

    width = "avx512" if "avx512f" in _cpu_flags() else "avx2" if _cpu_has_avx2() else "sse"
    return f"jax {jax.__version__}: xla matrix products {width}; {vendor}"


def pin_training_kernels() -> None:
    """Set the pins for libraries not loaded yet (the instruction caps never on a CPU without
    AVX2: an AVX2 cap there would select instructions it cannot run)."""
    if "jax" not in sys.modules:
        os.environ.update(XLA_POOL)
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
        for name, value in ENV_PINS.items()
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
