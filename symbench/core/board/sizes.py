"""The board's sizes: a record at the model's default size, one matched to N parameters
(`--parameters N`), or one with build keywords set by name (`--size mirror=1`). Sizes are
never mixed in one table, as protocols are not: each size has its own sections and its own
ranks, default sizes first, then matched sizes by count, then sizes set by name.

A matched section asks every model to be within BOARD_TOLERANCE of N, tighter than the
MATCH_TOLERANCE `symbench run` accepts (`training.sizes`): the board states each model's
relative miss and marks a model outside it, rather than hiding it.
"""

from __future__ import annotations

import re

import pandas as pd

from symbench.core.runs.results import RecordV1

DEFAULT = "default"
MATCHED = "matched "  # a matched size's label: 'matched 100000'
SET = "with "  # keywords set by name: 'with mirror=1', 'matched 100000 with latent=64'
BOARD_TOLERANCE = 0.05
_MATCHED = re.compile(r"^matched (\d+)")


def size_of(record: RecordV1) -> str:
    """'default'; 'matched N' for a record made with `--parameters N`; 'with a=1, b=2' for
    build keywords set by `--size` (after 'matched N ' when both)."""
    matched = getattr(record.model, "matched_parameters", None)
    sizes = getattr(record.model, "sizes", None) or {}
    parts = [] if matched is None else [f"{MATCHED}{matched}"]
    if sizes:
        parts.append(SET + ", ".join(f"{k}={v}" for k, v in sorted(sizes.items())))
    return " ".join(parts) or DEFAULT


def matched_count(size: str) -> int | None:
    """N of 'matched N'; None for a size not matched."""
    found = _MATCHED.match(size)
    return None if found is None else int(found.group(1))


def size_order(size: str) -> tuple[int, int, str]:
    """Default sizes first, then matched sizes by increasing count, then keywords set by name."""
    count = matched_count(size)
    if size == DEFAULT:
        return (0, 0, "")
    return (1, count, size) if count is not None else (2, 0, size)


def by_size(table: pd.DataFrame) -> list[tuple[str, pd.DataFrame]]:
    """The rows of each size, default first."""
    parts = table.groupby("size", sort=False)
    return sorted(((str(s), part) for s, part in parts), key=lambda item: size_order(item[0]))


def default_size(table: pd.DataFrame) -> pd.DataFrame:
    """The rows at the models' default sizes: what plots, clips and claims compare."""
    return table[table["size"] == DEFAULT]


def titled(heading: str, size: str) -> str:
    """A section's heading with its size: unchanged at the default size, else followed by
    ', matched at 100 000 parameters' and/or ', built with mirror=1'."""
    count = matched_count(size)
    if count is not None:
        grouped = f"{count:,}".replace(",", " ")
        heading = f"{heading}, matched at {grouped} parameters"
    if SET in size:
        heading = f"{heading}, built {size[size.index(SET) :]}"
    return heading


def miss(parameters: int, size: str) -> float | None:
    """A matched model's relative miss of its target (+0.012: 1.2 % above); None at default."""
    count = matched_count(size)
    return None if count is None else parameters / count - 1


def miss_text(parameters: int, size: str) -> str:
    """'+1.2 %', with '(outside 5 %)' beyond the board's tolerance; '' at default size."""
    off = miss(parameters, size)
    if off is None:
        return ""
    flag = f" (outside {BOARD_TOLERANCE * 100:.0f} %)" if abs(off) > BOARD_TOLERANCE else ""
    return f"{_percent(off)}{flag}"


def miss_caption(rows: pd.DataFrame, size: str) -> str:
    """What a matched section says under its heading: the target, the tolerance and each
    model's miss, those outside it marked; '' at default size."""
    count = matched_count(size)
    if count is None:
        return ""
    where = rows.dataset.nunique() > 1  # summary.md: a model's count differs per robot
    models = rows.drop_duplicates(["dataset", "model", "variant", "backend"])
    misses = ", ".join(
        f"{r.model}{f' on {r.dataset}' if where else ''} {miss_text(int(r.parameters), size)}"
        for _, r in models.iterrows()
    )
    outside = any(abs(r.parameters / count - 1) > BOARD_TOLERANCE for _, r in models.iterrows())
    said = "; a model outside it is marked, not left out" if outside else ""
    return (
        f"Every model's widths scaled to {count} parameters (`--parameters {count}`); the "
        f"board allows a miss of {BOARD_TOLERANCE * 100:.0f} %{said}. Misses: {misses}."
    )


def _percent(fraction: float) -> str:
    return f"{fraction * 100:+.1f} %"
