"""symbench: a benchmark for learned dynamics of symmetric legged robots."""

from importlib.metadata import PackageNotFoundError, version

try:
    __version__ = version("symbench")
except PackageNotFoundError:  # running from a source tree that was never installed
    __version__ = "0.0.0+unknown"

from symbench.core.training_kernels import pin_training_kernels  # noqa: E402

pin_training_kernels()  # before torch, MKL or XLA load: same training numbers on every CPU

from symbench.core.hookspecs import hookimpl  # noqa: E402  (the marker plugin authors use)

__all__ = ["__version__", "hookimpl"]
