#!/usr/bin/env bash
# Before a working session ends: copies the records of the worktrees' output folders that are not
# published into leaderboards/pending/<output folder>/ (to be committed), and drops from there
# those published since; board-v7.sh copies them back. Published means the same bytes in the
# board's records/ or a study's: a study's run may share its file name with a board record
# (sdnn with --size mirror=1, or a board run made again with another evaluator) and still be
# a different record. The split overlaps the output folders measured
# (image-overlap-cache/: small JSON files, keyed by the dataset's content hash, that cost about
# 25 CPU minutes a split and seed on hexa's paper data) are kept with them, in
# pending/<output folder>/image-overlap-cache/, until no record of that folder is pending; so
# are the trainings keep-trainings.sh kept (pending/trainings/<kernel class>/<output folder>/).
#
#   leaderboards/sweeps/keep-pending.sh [WORKTREE...]
#       (default: ../wt-board7m and ../wt-paper7 beside the repo, board-v7.sh's)
set -euo pipefail

REPO=$(cd "$(dirname "$0")/../.." && pwd)
if [ $# -eq 0 ]; then set -- "$(dirname "$REPO")/wt-board7m" "$(dirname "$REPO")/wt-paper7"; fi
PENDING=$REPO/leaderboards/pending

published() {  # published RECORD: whether a board or a study holds RECORD's very bytes
    local name copy
    name=$(basename "$1")
    for copy in "$REPO/leaderboards/records/$name" "$REPO"/leaderboards/studies/*/records/"$name"; do
        if cmp -s "$copy" "$1"; then return 0; fi
    done
    return 1
}

for worktree in "$@"; do
    for out in "$worktree"/results*/; do
        for record in "$out"*.json; do
            [ -e "$record" ] || continue
            published "$record" && continue
            mkdir -p "$PENDING/$(basename "$out")"
            cp "$record" "$PENDING/$(basename "$out")/"
        done
        if compgen -G "$PENDING/$(basename "$out")/*.json" > /dev/null \
            && compgen -G "$out/image-overlap-cache/*.json" > /dev/null; then
            mkdir -p "$PENDING/$(basename "$out")/image-overlap-cache"
            cp "$out"image-overlap-cache/*.json "$PENDING/$(basename "$out")/image-overlap-cache/"
        fi
    done
done
for kept in "$PENDING"/*/*.json; do
    [ -e "$kept" ] || continue
    if published "$kept"; then rm "$kept"; fi
done
for cache in "$PENDING"/*/image-overlap-cache/; do  # its folder's records all published
    [ -d "$cache" ] || continue
    compgen -G "$(dirname "$cache")/*.json" > /dev/null || rm -r "$cache"
done
for kept in "$PENDING"/trainings/*/*/; do  # keep-trainings.sh's, likewise
    [ -d "$kept" ] || continue
    compgen -G "$PENDING/$(basename "$kept")/*.json" > /dev/null || rm -r "$kept"
done
find "$PENDING/trainings" -mindepth 1 -type d -empty -delete 2>/dev/null || true
