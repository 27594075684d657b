"""A dataset's metadata.json: provenance, per-file SHA-256 and the content hash.

The content hash is the SHA-256 of the canonical metadata without the hash itself (and, for
imported datasets, without the local folder, id and repair command: see LOCAL_FIELDS); the
metadata holds every file's SHA-256, so the hash covers the trajectories, the scenario grid,
the failures and the library versions. No timestamps are stored, which keeps the file (and
the hash) identical when the same preset is generated twice on the same versions.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

from pydantic import ValidationError

from symbench.core.common.errors import SymbenchError, first_of
from symbench.core.common.hashing import sha256_file
from symbench.core.common.jsonfile import read_json
from symbench.core.common.paths import datasets_dir
from symbench.core.common.validation import explain
from symbench.core.config.provenance import package_versions
from symbench.core.data.storage.files import (
    atomic_write_json,
    canonical_json,
    sha256_bytes,
    step_count,
)
from symbench.core.data.storage.metadata_schema import DatasetMetadata

FORMAT = "symbench-dataset"
FORMAT_VERSION = 1
METADATA = "metadata.json"
VERSIONED = ("symbench", "mujoco", "dm-control", "numpy", "pyarrow", "numba", "llvmlite", "daqp")


def library_versions() -> dict[str, str]:
    """The versions a dataset's bytes depend on (part of its content hash)."""
    return package_versions(VERSIONED)


def dataset_dir(dataset_id: str) -> Path:
    if not dataset_id or "/" in dataset_id or dataset_id.startswith("."):
        raise SymbenchError(f"'{dataset_id}' is not a valid dataset id")
    return datasets_dir() / dataset_id


# Where an imported dataset was imported from, and under which id: local facts, not content,
# so the same logs imported on two machines (or under two ids) get the same content hash.
LOCAL_FIELDS = ("id", "imported_from", "repair_command")


def content_hash(meta: dict[str, Any]) -> str:
    """SHA-256 of the canonical metadata without the hash itself; for an imported dataset,
    without its local fields too (generated datasets hash every field, as they always did)."""
    skip = {"content_hash"}
    if meta.get("source") == "imported":
        skip.update(LOCAL_FIELDS)
    body = {k: v for k, v in meta.items() if k not in skip}
    return sha256_bytes(canonical_json(body).encode())


def _legacy_hash(meta: dict[str, Any]) -> str:
    """The hash of datasets imported before LOCAL_FIELDS were left out (every field)."""
    body = {k: v for k, v in meta.items() if k != "content_hash"}
    return sha256_bytes(canonical_json(body).encode())


def write_metadata(root: Path, meta: dict[str, Any]) -> dict[str, Any]:
    """Add format fields and the content hash; write metadata.json atomically (last)."""
    meta = {"format": FORMAT, "format_version": FORMAT_VERSION, **meta}
    meta["content_hash"] = content_hash(meta)
    atomic_write_json(root / METADATA, meta)
    return meta


def read_metadata(dataset_id: str, missing_hint: str) -> tuple[Path, dict[str, Any]]:
    root = dataset_dir(dataset_id)
    if not (root / METADATA).is_file():
        raise SymbenchError(f"dataset '{dataset_id}' is not in the cache ({root}); {missing_hint}")
    meta = read_json(root / METADATA, f"dataset '{dataset_id}'")
    if not isinstance(meta, dict) or meta.get("format") != FORMAT:
        raise SymbenchError(f"{root / METADATA} is not a symbench dataset's metadata")
    if meta.get("format_version") != FORMAT_VERSION:
        raise SymbenchError(
            f"dataset '{dataset_id}' has format version {meta.get('format_version')},"
            f" this symbench reads {FORMAT_VERSION}; {_repair(meta)}"
        )
    if meta.get("content_hash") != content_hash(meta) and not (
        meta.get("source") == "imported" and meta.get("content_hash") == _legacy_hash(meta)
    ):
        raise SymbenchError(
            f"dataset '{dataset_id}': metadata.json was edited or damaged "
            f"(content hash mismatch); rebuild it with: {_repair(meta)}"
        )
    try:
        DatasetMetadata.model_validate(meta)
    except ValidationError as exc:
        raise explain(exc, f"dataset '{dataset_id}': {root / METADATA} is malformed") from None
    if meta["id"] != dataset_id:  # an imported dataset's id is not hashed: it must match
        raise SymbenchError(
            f"dataset '{dataset_id}': {root / METADATA} names dataset '{meta['id']}' (a "
            f"folder copied or renamed by hand); rebuild it with: {_repair(meta)}"
        )
    return root, meta


def _repair(meta: dict[str, Any]) -> str:
    """The dataset's own repair command, or a generic one where an edit left it blank."""
    command = meta.get("repair_command")
    if isinstance(command, str) and command.strip():
        return command
    return "delete the dataset's folder and generate or import it again"


def damaged_files(root: Path, meta: dict[str, Any]) -> list[str]:
    """Trajectory files that are missing or whose SHA-256 differs from the metadata."""
    bad = []
    for rec in meta["trajectories"]:
        path = root / rec["file"]
        if not path.is_file() or sha256_file(path) != rec["sha256"]:
            bad.append(rec["file"])
    return bad


def verify(root: Path, meta: dict[str, Any]) -> None:
    """Every file as the metadata describes it: its SHA-256, then its number of steps (which
    a re-hashed metadata.json could misstate while naming the right file)."""
    bad = damaged_files(root, meta)
    if bad:
        shown = first_of(bad, 3)
        raise SymbenchError(
            f"dataset '{meta['id']}': {shown} changed, truncated or missing "
            f"(SHA-256 mismatch); fix it with: {_repair(meta)}"
        )
    for rec in meta["trajectories"]:
        steps = step_count(root / rec["file"])
        if steps != rec["n_steps"]:
            raise SymbenchError(
                f"dataset '{meta['id']}': {rec['file']} holds {steps} steps, "
                f"metadata.json says {rec['n_steps']}; fix it with: "
                f"{_repair(meta)}"
            )
