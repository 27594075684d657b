"""Whatever a result record file holds, reading it gives a one-line error naming it or the
record it holds, sealed; whatever a record is made of, writing it gives an error and no file, or a
file that reads back as that record."""

from __future__ import annotations

import json

from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from sandbox import files_under
from strategies import FILE_BYTES, edited

from symbench.core.common.errors import SymbenchError
from symbench.core.runs.results import read_record, seal_of, write_record

# `make_record` and `tmp_path` give a builder and a folder that every example may share
SHARED_FIXTURES = settings(suppress_health_check=[HealthCheck.function_scoped_fixture])


def assert_named(error: SymbenchError, path) -> None:
    assert str(path) in str(error) and "\n" not in str(error)


@SHARED_FIXTURES
@given(content=FILE_BYTES)
def test_any_file_read_as_a_record_gives_an_error_naming_it(tmp_path, content):
    path = tmp_path / "r.json"
    path.write_bytes(content)
    try:
        read_record(path)
    except SymbenchError as error:
        assert_named(error, path)


@SHARED_FIXTURES
@given(data=st.data(), reseal=st.booleans())
def test_an_edited_record_is_refused_or_reads_as_its_content(tmp_path, make_record, data, reseal):
    sealed = write_record(make_record(), tmp_path / "valid.json").model_dump(mode="json")
    record = data.draw(edited(sealed))
    if reseal and isinstance(record, dict):
        record["seal"] = seal_of(record)
    path = tmp_path / "r.json"
    path.write_text(json.dumps(record))
    try:
        read = read_record(path)
    except SymbenchError as error:
        assert_named(error, path)
        return
    # what is compared and published is exactly the file's (other fields are read the way
    # pydantic's lax mode reads them: "3" as 3 for the seed, say)
    assert read.metrics == record["metrics"]
    assert read.dataset.model_dump() == record["dataset"]
    assert read.seal == record["seal"] == seal_of(record)


@SHARED_FIXTURES
@given(data=st.data())
def test_writing_any_record_gives_an_error_and_no_file_or_one_that_reads_back(
    tmp_path, make_record, data
):
    folder = tmp_path / "out"
    record = data.draw(edited(make_record()))
    try:
        written = write_record(record, folder / "r.json")
    except SymbenchError as error:
        assert_named(error, folder / "r.json")
        assert not folder.exists() or files_under(folder) == []
        return
    assert read_record(folder / "r.json") == written
    assert files_under(folder) == ["r.json"]
    (folder / "r.json").unlink()
