"""Publishing: checked records merged into the repository's leaderboards/ and tables rebuilt.

A record is accepted when it validates, was made on a standard dataset (a preset's, not an
import) whose content hash equals the one this machine generates, and its run group (robot,
split, model, backend) has at least MIN_SEEDS seeds once merged. Anything else is refused
with the reason, and nothing is written.
"""

from __future__ import annotations

from collections import defaultdict
from pathlib import Path

from symbench.core.errors import SymbenchError
from symbench.core.leaderboard import MIN_SEEDS, load_records, write_leaderboard
from symbench.core.results import ResultRecord, check_dataset_hash, read_record, write_record

RECORDS = "records"


def standard_hash(dataset_id: str, source: Path) -> str:
    """The content hash of the standard dataset `dataset_id` in this machine's cache."""
    from symbench.core.data.dataset import missing_hint
    from symbench.core.data.metadata import read_metadata
    from symbench.core.data.presets import parse_dataset_id

    if parse_dataset_id(dataset_id) is None:
        raise SymbenchError(f"{source}: dataset '{dataset_id}' is not a standard dataset "
                            "(a preset's); only those are published")
    return read_metadata(dataset_id, missing_hint(dataset_id))[1]["content_hash"]


def _group(r: ResultRecord) -> tuple[str, ...]:
    return (r.robot, r.split, r.model.name, r.model.variant, r.model.backend)


def publish(paths: list[Path], board: Path) -> list[Path]:
    """Check `paths`, merge them into `board`/records, rebuild the tables; files written."""
    incoming = [(Path(p), read_record(Path(p))) for p in paths]
    hashes: dict[str, str] = {}
    for path, record in incoming:
        dataset = record.dataset.id
        hashes.setdefault(dataset, standard_hash(dataset, path))
        check_dataset_hash(record, hashes[dataset], source=str(path))
    folder = board / RECORDS
    published = {r.key(): r for _, r in load_records(folder)} if any(folder.glob("*.json")) else {}
    for path, record in incoming:
        old = published.get(record.key())
        if old is not None and old != record:
            raise SymbenchError(f"{path}: a different record for {record.key()} is already "
                                "published; remove it from leaderboards/records first")
        published[record.key()] = record
    seeds: dict[tuple, set[int]] = defaultdict(set)
    for record in published.values():
        seeds[_group(record)].add(record.seed)
    for _, record in incoming:
        count = len(seeds[_group(record)])
        if count < MIN_SEEDS:
            raise SymbenchError(f"{' / '.join(_group(record))} would have {count} seed(s); "
                                f"publish at least {MIN_SEEDS} seeds of a run together")
    written = []
    for _, record in incoming:
        written.append(folder / f"{record.key()}.json")
        write_record(record, written[-1])
    return written + write_leaderboard(folder, board)
