"""The content hashes of the standard datasets, as this version of symbench generates them.

Standard datasets are byte-identical on every x86-64 CPU (see `determinism`), so their hashes
are facts about the code, not about a machine: they are committed here, made on one machine
and checked on every other by the test suite. `symbench data generate` says whether it
matches, and publishing refuses a cached dataset that differs from its reference (a forged
or damaged cache, or a platform that breaks the guarantee). A hash holds only for the
library versions it was made with (they are part of the dataset metadata); with other
versions there is no reference. After a deliberate change to the data, bump
DATASET_VERSION, regenerate, and replace the hashes.
"""

from __future__ import annotations

LIBRARY_VERSIONS = {
    "dm-control": "1.0.50",
    "mujoco": "3.17.0",
    "numpy": "2.4.6",
    "pyarrow": "26.0.1",
    "symbench": "0.1.0",
}

CONTENT_HASHES = {
    "magneto-climb-smoke-v4": "58eb30292e052784664403dad7a3cd70278f431c1d11be2a0a95851fa98d19e5",
    "hexa-climb-smoke-v4": "e3f3bfc9097ec1b783aaff2a23082bfa546542e97c23aa0fe382bf8def851641",
    "nona-climb-smoke-v4": "22c7067b5e4cef872a3f349eeb2294226bf1464a18a84d57c19eec3be4871b08",
    "magneto-climb-small-v4": "9b2ad83546142423df94ff3d1da1221474b772fe43fed7d59d8d8ea35f2389b9",
    "hexa-climb-small-v4": "e5530304f669b3f1fa51373773f6102368903049474cbcf168ca59e747a8ed08",
    "nona-climb-small-v4": "5526a212002c0e6eabb4afda15547911442a4b93dd272b532342dda98dd02c3c",
    # data for control: smoke's grid with torque noise (its draws seeded by each scenario)
    "magneto-climb-smoke-noisy-v4": (
        "03b2b28754b210e278a74e2981246bad54c5624392bdd19fab3f7ec58cc52020"
    ),
    "hexa-climb-smoke-noisy-v4": "6905ca397476d2e4a51b71b974c2bd2e55d223b7122487490ad4c9726d8d42c7",
    "nona-climb-smoke-noisy-v4": "c0d265821be97d80a9667553d183b2a875bd3cdf839dcd2dfe0e0723e367c37b",
}


def reference_hash(dataset_id: str, versions: dict[str, str]) -> str | None:
    """The committed hash of `dataset_id` made with `versions`, or None when there is none."""
    return CONTENT_HASHES.get(dataset_id) if versions == LIBRARY_VERSIONS else None
