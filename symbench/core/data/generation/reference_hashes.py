"""The content hashes of the standard datasets, as this version of symbench generates them.

Standard datasets are byte-identical on every x86-64 CPU (see `determinism`), so their hashes
are facts about the code, not about a machine: they are committed here, made on one machine
and checked on every other by the test suite. `symbench data generate` says whether it
matches, and publishing refuses a cached dataset that differs from its reference (a forged
or damaged cache, or a platform that breaks the guarantee). A hash holds only for the
library versions it was made with (they are part of the dataset metadata); with other
versions there is no reference. After a deliberate change to the data, bump
DATASET_VERSION, regenerate, and add the hashes; the earlier version's stay, since its
datasets are still generated (the legacy presets `small@v6` and the like).
"""

from __future__ import annotations

LIBRARY_VERSIONS = {
    "daqp": "0.11.0",
    "dm-control": "1.0.50",
    "llvmlite": "0.50.0",
    "mujoco": "3.17.0",
    "numba": "0.68.1",
    "numpy": "2.4.6",
    "pyarrow": "26.0.1",
    "symbench": "0.1.0",
}

CONTENT_HASHES = {
    "magneto-climb-smoke-v6": ("9448d645bc00a32837ca39de324f866203e00f01d6452bfeadb0f37e7129e67f"),
    "hexa-climb-smoke-v6": ("d3c2a7ee0219fc338879d7a0a6a65e7c45233baca62ec6289ed4eb82fd3764c9"),
    "nona-climb-smoke-v6": ("574d81078cca2bf097d19ac4778b4c1e6f42ff4ad89c1d7eaebfd66ff9677887"),
    "magneto-climb-small-v6": ("39a83af0b7d78d1cbf139cdbe20b5dba55e17cb6a36568e4ec694857292c6df8"),
    "hexa-climb-small-v6": ("777007e769ad7a0e9f50f1bdf1cd582c08b444b62cf723e6accad2b12d5f837b"),
    "nona-climb-small-v6": ("bb316801d18a4427adc9ee54e0b3d6c0513a817531945fe4ad2495cbea7e745c"),
    # every slope from floor to ceiling, both leg orders: unseen-inclination, unseen-gait
    "magneto-climb-transfer-v6": (
        "b7f67da7924c260914009fc47fe1281a0a6f278adba4bcefe64059fd2778cc32"
    ),
    "hexa-climb-transfer-v6": ("2d43be982b921c25525ae991ed89ffbadd887dc254f039763c9dc7188a1e1b35"),
    "nona-climb-transfer-v6": ("b0e09cf6b5265fa257a98aa7376d1452f55a337b641c969b676701b7af9b1246"),
    # hexa with leg 0 heavier by A (approximately symmetric variants)
    "hexa-asym-0.05-climb-small-v6": (
        "0fbd9db18b415c2f1a0018bee148d70661caf78017d8055671a076d30b866276"
    ),
    "hexa-asym-0.1-climb-small-v6": (
        "772c2741a6e16061af90b424d770cbd76e4031a2710ac65774f4c03b15c180d4"
    ),
    "hexa-asym-0.2-climb-small-v6": (
        "cc97e597f845d9a1c3a3335eb8290ff3f87abf42794bc59195c1aeb27defb03f"
    ),
    # data for control: the grids with torque noise (its draws seeded by each scenario)
    "magneto-climb-smoke-noisy-v6": (
        "5abbeedf106ac244d7113465fb79260950950b08a7c81dd04e39fdb55738db94"
    ),
    "hexa-climb-smoke-noisy-v6": (
        "c8088918d9bdc65b40af39e446ff811dfec64d10d925770d494a1b8366d8eed0"
    ),
    "nona-climb-smoke-noisy-v6": (
        "938587337dd43b0a10dd8fc7757bc5f9a9fe78ea17bc58266f8df2c38fbe438f"
    ),
    "magneto-climb-small-noisy-v6": (
        "f8ed11f4a52c87de8f86261f65f138232bfabde127625fc55d644f5c3206ebd4"
    ),
    "hexa-climb-small-noisy-v6": (
        "4e87833fd9d55501da8e188798169700296cfdf3d2f2252adae7551adf756ea4"
    ),
    "nona-climb-small-noisy-v6": (
        "05e0441726aa0f861e80dba612f84f76c704592e1e2fa695fc5133a52ff8424f"
    ),
    # dataset v7: climbs drawn from continuous distributions, each step its own
    "magneto-climb-smoke-v7": ("75465e28ba671957ff5ad18c8b8a0f5af234d2a3d4a9bb2de198acff79e51e80"),
    "hexa-climb-smoke-v7": ("8cb818d40a2b53701e40a600d17c32b77325c470234ed4a9ae3cd9e2f53e92af"),
    "nona-climb-smoke-v7": ("5a588c4b6ce8403132e4fc3d2c5f21b797970e3f79e30ddc4fa70dac1cba5f28"),
    "magneto-climb-small-v7": ("141b589a76a399be978bbc8140737a40d8bfe7577c32fa66ed8e33b54154d82a"),
    "hexa-climb-small-v7": ("a6d97a7bd9e3aa5de3fe7811adeff27c554ab20d196d0d595d4e1767ac5852d7"),
    "nona-climb-small-v7": ("96a98437f37c743a77eb826818ab9e72f4181c6166f005c296f478ec341c6c5c"),
    "magneto-climb-transfer-v7": (
        "0fc643da59f8aaaff2d48d2cc139e1b8c1c3766d6480d7de3ee23d9a5a4aa52c"
    ),
    "hexa-climb-transfer-v7": ("84ce980ef94d98070604e6ede09299fc324f88d8ebe5278ff2e6cafd39d39621"),
    "nona-climb-transfer-v7": ("7b8686dab6d6e793a7f057be8d6031071a520d32c52d7e67384496f0998449eb"),
    "hexa-asym-0.05-climb-small-v7": (
        "bd158b1fed1f4e910735b0bdccc6d3e69d9374dc0011128522a1e5ba765bac1f"
    ),
    "hexa-asym-0.1-climb-small-v7": (
        "e3375f81428e8a8362a8495ae43616e35f6bb0243df4ea4d1ee6f0bc5d089373"
    ),
    "hexa-asym-0.2-climb-small-v7": (
        "114b84d8285fb452af412bdd9386f480c7d6cdb63964b59b414aedabf2038797"
    ),
    "magneto-climb-smoke-noisy-v7": (
        "8436c48d895eb9b99830c147bc4d5b428385375f6fd3a301a5d6afab99bfb517"
    ),
    "hexa-climb-smoke-noisy-v7": (
        "3328cd9b49531e9473e6e31837f3b568fce88ca5ab5eed1c099fe8c379b095ed"
    ),
    "nona-climb-smoke-noisy-v7": (
        "b4b617db5befa644ed653e4c18adec203e3374dc23a1be5f658722a38e653abe"
    ),
    "magneto-climb-small-noisy-v7": (
        "ed60f097399d1686d08b42a9a6cbaa0eef6f747334771ca5ce007673d7d7fd91"
    ),
    "hexa-climb-small-noisy-v7": (
        "e69c4fb6a66edc411598c879a85aed6e5407df2022a8b4cc5e73e8dfa95ab7d4"
    ),
    "nona-climb-small-noisy-v7": (
        "b9af0fcb1078f700852e71127ed31dc1acdab9a7b002b71914ee02e749e53b8c"
    ),
    # the paper preset on hexa (768 climbs of 10 s, 1.28 M samples, 750 MB): the first
    # paper-scale board's data, generated by the same code as the smoke datasets whose hashes
    # the test suite checks on every CPU
    "hexa-climb-paper-v7": ("2acb878234bb0ed322c8993e43101d73dd4e85739c13416821cca3d2317a0c81"),
}


def reference_hash(dataset_id: str, versions: dict[str, str]) -> str | None:
    """The committed hash of `dataset_id` made with `versions`, or None when there is none."""
    return CONTENT_HASHES.get(dataset_id) if versions == LIBRARY_VERSIONS else None


def no_reference(dataset_id: str, versions: dict[str, str]) -> str:
    """Why `reference_hash` found none, in one line: a plugin robot's (or another non-standard)
    dataset has none by design, a standard one with other library versions none for them."""
    if dataset_id not in CONTENT_HASHES:
        return (
            "no reference hash for this id: expected for a plugin robot's dataset and any other "
            "that is not a built-in robot's standard dataset (only those have references "
            "committed with symbench); its content hash above identifies it"
        )
    names = sorted(set(versions) | set(LIBRARY_VERSIONS))
    differ = [
        f"{n} {versions.get(n, 'absent')} (reference {LIBRARY_VERSIONS.get(n, 'absent')})"
        for n in names
        if versions.get(n) != LIBRARY_VERSIONS.get(n)
    ]
    return f"no reference hash for these library versions: {', '.join(differ)}"
