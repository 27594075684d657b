"""symbench's public API. Its names, grouped by role, are declared once, in `__init__.pyi`:
this docstring, `__all__` and what loads on first use are read from there (see
`symbench.core.common.lazy_names`)."""

from __future__ import annotations

from pathlib import Path
from typing import Any

from symbench.core.common.lazy_names import LazyNames
from symbench.core.common.version import __version__ as __version__
from symbench.core.training.kernels import pin_training_kernels

pin_training_kernels()  # before torch, MKL or XLA load: same training numbers on every CPU

# the marker plugin authors use
from symbench.core.plugin.hookspecs import hookimpl as hookimpl  # noqa: E402

_NAMES = LazyNames.from_stub(__name__, Path(__file__).with_suffix(".pyi"))
__doc__ = _NAMES.docstring()
__all__ = _NAMES.all


def __getattr__(name: str) -> Any:
    """Load a public name on first use (PEP 562) and keep it."""
    value = _NAMES.load(name)
    globals()[name] = value
    return value


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(__all__))
