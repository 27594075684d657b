"""An npz file's arrays (an imported log, the closed-loop calibration's cached references),
read entry by entry, each header checked against the bytes the file holds before the array
is read: numpy allocates what a header claims before reading a byte, so a header claiming
10^12 rows would end in a MemoryError (or the kernel's out-of-memory killer) instead of a
message naming the file. What a zip entry holds is bounded by its compressed bytes, never
by the sizes its directory states (those are written by whoever made the file), and
`np.load` is not used: it reads an entry without the `.npy` suffix as an array too when its
bytes begin like one, and any other entry whole, as bytes."""

from __future__ import annotations

import math
import tokenize
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
# what zipfile and numpy raise on a damaged file: a header of Python 2 syntax is tokenized
# (TokenError), a zip of another version is not implemented, and an array a header claims
# within the file's bounds may still not fit in memory
UNREADABLE = (
    OSError,
    ValueError,
    EOFError,
    SyntaxError,
    MemoryError,
    NotImplementedError,
    tokenize.TokenError,
    zipfile.BadZipFile,
    zlib.error,
)
# DEFLATE expands at most about 1032-fold: an entry claiming more than this many times its
# compressed bytes cannot hold them
DEFLATE_RATIO = 1100
EXPANDS = {zipfile.ZIP_STORED: 1, zipfile.ZIP_DEFLATED: DEFLATE_RATIO}  # np.savez's methods
# how an npz begins, as np.load tells one: a zip's first entry, or an empty zip's directory
# (zipfile alone also opens a zip behind bytes of anything else, which np.load refuses)
ZIP_STARTS = (b"PK\x03\x04", b"PK\x05\x06")


def read_npz(path: Path) -> dict[str, np.ndarray]:
    """Every array of npz file `path`, none of them pickled; a file that is not such an npz
    (an entry that is no array, two of one name), or whose array headers claim more than it
    holds, is a one-line error naming it."""
    arrays: dict[str, np.ndarray] = {}
    try:
        with path.open("rb") as file:
            if file.read(4) not in ZIP_STARTS:
                raise ValueError("it does not begin as a zip file")
        with zipfile.ZipFile(path) as archive:
            for info in archive.infolist():
                name = info.filename.removesuffix(".npy")
                if name in arrays:
                    raise ValueError(f"two entries hold column '{name}'")
                arrays[name] = _read_array(archive, info, path)
    except UNREADABLE as exc:
        raise SymbenchError(
            f"{path}: not a readable npz file without pickles "
            f"({one_line(exc) or type(exc).__name__})"
        ) from None
    return arrays


def _read_array(archive: zipfile.ZipFile, info: zipfile.ZipInfo, path: Path) -> np.ndarray:
    """The array of entry `info`, read only when its header claims no more bytes than the
    entry holds."""
    if info.compress_type not in EXPANDS:
        raise ValueError(f"'{info.filename}' is compressed by method {info.compress_type}")
    with archive.open(info) as member:
        if member.read(len(np.lib.format.MAGIC_PREFIX)) != np.lib.format.MAGIC_PREFIX:
            raise ValueError(f"entry '{info.filename}' is not a numpy array")
        member.seek(0)
        version = np.lib.format.read_magic(member)
        if version not in HEADERS:
            raise ValueError(f"'{info.filename}' is in npy format {version}, not 1.0 or 2.0")
        shape, _, dtype = HEADERS[version](member)
        header = member.tell()
        # the bytes it can hold: its compressed bytes, at most the archive's, expanded
        stored = min(info.compress_size, path.stat().st_size) * EXPANDS[info.compress_type]
        holds = min(info.file_size, stored) - header
        claimed = math.prod(shape) * dtype.itemsize
        if claimed > holds:
            name = info.filename.removesuffix(".npy")
            raise SymbenchError(
                f"{path}: column '{name}' claims shape {shape} ({claimed} bytes), but the file "
                f"holds {max(holds, 0)} bytes for it: a damaged or crafted header"
            )
        member.seek(0)
        return np.lib.format.read_array(member, allow_pickle=False)
