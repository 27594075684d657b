"""Publishing: checked records merged into a board (leaderboards/) and its tables rebuilt.

Every record that would be on the board afterwards, incoming and already published, must
pass `RecordChecks` (sealed, committed tree, accepted preset, registered names, the standard
dataset's hash); each run group (dataset, split, model, variant, backend) needs MIN_SEEDS
seeds; `verify` re-runs a seeded sample of the incoming records first. Only then is the new
board built in a staging folder beside it (records, named by their key `run_key`, and
tables) and swapped in by renames (`replace_folder`), so a refusal, or a failure half-way,
leaves the board exactly as it was.

The CLI accepts the `small` and `paper` presets only. The Python API takes the accepted
presets as a parameter so that tests can publish records of the seconds-long `smoke` preset;
those records still pass every other check, on a real smoke dataset.
"""

from __future__ import annotations

import shutil
import tempfile
from collections import defaultdict
from collections.abc import Callable, Collection, Sequence
from pathlib import Path

from symbench.core.board.leaderboard import MIN_SEEDS, RECORDS, write_leaderboard
from symbench.core.board.publish_checks import RecordChecks
from symbench.core.common.atomic import replace_folder, staging_folder
from symbench.core.common.errors import SymbenchError
from symbench.core.runs.results import ResultRecord, read_record, write_record

PUBLISHED_PRESETS = ("small", "transfer", "paper")


def _group(r: ResultRecord) -> tuple[str, ...]:
    return (r.dataset.id, r.split, r.model.name, r.model.variant, r.model.backend)


def merge_problems(
    published: list[tuple[Path, ResultRecord]], incoming: list[tuple[Path, ResultRecord]]
) -> list[tuple[Path, str]]:
    """Every incoming record the merge refuses, with the reason: a different record under a
    published key (first, in the order of `incoming`), then a group left with too few seeds."""
    merged = {r.key(): r for _, r in published}
    problems = []
    for path, record in incoming:
        old = merged.get(record.key())
        if old is not None and old != record:
            problems.append(
                (
                    path,
                    f"a different record for {record.key()} is already published; remove it "
                    "from the board's records first",
                )
            )
        else:
            merged[record.key()] = record
    seeds: dict[tuple, set[int]] = defaultdict(set)
    for record in merged.values():
        seeds[_group(record)].add(record.seed)
    for path, record in incoming:
        count = len(seeds[_group(record)])
        if count < MIN_SEEDS:
            problems.append(
                (
                    path,
                    f"{' / '.join(_group(record))} would have {count} seed(s); publish at "
                    f"least {MIN_SEEDS} seeds of a run together",
                )
            )
    return problems


def check_merge(
    published: list[tuple[Path, ResultRecord]], incoming: list[tuple[Path, ResultRecord]]
) -> None:
    """Refuse a different record under a published key, or a group left with too few seeds."""
    for path, reason in merge_problems(published, incoming)[:1]:
        raise SymbenchError(f"{path}: {reason}")


def verify_sample(paths: Sequence[Path], n: int, seed: int, report: Callable[[str], None]) -> None:
    """Re-run `n` of `paths` chosen with `seed`; refuse on the first that does not reproduce."""
    from symbench.core.runs.verify import first_problem, sample, verify_record

    chosen = sample(paths, n, seed)
    report(
        f"verifying {len(chosen)} of {len(paths)} records (sample seed {seed}): "
        + ", ".join(str(p) for p in chosen)
    )
    with tempfile.TemporaryDirectory(prefix="symbench-verify-") as workdir:
        for path in chosen:
            result = verify_record(path, Path(workdir))
            if not result.agree:
                raise SymbenchError(first_problem(result))
            report(f"{path}: all {result.n_recorded} values reproduce ({result.seconds:.0f} s)")


def swap_in(board: Path, build: Callable[[Path], list[Path]]) -> list[Path]:
    """Build a copy of `board` in a staging folder beside it, then put the copy in its place;
    returns the files `build` wrote, as paths in the board."""
    board = Path(board)
    staging = staging_folder(board)
    try:
        if board.exists():
            shutil.copytree(board, staging, symlinks=True, dirs_exist_ok=True)
        written = [board / p.relative_to(staging) for p in build(staging)]
        replace_folder(staging, board)
        return written
    except BaseException:
        shutil.rmtree(staging, ignore_errors=True)
        raise


def dry_run(
    paths: Sequence[Path],
    board: Path,
    presets: Collection[str] = PUBLISHED_PRESETS,
    report: Callable[[str], None] = lambda message: None,
) -> int:
    """What `publish` would say of each of `paths`, writing nothing: accepted, or refused
    with every reason publish could give (its checks, then the merge with the board: a
    different record under a published key, a group left with too few seeds). The board's
    own records are read (sealed), not checked again: only the incoming ones are. Returns
    the number of refusals (0: publish would take them all)."""
    checks = RecordChecks(presets)
    checked, refusals = [], []
    for path in map(Path, paths):
        try:
            checked.append((path, checks.check(path)))
        except SymbenchError as exc:
            refusals.append(str(exc))
    published = [(p, read_record(p)) for p in sorted((Path(board) / RECORDS).glob("*.json"))]
    problems = merge_problems(published, checked)
    refusals += [f"{path}: {reason}" for path, reason in problems]
    merge_refused = {path for path, _ in problems}
    for path in (path for path, _ in checked if path not in merge_refused):
        report(f"accepted: {path}")
    for reason in refusals:
        report(f"refused: {reason}")
    return len(refusals)


def publish(
    paths: Sequence[Path],
    board: Path,
    presets: Collection[str] = PUBLISHED_PRESETS,
    verify: int = 0,
    verify_seed: int = 0,
    report: Callable[[str], None] = lambda message: None,
) -> list[Path]:
    """Check `paths` (and the records already on `board`), merge them into `board`/records and
    rebuild the tables; returns the files written. Nothing is written when anything fails."""
    checks = RecordChecks(presets)
    incoming = [(Path(p), checks.check(Path(p))) for p in paths]
    published = [(p, checks.check(p)) for p in sorted((Path(board) / RECORDS).glob("*.json"))]
    check_merge(published, incoming)
    if verify:
        verify_sample([p for p, _ in incoming], verify, verify_seed, report)

    def build(staged: Path) -> list[Path]:
        folder = staged / RECORDS
        written = [folder / f"{record.key()}.json" for _, record in incoming]
        for path, (_, record) in zip(written, incoming):
            write_record(record, path)
        return written + write_leaderboard(folder, staged)

    return swap_in(Path(board), build)
