"""npz files whose array headers lie: numpy allocates what a header claims before reading a
byte, so a header claiming more rows than its file holds is how a crafted or damaged file
asks for terabytes."""

from __future__ import annotations

import io
import zipfile
from pathlib import Path

import numpy as np


def claim_rows(path: Path, column: str, rows: int, suffix: str = ".npy") -> None:
    """Rewrites npz `path` so that `column`'s header claims `rows` rows (its other axes and
    its data as they were), in an entry named `column + suffix` (np.load reads an entry of
    any name as an array when it holds one); every other array is left as it was."""
    with np.load(path) as npz:
        arrays = {k: npz[k] for k in npz.files}
    with zipfile.ZipFile(path, "w") as archive:
        for name, array in arrays.items():
            buffer = io.BytesIO()
            if name == column:
                header = {"descr": array.dtype.str, "fortran_order": False}
                np.lib.format.write_array_header_1_0(
                    buffer, {**header, "shape": (rows, *array.shape[1:])}
                )
                buffer.write(array.tobytes())
            else:
                np.lib.format.write_array(buffer, array)
            archive.writestr(name + (suffix if name == column else ".npy"), buffer.getvalue())


def npz_bytes(members: dict[str, bytes], compression: int = zipfile.ZIP_STORED) -> bytes:
    """A zip of `members` (entry name: bytes), every checksum right: whatever a member holds
    reaches numpy's parser, not zipfile's CRC check."""
    buffer = io.BytesIO()
    with zipfile.ZipFile(buffer, "w", compression=compression) as archive:
        for name, content in members.items():
            archive.writestr(name, content)
    return buffer.getvalue()


def npy_members(arrays: dict[str, np.ndarray]) -> dict[str, bytes]:
    """The entries np.savez writes for `arrays`: NAME.npy, each an .npy file."""
    out = {}
    for name, array in arrays.items():
        buffer = io.BytesIO()
        np.lib.format.write_array(buffer, array, allow_pickle=False)
        out[f"{name}.npy"] = buffer.getvalue()
    return out
