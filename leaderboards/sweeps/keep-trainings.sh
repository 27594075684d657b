#!/usr/bin/env bash
# Before a working session ends with a model and seed's paper runs unfinished: copies the
# trainings its runs share (each one's resume checkpoint, finished or not; it holds the best
# parameters too, from which a training rewrites a missing best/) into
# leaderboards/pending/trainings/<kernel class>/<output folder>/checkpoints/ (to be
# committed). board-v7.sh copies them back on a machine of the same kernel class only, where
# they are the very bits it would train (or resume to); keep-pending.sh drops them with the
# output folder's last pending record. A new machine would otherwise train them again: on
# hexa's paper data up to five gnn trainings of about 19 minutes before a run's first record.
#
#   leaderboards/sweeps/keep-trainings.sh MODEL SEED [OUTPUT] [WORKTREE]
#       (default: results-paper in ../wt-paper7 beside the repo, board-v7.sh's)
set -euo pipefail

[ $# -ge 2 ] || { echo "usage: $0 MODEL SEED [OUTPUT] [WORKTREE]" >&2; exit 2; }
REPO=$(cd "$(dirname "$0")/../.." && pwd)
model=$1 seed=$2 out=${3:-results-paper} worktree=${4:-$(dirname "$REPO")/wt-paper7}
class=$("${PYTHON:-$REPO/.venv/bin/python}" "$REPO/leaderboards/sweeps/kernel-class.py")
to=$REPO/leaderboards/pending/trainings/$class/$out/checkpoints
kept=0
# checkpoints/<run key>/<dataset hash>/<split>__<variant>/: run keys name model and seed
for training in "$worktree/$out"/checkpoints/*__"${model}"__*__seed"$seed"/*/*/; do
    [ -f "$training/resume.safetensors" ] || continue
    dest=$to/${training#"$worktree/$out/checkpoints/"}
    mkdir -p "$dest"
    cp "$training/resume.safetensors" "$dest/"
    kept=$((kept + 1))
done
echo "kept $kept trainings of $model seed $seed in ${to#"$REPO/"}"
