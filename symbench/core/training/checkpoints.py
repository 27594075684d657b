"""Atomic, pickle-free, self-verifying checkpoint files: safetensors for arrays, JSON for
everything else.

Every checkpoint carries the SHA-256 of its own content in its safetensors metadata (key
`sha256`): over the header without that key (tensor names, dtypes, shapes, offsets, the
JSON metadata; canonical JSON) and the tensor bytes, i.e. over every byte that means
something. The hash lives inside the file rather than in a sidecar manifest because then one
atomic rename replaces content and hash together: a crash can never leave a new file with an
old manifest (a false alarm) or the other way round, and a checkpoint copied anywhere
carries its own proof. A flipped bit or a truncated file no longer matches its hash and is
refused with `CheckpointError`; `checkpoint_sha256` gives the verified hash for provenance.
"""

from __future__ import annotations

import hashlib
import json
from pathlib import Path
from typing import Any

import numpy as np
from safetensors import SafetensorError
from safetensors.numpy import load, save

from symbench.core.common.atomic import write_bytes_atomic
from symbench.core.common.errors import SymbenchError
from symbench.core.common.jsonfile import loads, one_line

METADATA_KEY = "symbench"
HASH_KEY = "sha256"
_META = "__metadata__"  # where safetensors keeps string metadata in its header


class CheckpointError(SymbenchError):
    """A checkpoint file that is missing, unreadable or does not match its content hash."""


def encode(arrays: dict[str, np.ndarray], metadata: Any) -> tuple[bytes, str]:
    """The checkpoint file's bytes, with its content hash inside, and that hash."""
    raw = save(
        {k: np.ascontiguousarray(v) for k, v in arrays.items()},
        {METADATA_KEY: json.dumps(metadata)},
    )
    header, data = _split(raw)
    digest = _digest(header, data)
    header[_META][HASH_KEY] = digest
    text = json.dumps(header, separators=(",", ":")).encode()
    text += b" " * (-len(text) % 8)  # safetensors aligns the data to 8 bytes
    return len(text).to_bytes(8, "little") + text + data, digest


def write_tensors(path: Path, arrays: dict[str, np.ndarray], metadata: Any = None) -> None:
    """Arrays as safetensors; `metadata` (JSON-ready) and the content hash ride in the same
    file, so all are replaced by one atomic rename."""
    write_bytes_atomic(Path(path), encode(arrays, metadata)[0])


def read_tensors(path: Path) -> tuple[dict[str, np.ndarray], Any]:
    """The arrays and the JSON metadata, once the content hash is checked."""
    raw, header, _ = _open(Path(path))
    try:
        return load(raw), loads(header[_META][METADATA_KEY])
    except (
        SafetensorError,
        KeyError,
        TypeError,
        ValueError,
    ) as exc:  # only a forged hash gets here
        raise CheckpointError(f"checkpoint {path} is malformed ({one_line(exc)})") from None


def checkpoint_sha256(path: Path) -> str:
    """The content hash a checkpoint file carries, checked against its content (for records'
    provenance: the same parameters and description give the same hash, as long as
    safetensors lays the file out alike)."""
    return _open(Path(path))[2]


def write_json(path: Path, obj: Any) -> None:
    write_bytes_atomic(Path(path), (json.dumps(obj, indent=2, sort_keys=True) + "\n").encode())


def _open(path: Path) -> tuple[bytes, dict[str, Any], str]:
    """The file's bytes, its header (hash removed) and its hash, once they agree."""
    try:
        raw = path.read_bytes()
        header, data = _split(raw)
        stored = header[_META].pop(HASH_KEY)
    except FileNotFoundError:
        raise CheckpointError(f"checkpoint {path} does not exist") from None
    except OSError as exc:
        raise CheckpointError(f"checkpoint {path} cannot be read ({one_line(exc)})") from None
    except ValueError as exc:
        raise CheckpointError(
            f"checkpoint {path} is not a readable safetensors file ({one_line(exc)})"
        ) from None
    except (KeyError, TypeError, AttributeError):
        raise CheckpointError(
            f"checkpoint {path} carries no content hash (damaged, or "
            "written before checkpoints were hashed)"
        ) from None
    if _digest(header, data) != stored:
        raise CheckpointError(f"checkpoint {path} is {_damage(header, data)}")
    return raw, header, stored


def _split(raw: bytes) -> tuple[dict[str, Any], bytes]:
    """A safetensors file's header (parsed) and data section."""
    size = int.from_bytes(raw[:8], "little")
    if len(raw) < 8 + size:
        raise ValueError("the file is shorter than its header")
    header = loads(raw[8 : 8 + size])
    if not isinstance(header, dict):
        raise ValueError("its header is not a JSON object")
    return header, raw[8 + size :]


def _digest(header: dict[str, Any], data: bytes) -> str:
    digest = hashlib.sha256(json.dumps(header, sort_keys=True, separators=(",", ":")).encode())
    digest.update(data)
    return digest.hexdigest()


def _damage(header: dict[str, Any], data: bytes) -> str:
    """Why content and hash disagree: a data section shorter than the header says is a
    truncated file, anything else a damaged one."""
    try:
        size = max(t["data_offsets"][1] for k, t in header.items() if k != _META)
    except (KeyError, TypeError, IndexError, ValueError):  # a damaged header
        size = 0
    if len(data) < size:
        return f"truncated ({len(data)} of {size} data bytes)"
    return "damaged (its content does not match its SHA-256)"
