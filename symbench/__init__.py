"""symbench: a benchmark for learned dynamics of symmetric legged robots."""

from importlib.metadata import PackageNotFoundError, version

try:
    __version__ = version("symbench")
except PackageNotFoundError:  # running from a source tree that was never installed
    __version__ = "0.0.0+unknown"

from symbench.core.hookspecs import hookimpl  # noqa: E402  (the marker plugin authors use)

__all__ = ["__version__", "hookimpl"]
