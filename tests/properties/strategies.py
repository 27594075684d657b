"""Hypothesis strategies for what symbench reads: JSON of any shape, a valid document with
one thing changed, arbitrary bytes, a valid file with a few bytes changed (an npz with its
checksums made right again), and trajectory columns with one defect."""

from __future__ import annotations

import copy
import json
import zipfile
from collections.abc import Iterator
from typing import Any

import numpy as np
from crafted_npz import npy_members, npz_bytes
from hypothesis import strategies as st

FLOATS = st.floats() | st.sampled_from([1e300, -1e300, 3.5e38, 1e-320, 0.0])
SCALARS = st.none() | st.booleans() | st.integers(-(2**70), 2**70) | FLOATS | st.text(max_size=12)
JSON = st.recursive(
    SCALARS,
    lambda inner: (
        st.lists(inner, max_size=4) | st.dictionaries(st.text(max_size=10), inner, max_size=4)
    ),
    max_leaves=10,
)
# text no JSON reader should trace back on: nesting past the recursion limit, a number past
# Python's 4300-digit conversion limit, NaN and Infinity (json.dumps writes them)
NASTY_TEXT = (
    st.integers(1_000, 100_000).map(lambda n: "[" * n + "]" * n)
    | st.integers(4_301, 6_000).map(lambda n: "9" * n)
    | JSON.map(json.dumps)
    | st.text()
)
FILE_BYTES = st.binary(max_size=300) | NASTY_TEXT.map(str.encode)


def _slots(doc: Any) -> Iterator[tuple[Any, Any]]:
    """(container, key) of every value inside `doc`."""
    items = (
        doc.items() if isinstance(doc, dict) else enumerate(doc) if isinstance(doc, list) else ()
    )
    for key, value in items:
        yield doc, key
        yield from _slots(value)


def _near(value: Any) -> st.SearchStrategy:
    """Values a subtle edit would put in place of `value`: another of its kind."""
    if isinstance(value, bool):
        return st.booleans()
    if isinstance(value, int):
        return st.integers(-3, 3).map(lambda change: value + change)
    if isinstance(value, float):
        return FLOATS
    if isinstance(value, str):
        return st.text(max_size=12) | st.just(value[:-1])
    return JSON


@st.composite
def edited(draw: st.DrawFn, document: Any) -> Any:
    """`document` with one value deleted, replaced by another of its kind or by any JSON, or
    one key added."""
    doc = copy.deepcopy(document)
    container, key = draw(st.sampled_from(list(_slots(doc))))
    action = draw(st.sampled_from(["delete", "replace", "near", "add"]))
    if action == "delete":
        del container[key]
    elif action == "near":
        container[key] = draw(_near(container[key]))
    elif action == "add" and isinstance(container[key], dict):
        container[key][draw(st.text(max_size=10))] = draw(JSON)
    else:
        container[key] = draw(JSON)
    return doc


@st.composite
def defective(
    draw: st.DrawFn, columns: dict[str, np.ndarray], same_length: bool
) -> dict[str, np.ndarray]:
    """`columns` (a trajectory's arrays) unchanged or with one defect: a value set to any
    float, a column dropped, shortened, made text, pickled or added, or fewer steps;
    `same_length` is for Parquet tables, whose columns can be neither ragged nor pickled."""
    out = {k: np.array(v) for k, v in columns.items()}
    name = draw(st.sampled_from(sorted(out)))
    kinds = ["none", "value", "drop", "text", "extra", "steps"]
    kinds += [] if same_length else ["shorten", "pickled"]
    kind = draw(st.sampled_from(kinds))
    if kind == "value":
        values = out[name].astype(np.float64)
        values.flat[draw(st.integers(0, values.size - 1))] = draw(FLOATS)
        out[name] = values
    elif kind == "drop":
        del out[name]
    elif kind == "text":
        out[name] = out[name].astype(str)
    elif kind == "extra":
        out[draw(st.from_regex(r"[a-z][a-z0-9_.]{0,10}", fullmatch=True))] = out[name]
    elif kind == "steps":
        n = draw(st.integers(0, 3))
        out = {k: v[:n] for k, v in out.items()}
    elif kind == "shorten":
        out[name] = out[name][: -draw(st.integers(1, 3))]
    elif kind == "pickled":  # np.savez pickles object arrays
        out[name] = out[name].astype(object)
    return out


# what a changed byte becomes: the digits, brackets and letters of an .npy header's text (its
# shape, dtype and order), or any byte
HEADER_BYTES = st.sampled_from(list(b"0123456789(),: '<>|fiuUSOVbcmM{}LNTrue")) | st.integers(
    0, 255
)


@st.composite
def changed(draw: st.DrawFn, content: bytes, near_start: int | None = None) -> bytes:
    """`content` with one to four bytes changed (within its first `near_start` bytes when
    given, where a file's header is), cut short, or a run of it repeated."""
    out = bytearray(content)
    kind = draw(st.sampled_from(["bytes", "bytes", "cut", "repeat"]))
    if kind == "cut":
        return bytes(out[: draw(st.integers(0, max(len(out) - 1, 0)))])
    if kind == "repeat":
        start = draw(st.integers(0, len(out) - 1))
        end = draw(st.integers(start, min(len(out), start + 64)))
        return bytes(out[:end] + out[start:end] * draw(st.integers(1, 4)) + out[end:])
    span = min(len(out), near_start or len(out))
    for _ in range(draw(st.integers(1, 4))):
        out[draw(st.integers(0, span - 1))] = draw(HEADER_BYTES)
    return bytes(out)


@st.composite
def changed_npz(draw: st.DrawFn, arrays: dict[str, np.ndarray]) -> bytes:
    """An npz of `arrays` with one entry's bytes changed (mostly in its header), renamed
    without its .npy suffix, or another entry added, stored or compressed, every checksum
    right."""
    members = npy_members(arrays)
    name = draw(st.sampled_from(sorted(members)))
    kind = draw(st.sampled_from(["header", "header", "anywhere", "suffix", "extra"]))
    if kind == "suffix":
        members[name.removesuffix(".npy")] = members.pop(name)
    elif kind == "extra":
        members[draw(st.sampled_from(["notes.txt", name.removesuffix(".npy")]))] = draw(
            st.binary(max_size=40) | st.just(members[name])
        )
    else:
        members[name] = draw(changed(members[name], 128 if kind == "header" else None))
    return npz_bytes(members, draw(st.sampled_from([zipfile.ZIP_STORED, zipfile.ZIP_DEFLATED])))
