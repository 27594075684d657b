"""Callables named by 'module:attribute', imported on first call.

A model entry points at its network builder this way, so that listing models (`symbench
list models`) never imports torch or JAX.
"""

from __future__ import annotations

import importlib
from dataclasses import dataclass
from typing import Any

from symbench.core.common.errors import SymbenchError


@dataclass(frozen=True)
class Lazy:
    target: str  # "package.module:attribute"

    def __post_init__(self) -> None:
        if self.target.count(":") != 1:
            raise SymbenchError(f"lazy target '{self.target}' must read 'module:attribute'")

    def resolve(self) -> Any:
        module, attr = self.target.split(":")
        return getattr(importlib.import_module(module), attr)

    def __call__(self, *args: Any, **kwargs: Any) -> Any:
        return self.resolve()(*args, **kwargs)
