"""`symbench data generate` says why a dataset has no reference hash (issue 42, item 12): for a
plugin robot's dataset that is expected, not a warning sign; for a standard dataset it names
the library versions that differ from the references'."""

from __future__ import annotations

from symbench.core.data.generation.reference_hashes import (
    LIBRARY_VERSIONS,
    no_reference,
    reference_hash,
)


def test_a_plugin_robots_dataset_is_told_that_none_is_expected():
    versions = dict(LIBRARY_VERSIONS)
    assert reference_hash("penta-climb-smoke-v7", versions) is None
    message = no_reference("penta-climb-smoke-v7", versions)
    assert message.startswith("no reference hash for this id: expected for a plugin robot's")
    assert "\n" not in message


def test_a_standard_dataset_names_the_versions_that_differ():
    versions = {**LIBRARY_VERSIONS, "numpy": "9.9.9"}
    del versions["daqp"]
    assert reference_hash("hexa-climb-smoke-v7", versions) is None
    assert no_reference("hexa-climb-smoke-v7", versions) == (
        "no reference hash for these library versions: "
        f"daqp absent (reference {LIBRARY_VERSIONS['daqp']}), "
        f"numpy 9.9.9 (reference {LIBRARY_VERSIONS['numpy']})"
    )
