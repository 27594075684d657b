"""The installed symbench version, readable from any layer without importing the package root
(which pins the training kernels)."""

from importlib.metadata import PackageNotFoundError, version

try:
    __version__ = version("symbench")
except PackageNotFoundError:  # running from a source tree that was never installed
    __version__ = "0.0.0+unknown"
