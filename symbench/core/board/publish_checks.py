"""What may go on a board: one check per way a record could put wrong numbers there.

A publishable record is sealed and matches its seal, was made from a committed tree (so it
can be re-run), on an accepted preset, with names this installation registers, on the
standard dataset of its robot and preset whose content hash equals the one this machine
generates. Each refusal is one line naming the record file and the reason.
"""

from __future__ import annotations

import re
from collections.abc import Collection
from pathlib import Path

from symbench.core.common.errors import SymbenchError
from symbench.core.data.generation.standard import standard_hash
from symbench.core.data.views.schema import VARIANTS
from symbench.core.plugin import registry
from symbench.core.robot.specs import registered_robot
from symbench.core.runs.results import ResultRecord, read_record

COMMIT = re.compile(r"^[0-9a-f]{40}$")


class RecordChecks:
    """The checks, with the standard dataset hashes looked up once per dataset id."""

    def __init__(self, presets: Collection[str]) -> None:
        self.presets = tuple(presets)
        self._hashes: dict[str, str] = {}

    def check(self, path: Path) -> ResultRecord:
        """The record at `path`, or a SymbenchError saying why it may not be published."""
        record = read_record(path)  # schema, seal, safe identifiers
        for problem in (
            _commit_problem,
            self._preset_problem,
            _name_problem,
            self._dataset_problem,
        ):
            reason = problem(record)
            if reason:
                raise SymbenchError(f"{path}: {reason}")
        return record

    def _preset_problem(self, record: ResultRecord) -> str:
        preset = record.dataset.preset
        if preset in self.presets:
            return ""
        takes = ", ".join(self.presets)
        return f"{preset}-preset records are not published (this board takes {takes})"

    def _dataset_problem(self, record: ResultRecord) -> str:
        from symbench.core.config.presets import dataset_id, parse_dataset_id, preset

        did = record.dataset.id
        expected = dataset_id(record.robot, record.dataset.preset)
        parsed = parse_dataset_id(did)
        earlier = (  # a standard dataset of an earlier version of the preset (`small@v6`)
            parsed is not None
            and parsed[0] == record.robot
            and preset(parsed[1]).name == record.dataset.preset
        )
        if did != expected and not earlier:
            return (
                f"dataset '{did}' is not the standard dataset of {record.robot} on preset "
                f"{record.dataset.preset} ('{expected}'); records on imported data go on "
                "boards of their own (symbench leaderboard)"
            )
        if did not in self._hashes:
            try:
                self._hashes[did] = standard_hash(did)
            except SymbenchError as exc:
                return str(exc)
        if record.dataset.content_hash != self._hashes[did]:
            return (
                f"made on dataset {did} with content hash {record.dataset.content_hash[:12]}"
                f"..., but the standard dataset this code generates has hash "
                f"{self._hashes[did][:12]}...; re-run it on the standard dataset"
            )
        return ""


def _commit_problem(record: ResultRecord) -> str:
    commit = record.git_commit
    if commit.endswith("+dirty"):
        return (
            f"made from a working tree with uncommitted changes (git_commit {commit}), "
            "so nobody can re-run it; commit and re-run it"
        )
    if not COMMIT.match(commit):
        return f"git_commit '{commit}' names no commit; re-run it from a git checkout of symbench"
    return ""


def _name_problem(record: ResultRecord) -> str:
    """Every name must be registered here, and the model's view and variant its own."""
    try:
        registered_robot(record.robot)
        registry.split(record.split)
        entry = registry.model(record.model.name, record.model.backend)
        for evaluator in record.metrics:
            registry.evaluator(evaluator)
    except SymbenchError as exc:
        return str(exc)
    if record.model.view != entry.view:
        return (
            f"model {entry.name} reads the {entry.view} view, the record says {record.model.view}"
        )
    if record.model.variant not in VARIANTS:
        return f"unknown input variant '{record.model.variant}' (known: {', '.join(VARIANTS)})"
    return ""
