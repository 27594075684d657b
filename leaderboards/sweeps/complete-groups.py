"""The records under the given output folders whose whole split is there and not yet
published: every model of the split with every seed, by record file name
(`<dataset>__<preset>__<split>__<model>__<variant>__<backend>__<protocol>[__p<N>]__seed<S>.json`).
Prints their paths, one per line, for `symbench publish`.

    python leaderboards/sweeps/complete-groups.py --models 5 --seeds 5 WORKTREE/results ...
"""

from __future__ import annotations

import argparse
import re
from collections import defaultdict
from pathlib import Path

NAME = re.compile(
    r"(?P<dataset>[^_]+(?:_[^_]+)*?)__(?P<preset>[^_]+)__(?P<split>[^_]+)__"
    r"(?P<model>[^_]+)__(?P<rest>.+)__seed(?P<seed>\d+)\.json"
)
PUBLISHED = Path(__file__).resolve().parents[1] / "records"


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("folders", nargs="+", type=Path)
    parser.add_argument("--models", type=int, default=5)
    parser.add_argument("--seeds", type=int, default=5)
    args = parser.parse_args()
    published = {p.name for p in PUBLISHED.glob("*.json")}
    splits: dict[tuple[str, ...], dict[str, list[Path]]] = defaultdict(lambda: defaultdict(list))
    for folder in args.folders:
        for path in sorted(folder.glob("*.json")):
            found = NAME.fullmatch(path.name)
            if found is None or path.name in published:
                continue
            split = (found["dataset"], found["preset"], found["split"], found["rest"])
            splits[split][found["model"]].append(path)
    for models in splits.values():
        if len(models) == args.models and all(len(s) == args.seeds for s in models.values()):
            for paths in models.values():
                print(*paths, sep="\n")


if __name__ == "__main__":
    main()
