#!/usr/bin/env bash
# Before a working session ends: copies the records of WORKTREE's output folders that are not
# published into leaderboards/pending/<output folder>/ (to be committed), and drops from there
# those published since; board-v7.sh copies them back.
#
#   leaderboards/sweeps/keep-pending.sh [WORKTREE]    (default: ../wt-board7m beside the repo)
set -euo pipefail

REPO=$(cd "$(dirname "$0")/../.." && pwd)
WT=${1:-$(dirname "$REPO")/wt-board7m}
PENDING=$REPO/leaderboards/pending

for out in "$WT"/results*/; do
    for record in "$out"*.json; do
        [ -e "$record" ] || continue
        [ -e "$REPO/leaderboards/records/$(basename "$record")" ] && continue
        mkdir -p "$PENDING/$(basename "$out")"
        cp "$record" "$PENDING/$(basename "$out")/"
    done
done
for kept in "$PENDING"/*/*.json; do
    [ -e "$kept" ] || continue
    if [ -e "$REPO/leaderboards/records/$(basename "$kept")" ]; then rm "$kept"; fi
done
