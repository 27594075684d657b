"""Whatever scenarios an import.json gives real climbing logs (leg orders, yaws, headings,
directions edited one by one: the fields `data symmetry` maps by the group to pair images),
importing them gives a one-line refusal, and `symbench data symmetry` on what was imported
gives its report or a one-line refusal: never an internal error."""

from __future__ import annotations

import json
import shutil
from pathlib import Path

import pytest
from cli_invoke import invoke, refusal
from hypothesis import event, given, settings
from hypothesis import strategies as st
from sandbox import fresh_home
from strategies import edited

from symbench.core.common.errors import SymbenchError
from symbench.core.data.importing.importer import import_logs

LOGS = Path(__file__).parents[1] / "data" / "symmetry" / "logs" / "magneto-gaits"


@pytest.fixture(scope="module")
def logs(tmp_path_factory) -> Path:
    return shutil.copytree(LOGS, tmp_path_factory.mktemp("logs") / "magneto-gaits")


@settings(max_examples=settings.default.max_examples // 2)  # each imports and measures
@given(data=st.data())
def test_edited_scenarios_are_refused_on_import_or_reported_on(logs, data):
    manifest = json.loads((LOGS / "import.json").read_text())
    manifest["trajectories"] = data.draw(edited(manifest["trajectories"]))
    (logs / "import.json").write_text(json.dumps(manifest))
    with fresh_home() as home:
        try:
            import_logs(logs, "gaits")
        except SymbenchError as error:
            event("import refused")
            assert "\n" not in str(error) and str(logs) in str(error), str(error)
            return
        result = invoke("data", "symmetry", "gaits", "--json", "--output", home / "plots")
    if result.exit_code != 0:
        event("symmetry refused")
        assert "gaits" in refusal(result)
        return
    event("reported")
    report = json.loads(result.stdout)
    assert report["dataset"] == "gaits"
    assert report["trajectories"] == len(manifest["trajectories"])
