"""The pytest11 entry point provides the kit's fixtures to any test suite."""

from __future__ import annotations

from symbench.core.plugin import registry


def test_fixtures_come_from_the_installed_plugin(symbench_kit, symbench_groups):
    assert set(symbench_groups) == {"magneto", "hexa", "nona"}
    assert symbench_kit.n_samples == 32
    report = symbench_kit.assert_equivariant(
        registry.model("sdnn", "torch"), symbench_groups["nona"], hyper={"latent": 8}
    )
    assert report.equivariant and len(report.elements) == 9
