"""Whatever a robot.toml holds (any bytes, or a built-in robot's spec edited one value at a
time), reading it gives a one-line error naming the file, or a spec: never an internal
error. A plugin author writes this file by hand (docs/writing-plugins.md, "Adding a robot")."""

from __future__ import annotations

import tomllib
from pathlib import Path

import pytest
from hypothesis import event, given
from hypothesis import strategies as st
from strategies import FILE_BYTES, edited
from toml_writer import toml_text

from symbench.core.common.errors import SymbenchError
from symbench.core.plugin import registry
from symbench.core.robot.specs import RobotSpec, load_spec


@pytest.fixture(scope="module", params=["hexa", "magneto"])
def spec_doc(request) -> dict:
    path = Path(registry.robot(request.param).spec_dir) / "robot.toml"
    return tomllib.loads(path.read_text())


def read(folder: Path, content: bytes) -> None:
    """load_spec on `content` as robot.toml: a spec, or one line naming the file."""
    path = folder / "robot.toml"
    path.write_bytes(content)
    try:
        spec = load_spec(folder)
    except SymbenchError as error:
        event("refused")
        assert "\n" not in str(error) and str(path) in str(error), str(error)
        return
    event("read")
    assert isinstance(spec, RobotSpec) and spec.n_legs == len(spec.mount_angles_deg)


@given(content=FILE_BYTES)
def test_a_robot_toml_of_any_bytes_is_refused_naming_it(tmp_path_factory, content):
    read(tmp_path_factory.mktemp("robot"), content)


@given(data=st.data())
def test_an_edited_robot_toml_is_refused_naming_it_or_read(tmp_path_factory, spec_doc, data):
    doc = data.draw(edited(spec_doc))
    read(tmp_path_factory.mktemp("robot"), toml_text(doc).encode())
