"""C functions that compiled code calls directly: MuJoCo's step and mass matrix, DAQP's QP.

The climbing loop runs compiled (`climb_kernel`), so the library calls inside it must be C
calls, not Python ones. The symbols come from the libraries that the `mujoco` and `daqp`
wheels ship (libmujoco exports its API; DAQP's extension module exports its C API) and are
registered with LLVM by name at import, before any compiled function that calls them is
loaded, so cached machine code resolves them in every process. Pointers travel as integers
(`MjModel._address`, `MjData._address`, `ctypes.addressof`).
"""

from __future__ import annotations

import ctypes
from pathlib import Path

from llvmlite import binding
from numba import types

from symbench.core.common.errors import SymbenchError


def _mujoco_library() -> ctypes.CDLL:
    import mujoco

    found = sorted(Path(mujoco.__file__).parent.glob("libmujoco.so*"))
    if not found:
        raise SymbenchError(f"no libmujoco shared library next to {mujoco.__file__}")
    return ctypes.CDLL(str(found[0]))


def _daqp_library() -> ctypes.CDLL:
    import daqp

    return ctypes.CDLL(daqp.__file__)


def _register(library: ctypes.CDLL, name: str) -> None:
    binding.add_symbol(name, ctypes.cast(getattr(library, name), ctypes.c_void_p).value)


MUJOCO = _mujoco_library()
DAQP = _daqp_library()
for _name in ("mj_step1", "mj_step2", "mj_fullM"):
    _register(MUJOCO, _name)
_register(DAQP, "daqp_quadprog")

_pointer = types.uintp
mj_step1 = types.ExternalFunction("mj_step1", types.void(_pointer, _pointer))
mj_step2 = types.ExternalFunction("mj_step2", types.void(_pointer, _pointer))
mj_full_m = types.ExternalFunction("mj_fullM", types.void(_pointer, _pointer, types.voidptr))
daqp_quadprog = types.ExternalFunction("daqp_quadprog", types.void(_pointer, _pointer, _pointer))
