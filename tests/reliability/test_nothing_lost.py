"""A failed or interrupted import loses nothing and blocks nothing."""

from __future__ import annotations

import pytest
from synthetic_raw import write_logs

from symbench.core.common.paths import dataset_ids
from symbench.core.data import load_dataset
from symbench.core.data.importing import importer
from symbench.core.data.importing.importer import import_logs


def failing_metadata(error: BaseException):
    def write_metadata(root, meta):
        raise error

    return write_metadata


def test_a_failed_import_with_force_leaves_the_existing_dataset_intact(home, tmp_path, monkeypatch):
    before = import_logs(write_logs(tmp_path / "first", n_files=4), "logs").content_hash
    monkeypatch.setattr(
        importer, "write_metadata", failing_metadata(OSError(28, "No space left on device"))
    )
    with pytest.raises(OSError, match="No space left"):
        import_logs(write_logs(tmp_path / "second", n_files=6, n_steps=30), "logs", force=True)
    assert load_dataset("logs").content_hash == before  # every file still verifies
    assert sorted(p.name for p in (home / "datasets").iterdir()) == ["logs"]  # no leftovers


def test_a_half_finished_import_does_not_block_its_id(home, tmp_path, monkeypatch):
    folder = write_logs(tmp_path / "logs")
    with monkeypatch.context() as patch:
        patch.setattr(importer, "write_metadata", failing_metadata(KeyboardInterrupt()))
        with pytest.raises(KeyboardInterrupt):  # Ctrl-C while the files were being written
            import_logs(folder, "logs")
    assert dataset_ids() == []
    assert len(import_logs(folder, "logs").trajectory_ids) == 6  # no --force needed
