"""Atomic, pickle-free checkpoint files: safetensors for arrays, JSON for everything else."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import numpy as np
from safetensors import SafetensorError, safe_open
from safetensors.numpy import save

from symbench.core.atomic import write_bytes_atomic
from symbench.core.errors import SymbenchError

METADATA_KEY = "symbench"


def write_tensors(path: Path, arrays: dict[str, np.ndarray], metadata: Any = None) -> None:
    """Arrays as safetensors; `metadata` (JSON-ready) rides in the same file, so both are
    replaced by one atomic rename."""
    meta = {METADATA_KEY: json.dumps(metadata)} if metadata is not None else None
    write_bytes_atomic(Path(path), save({k: np.ascontiguousarray(v) for k, v in arrays.items()}, meta))


def read_tensors(path: Path) -> tuple[dict[str, np.ndarray], Any]:
    """The arrays and the JSON metadata (None when the file carries none)."""
    try:
        with safe_open(Path(path), framework="np") as f:
            arrays = {k: f.get_tensor(k) for k in f.keys()}
            meta = (f.metadata() or {}).get(METADATA_KEY)
        return arrays, json.loads(meta) if meta is not None else None
    except FileNotFoundError:
        raise SymbenchError(f"checkpoint file {path} does not exist") from None
    except (SafetensorError, ValueError, OSError) as exc:
        raise SymbenchError(f"{path} is not a readable safetensors file ({exc})") from None


def write_json(path: Path, obj: Any) -> None:
    write_bytes_atomic(Path(path), (json.dumps(obj, indent=2, sort_keys=True) + "\n").encode())


def read_json(path: Path) -> Any:
    try:
        return json.loads(Path(path).read_text())
    except FileNotFoundError:
        raise SymbenchError(f"checkpoint file {path} does not exist") from None
    except json.JSONDecodeError as exc:
        raise SymbenchError(f"{path} is not valid JSON ({exc})") from None
