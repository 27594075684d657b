"""The names that end up in file names (robots, splits, models, variants, datasets, presets):
one rule, which plugin entries are checked against when they are made and records when they
are written, so that no name a plugin registers fails only when a finished run writes its
record (a model named `sdnn+aug` once trained and evaluated, then could not be recorded)."""

from __future__ import annotations

import re

# letters, digits, '.', '_' and '-', not starting with '.': no path separators, no '..'
IDENTIFIER = r"^[A-Za-z0-9][A-Za-z0-9._-]*$"
IDENTIFIER_LENGTH = 100
# a preset's key: an identifier, or an earlier dataset version's `name@vN` (`small@v6`)
PRESET_KEY = IDENTIFIER.removesuffix("$") + r"(@v[0-9]+)?$"


def is_identifier(name: str) -> bool:
    return len(name) <= IDENTIFIER_LENGTH and re.fullmatch(IDENTIFIER, name) is not None
