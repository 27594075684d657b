"""Whatever a `symbench tune` journal holds, damaged or edited line by line, resuming the search
gives a one-line error naming the journal, or resumes it: never an internal error."""

from __future__ import annotations

import json
import shutil
from unittest import mock

import pytest
from hypothesis import event, given, settings
from hypothesis import strategies as st
from sandbox import fresh_home
from strategies import FILE_BYTES, edited
from synthetic_raw import fake_simulate

from symbench.core.common.errors import SymbenchError
from symbench.core.data.generation.generate import generate
from symbench.core.runs import tune as tuning
from symbench.core.runs.spec import RunSpec
from symbench.core.training import loop

GRID = ((1e-3,), (1.0,))  # one point, not extended past its edges: a grid-only journal


class Trained(Exception):
    """What the stand-in for training raises: the search got past the journal."""


@pytest.fixture(scope="module")
def searched(tmp_path_factory):
    """A home with hexa's smoke dataset (stand-in simulator), and a folder holding the
    journal of a finished one-trial search on it."""
    folder = tmp_path_factory.mktemp("tuning")
    with fresh_home() as home:
        generate("hexa", "smoke", simulator=fake_simulate, show_progress=False)
        spec = RunSpec("ffnn", "hexa", preset="smoke", evaluators=(), max_steps=2, output=folder)
        tuning.tune(spec, *GRID, folder, report=lambda _: None, extend_edges=False)
        yield home, spec, tuning.journal_path(folder, spec)


def resume(searched, content: bytes, tmp_path_factory) -> None:
    """The search resumed from a journal holding `content`: it returns, trains (stopped by
    the stand-in) or refuses in one line naming the journal."""
    home, spec, _ = searched
    folder = tmp_path_factory.mktemp("resumed")
    shutil.copytree(home, folder / "home")
    path = tuning.journal_path(folder, spec)
    path.write_bytes(content)
    with fresh_home(), mock.patch.dict("os.environ", {"SYMBENCH_HOME": str(folder / "home")}):
        try:
            with mock.patch.object(loop, "train", side_effect=Trained):
                summary = tuning.tune(
                    spec, *GRID, folder, report=lambda _: None, extend_edges=False
                )
        except Trained:
            event("trains again")
            return
        except SymbenchError as error:
            event("refused")
            assert str(error).startswith(f"tuning journal {path} is damaged"), str(error)
            return
    event("resumed")
    assert summary["complete"] and len(summary["trials"]) == 1


@settings(max_examples=settings.default.max_examples // 2)  # a resumed search per example
@given(content=FILE_BYTES)
def test_a_journal_of_any_bytes_is_refused_naming_it_or_read(searched, tmp_path_factory, content):
    resume(searched, content, tmp_path_factory)


@settings(max_examples=settings.default.max_examples // 2)  # a resumed search per example
@given(data=st.data())
def test_an_edited_journal_line_is_refused_naming_it_or_read(searched, tmp_path_factory, data):
    lines = [json.loads(line) for line in searched[2].read_text().splitlines()]
    at = data.draw(st.integers(0, len(lines) - 1))
    lines[at] = data.draw(edited(lines[at]))
    content = "".join(json.dumps(line) + "\n" for line in lines)
    resume(searched, content.encode(), tmp_path_factory)
