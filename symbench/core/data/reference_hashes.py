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
    "magneto-climb-smoke-v5": "7e3f1e165eb001e716ff22380e48870569c2eee705dc5ec01bbe10675a8e03ee",
    "hexa-climb-smoke-v5": "d24975f3236a76ba5e9427c37c1bf419e950d415882df14dee99f331694be9db",
    "nona-climb-smoke-v5": "570205b105c68096020a13b5320fef88ece87f08e7de63cdf155d720516239cf",
    "magneto-climb-small-v5": "23de52021a59354a534947859631b26e3e5a7632b64e87d05139a8c0a624a194",
    "hexa-climb-small-v5": "a84d3a43f4f743b611cc276661af24c9d424a02d7b68380b5cebf7a2daee86a7",
    "nona-climb-small-v5": "69919b9be1dc8b22128d1ec4f06e6ab6c5e555f742b25d9e040310b236fb540d",
    # every slope from floor to ceiling, both leg orders: unseen-inclination, unseen-gait
    "magneto-climb-transfer-v5": (
        "534054b1928a5c12a3933717e422741b7751aec05481a31624ae8367a8cb4b5e"
    ),
    "hexa-climb-transfer-v5": ("16a2dc368ea5f075780fbde86ff8f6fbab20503090b95d6f587aa552d8940729"),
    "nona-climb-transfer-v5": ("9b61fdbe495d88707a1f5996baae3606ffa65fe7a70943c947a3dba76850cda1"),
    # hexa with leg 0 heavier by A (approximately symmetric variants, issue 22)
    "hexa-asym-0.05-climb-small-v5": (
        "7e4e37cef42c7d2fec61cb0f2a1fe0d36e7ff31420e55a7be4fa1b0631d66b40"
    ),
    "hexa-asym-0.1-climb-small-v5": (
        "e7085dfc3a5c577c591006659f9a4440d168452cb7859f2428bd6cc49dac4dce"
    ),
    "hexa-asym-0.2-climb-small-v5": (
        "13e6ca318e06fbc59da8f4c0ae33fdac93780f7dc9b23396c04d99b04e41d615"
    ),
    # data for control: the grids with torque noise (its draws seeded by each scenario)
    "magneto-climb-smoke-noisy-v5": (
        "6af979c0464e9a0f38e2ff4f32b5851fe3c295d20f683175e112fe604636e196"
    ),
    "hexa-climb-smoke-noisy-v5": (
        "23561d4ab523556a5876f2eef7a2dd6548f06eb59626a243a46f7506e02dd272"
    ),
    "nona-climb-smoke-noisy-v5": (
        "a3661d8e67738d26236b7a9c0888f96efa86356596b6e9d72aa34593d08ab35b"
    ),
    "magneto-climb-small-noisy-v5": (
        "971714b40301c5c86e5395d6d46cde9047db0aee0be485f0381e6094a67af534"
    ),
    "hexa-climb-small-noisy-v5": (
        "2615e2ff924c499b4fc411b342957dc41212a2dd0321ca9616a9053b19273c8e"
    ),
    "nona-climb-small-noisy-v5": (
        "87b14f4896e069f9b766dd75d1a7e3784f6b31269f3f307ddc8e416cd0a987f0"
    ),
}


def reference_hash(dataset_id: str, versions: dict[str, str]) -> str | None:
    """The committed hash of `dataset_id` made with `versions`, or None when there is none."""
    return CONTENT_HASHES.get(dataset_id) if versions == LIBRARY_VERSIONS else None
