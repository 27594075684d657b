"""An imported npz log's arrays, each header checked against the bytes its file holds before
the array is read: numpy allocates what a header claims before reading a byte, so a header
claiming 10^12 rows would end in a MemoryError (or the kernel's out-of-memory killer)
instead of a message naming the file."""

from __future__ import annotations

import math
import zipfile
import zlib
from pathlib import Path

import numpy as np

from symbench.core.common.errors import SymbenchError
from symbench.core.common.jsonfile import one_line

HEADERS = {  # what numpy writes for columns of plain numbers; 3.0 only for non-latin-1 fields
    (1, 0): np.lib.format.read_array_header_1_0,
    (2, 0): np.lib.format.read_array_header_2_0,
}
# DEFLATE expands at most about 1032-fold: an entry claiming more than this many times its
# compressed bytes cannot hold them
DEFLATE_RATIO = 1100


def read_npz(path: Path) -> dict[str, np.ndarray]:
    """Every array of npz file `path`, none of them pickled; a file that is not such an npz,
    or whose array headers claim more than it holds, is a one-line error naming it."""
    try:
        with zipfile.ZipFile(path) as archive:
            for info in archive.infolist():
                _check_claim(archive, info, path)
        with np.load(path, allow_pickle=False) as npz:
            return {k: npz[k] for k in npz.files}
    except (OSError, ValueError, EOFError, zipfile.BadZipFile, zlib.error) as exc:
        raise SymbenchError(
            f"{path}: not a readable npz file without pickles "
            f"({one_line(exc) or type(exc).__name__})"
        ) from None


def _check_claim(archive: zipfile.ZipFile, info: zipfile.ZipInfo, path: Path) -> None:
    """Refuses an array whose header claims more bytes than its zip entry holds."""
    if not info.filename.endswith(".npy"):
        return  # np.load reads only .npy entries as arrays
    with archive.open(info) as member:
        version = np.lib.format.read_magic(member)
        if version not in HEADERS:
            raise ValueError(f"'{info.filename}' is in npy format {version}, not 1.0 or 2.0")
        shape, _, dtype = HEADERS[version](member)
        header = member.tell()
    holds = info.file_size - header
    if info.compress_type != zipfile.ZIP_STORED:
        holds = min(holds, info.compress_size * DEFLATE_RATIO)
    claimed = math.prod(shape) * dtype.itemsize
    if claimed > holds:
        name = info.filename.removesuffix(".npy")
        raise SymbenchError(
            f"{path}: column '{name}' claims shape {shape} ({claimed} bytes), but the file "
            f"holds {max(holds, 0)} bytes for it: a damaged or crafted header"
        )
