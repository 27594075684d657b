#!/usr/bin/env bash
# What remains of board v7, in the order it is published, run from a clean worktree at the
# commit the small board is made at. Every sweep skips the runs whose record exists, so the
# same command resumes after an interruption; the published records and those kept in
# ../pending/ (committed between working sessions, before their group is complete) are
# copied into the worktree first. A run that
# failed beside another (out of memory) runs again alone before the next phase starts.
#
#   leaderboards/sweeps/board-v7.sh [WORKTREE [PAPER_WORKTREE [JAX_WORKTREE]]]
#       (defaults: ../wt-board7m, ../wt-paper7 and ../wt-jax7 beside the repo)
set -uo pipefail

REPO=$(cd "$(dirname "$0")/../.." && pwd)
# 2dd8a0d from hexa fraction-0.25 gnn on (2026-11-29): the runs' figures as at 7a8d9fb (the
# code between changes no torch training or evaluation figure), the image overlap measured
# once per split and seed; records made before name 7a8d9fb
COMMIT=2dd8a0d
WT=${1:-$(dirname "$REPO")/wt-board7m}
# the paper board from 5dd2529 (2026-12-06): the same runs as 2dd8a0d's (no training or
# evaluation figure changed between them), with the image overlap 2.4 times faster, which
# on the paper data cost about as much as the trainings (about 4 CPU seconds per held-out
# climb)
PAPER_COMMIT=5dd2529
PWT=${2:-$(dirname "$REPO")/wt-paper7}
# the JAX entries from d5d5414 (2026-12-07): JAX model version 4 (predictions and validation
# losses on 256 rows at a time), made again there; their torch twins are 2dd8a0d's
JAX_COMMIT=d5d5414
JWT=${3:-$(dirname "$REPO")/wt-jax7}
PY=${PYTHON:-$REPO/.venv/bin/python}
MODELS=sdnn,sdgnn,ffnn,ffnn-leg,gnn
ALL=torque-error,equivariance,invariance,generalization,closed-loop,image-overlap,generalization-gap
OPEN=torque-error,equivariance,invariance,generalization,image-overlap,generalization-gap
FRACTIONS=fraction-0.1,fraction-0.25,fraction-0.5,fraction-0.75

[ -x "$PY" ] || make -C "$REPO" .venv/.installed  # a fresh machine: the environment first
worktree() {  # worktree FOLDER COMMIT: FOLDER checked out at COMMIT, clean, or exit
    [ -d "$1" ] || git -C "$REPO" worktree add --detach "$1" "$2"
    [ "$(git -C "$1" rev-parse --short=7 HEAD)" = "$2" ] || { echo "$1 is not at $2" >&2; exit 1; }
    [ -z "$(git -C "$1" status --porcelain --untracked-files=no)" ] || { echo "$1 is not clean" >&2; exit 1; }
}
worktree "$WT" "$COMMIT"
worktree "$PWT" "$PAPER_COMMIT"
worktree "$JWT" "$JAX_COMMIT"
# published records back into the output folders whose sweeps made them, so that a fresh
# worktree skips them
home() {  # home OUTPUT[/SUBFOLDER]: the worktree whose sweeps write OUTPUT
    case $1 in
        results-paper | results-paper/*) echo "$PWT" ;;
        results-jax | results-jax/*) echo "$JWT" ;;
        *) echo "$WT" ;;
    esac
}
restore() {  # restore OUTPUT RECORDS...
    local out=$1 to; shift
    to=$(home "$out")
    mkdir -p "$to/$out"
    for record in "$@"; do [ -e "$record" ] && cp -n "$record" "$to/$out/"; done
    return 0
}
restore results "$REPO"/leaderboards/records/*-v7__*.json
restore results-matched "$REPO"/leaderboards/records/*-v7__*__p100000__*.json
restore results-jax "$REPO"/leaderboards/records/*-v7__*__jax__*.json
restore results-paper "$REPO"/leaderboards/records/*-paper-v7__*.json
STUDIES=$REPO/leaderboards/studies
restore results-asymmetry "$STUDIES"/asymmetry-v7/records/*.json
restore results-library "$STUDIES"/library-baseline-v7/records/*.json
restore results-transfer "$STUDIES"/transfer-v7/records/*.json
restore results-mirror "$STUDIES"/mirror-group-v7/records/*.json
for kept in "$REPO"/leaderboards/pending/*/; do
    compgen -G "$kept*.json" > /dev/null || continue  # a folder of records (not clip-sources/)
    restore "$(basename "$kept")" "$kept"*.json
    # the split overlaps its runs measured, by the dataset's content hash
    restore "$(basename "$kept")/image-overlap-cache" "$kept"image-overlap-cache/*.json
done
# trainings of unfinished paper runs a machine of this one's kernel class left
# (keep-trainings.sh): the bits this machine would train, so they are not trained again
for kept in "$REPO/leaderboards/pending/trainings/$("$PY" "$REPO/leaderboards/sweeps/kernel-class.py")"/*/; do
    [ -d "${kept}checkpoints" ] || continue
    out=$(basename "$kept")
    mkdir -p "$(home "$out")/$out"
    cp -rn "${kept}checkpoints" "$(home "$out")/$out/"
done

one_sweep() {  # one_sweep OUTPUT ARGS...: a one-worker sweep into OUTPUT, in its worktree
    local out=$1 at; shift
    at=$(home "$out")
    (cd "$at" && MUJOCO_GL=disable PYTHONPATH="$at" "$PY" -m symbench sweep "$@" \
        --output "$out" --workers 1)
}

FAILED=$(mktemp)  # the one-run sweeps that failed beside another, a line each: OUTPUT ARGS...
QUEUE=$(mktemp)  # the paper board's models and seeds still to run, a line each: MODEL SEED
trap 'rm -f "$FAILED" "$FAILED.retry" "$QUEUE" "$QUEUE.lock"' EXIT

once() {  # once OUTPUT ARGS...: a one-worker sweep, noted in $FAILED when it fails
    one_sweep "$@" || echo "$*" >> "$FAILED"
}

# recorded OUTPUT SPLIT MODEL SEEDS ARGS...: whether OUTPUT holds the record of every robot
# (--robots among ARGS) and seed, by file name (<robot>-climb-<preset>-v7__<preset>__<split>__
# <model>__<variant>__<backend>__<protocol>[__p<N>]__seed<S>.json), so that a resumed sweep
# passes a finished group without starting Python (3 s a group, 10 to 20 minutes a session).
# A name it does not foresee only means the sweep is asked, and finds the records itself.
option() {  # option NAME DEFAULT ARGS...: the value given to NAME among ARGS, else DEFAULT
    local name=$1 value=$2; shift 2
    while [ $# -gt 0 ]; do
        if [ "$1" = "$name" ] && [ $# -gt 1 ]; then value=$2; shift 2; else shift; fi
    done
    echo "$value"
}

recorded() {
    local out=$1 split=$2 model=$3 seeds=$4; shift 4
    local robots preset backend protocol size robot seed
    robots=$(option --robots "" "$@")
    preset=$(option --preset small "$@")
    backend=$(option --backends torch "$@")
    protocol=$(option --protocol converge "$@")
    size=$(option --parameters "" "$@")
    [ -z "$size" ] || size=__p$size
    [ -n "$robots" ] || return 1
    for robot in ${robots//,/ }; do
        for seed in ${seeds//,/ }; do
            compgen -G "$(home "$out")/$out/$robot-climb-$preset-v7__${preset}__${split}__${model}__*__${backend}__$protocol${size}__seed$seed.json" \
                > /dev/null || return 1
        done
    done
}

# datasets ARGS...: the standard dataset of every robot (--robots) of the preset (--preset)
# among ARGS, made with all workers before a sweep's first run: its one-run sweeps, started
# two at once, would each simulate a missing one (hexa's paper data: 768 climbs of 10 s).
datasets() {
    local robot preset
    preset=$(option --preset small "$@")
    for robot in $(option --robots "" "$@" | tr , ' '); do
        (cd "$WT" && MUJOCO_GL=disable PYTHONPATH="$WT" "$PY" -m symbench data generate \
            --robot "$robot" --preset "$preset" --workers "${WORKERS:-2}" --no-progress)
    done
}

# sweep OUTPUT --models LIST [--seeds LIST] ARGS... (--splits LIST among ARGS): one
# one-worker sweep per split, model and seed, WORKERS (2) of them at once, so that a split's
# lone fifth seed shares the cores with the next model's first instead of leaving one idle
# (about 20 minutes per gnn split on nona before, 2026-11-29). One run per process: at
# 7a8d9fb a sweep's worker keeps what its runs loaded (on magneto a worker reached 12 GB and a
# one-worker sweep 24 GB, killed for memory, 2026-11-28), where each run alone fits. Runs that
# share a training (the generalization evaluators') take turns on its lock file.
sweep() {
    local out=$1 models=$3 seeds=0,1,2,3,4 splits=iid; shift 3
    if [ "$1" = --seeds ]; then seeds=$2; shift 2; fi
    local rest=() model split seed made=""
    while [ $# -gt 0 ]; do
        if [ "$1" = --splits ]; then splits=$2; shift 2; else rest+=("$1"); shift; fi
    done
    for split in ${splits//,/ }; do  # a split's every model and seed first: publishable
        for model in ${models//,/ }; do
            for seed in ${seeds//,/ }; do
                recorded "$out" "$split" "$model" "$seed" "${rest[@]}" && continue
                [ -n "$made" ] || { datasets "${rest[@]}"; made=1; }
                while [ "$(jobs -rp | wc -l)" -ge "${WORKERS:-2}" ]; do wait -n; done
                once "$out" --models "$model" --splits "$split" --seeds "$seed" "${rest[@]}" &
            done
        done
    done
    wait  # the next phase may read this one's records
    alone_again
}

# alone_again: a run that failed beside another (out of memory: hexa's paper runs peak near
# 10 GB) runs again alone; one that fails alone too waits for the next session
alone_again() {
    local job
    mv "$FAILED" "$FAILED.retry" && : > "$FAILED"
    while read -r -a job; do
        one_sweep "${job[@]}" || echo "failed alone too: ${job[*]}" >&2
    done < "$FAILED.retry"
}

# 1-3. the small grid, robot by robot: a run's generalization evaluators train its model on
# other splits of its robot (unseen-rotation's: iid, unseen-heading, control-rotation), whose
# runs find those trainings while the checkpoints are on disk (they are not committed; a new
# machine trains them again)
for robot in magneto hexa nona; do
    sweep results --models $MODELS --robots $robot --splits iid,unseen-rotation --evaluators $ALL
    sweep results --models $MODELS --robots $robot \
        --splits control-rotation,unseen-heading,control-heading,$FRACTIONS --evaluators $OPEN
done
# 4. the matched-size section
sweep results-matched --models $MODELS --robots nona,magneto --splits iid --parameters 100000 \
    --evaluators torque-error,equivariance,invariance,image-overlap
# 5. the JAX entries
sweep results-jax --models sdnn,ffnn --backends jax --robots hexa --splits iid --evaluators $ALL
# 6. the studies again on v7 (each publishes to leaderboards/studies/<name>-v7): before the
# paper board, whose 12 core-hours span sessions, since each study completes within one
sweep results-asymmetry --models sdnn,sdgnn,ffnn --robots hexa-asym-0.05,hexa-asym-0.1,hexa-asym-0.2 \
    --splits iid --evaluators torque-error,equivariance,data-symmetry
# A = 0 again, on the CPU that made the variants: the board's hexa iid records were made on
# an Intel Xeon, whose torch kernel class trains to other figures (ffnn 0.223 here against
# the board's 0.224, seed by seed within 3 %), so that each A is paired seed by seed
sweep results-asymmetry --models ffnn,sdnn,sdgnn --robots hexa --splits iid \
    --evaluators torque-error,equivariance,data-symmetry
# e2cnn-mlp is a distribution of its own, the installed one (examples/symbench-e2cnn, 0.2.0:
# tuned on hexa v7), whose version and source hash its records carry
sweep results-library --models e2cnn-mlp --robots hexa --splits iid,unseen-rotation \
    --evaluators torque-error,equivariance,invariance
sweep results-transfer --models sdnn,sdgnn,ffnn --robots magneto,hexa,nona --preset transfer \
    --splits unseen-inclination,control-inclination,unseen-gait,control-gait \
    --evaluators torque-error,equivariance,image-overlap,generalization-gap
sweep results-mirror --models sdnn --size mirror=1 --robots hexa --splits iid,unseen-rotation,fraction-0.1 \
    --evaluators torque-error,equivariance,invariance
sweep results-mirror --models sdnn --size mirror=1 --robots nona,magneto --splits iid,fraction-0.1 \
    --evaluators torque-error,equivariance,invariance
sweep results-mirror --models sdnn --size mirror=1 --robots hexa --preset transfer --splits unseen-gait \
    --evaluators torque-error,equivariance
# 7. the paper board (hexa): 50 000 cosine steps, 3 seeds, model by model and seed by seed, each
# one's four runs in turn: they share seven trainings (the iid, unseen-heading,
# unseen-rotation, control-rotation and fraction-0.1 models and the closed loop's two `next`
# models), which a new machine trains again for every run still to make (a model and seed
# whose four runs fell in four sessions: 18 trainings). WORKERS lanes take models and seeds
# from one queue, those this machine holds trainings of first, so two runs at once never wait
# for each other's trainings.
PAPER=(--robots hexa --preset paper --protocol cosine --max-steps 50000)
paper_runs() {  # paper_runs MODEL SEED: its iid, unseen-rotation, control and fraction runs
    local split evaluators
    for split in iid unseen-rotation control-rotation fraction-0.1; do
        recorded results-paper "$split" "$1" "$2" "${PAPER[@]}" && continue
        evaluators=$ALL  # the closed loop on iid and unseen-rotation
        [ "$split" = iid ] || [ "$split" = unseen-rotation ] || evaluators=$OPEN
        once results-paper --models "$1" --splits "$split" --seeds "$2" "${PAPER[@]}" \
            --evaluators "$evaluators"
    done
}
next_in_queue() {  # the queue's first line, taken from it
    flock "$QUEUE.lock" bash -c 'head -n 1 "$1" && sed -i 1d "$1"' _ "$QUEUE"
}
lane() {
    local pair
    while pair=$(next_in_queue) && [ -n "$pair" ]; do
        # shellcheck disable=SC2086  # MODEL SEED
        paper_runs $pair
    done
}
for model in ${MODELS//,/ }; do
    for seed in 0 1 2; do
        trained=1
        compgen -G "$PWT/results-paper/checkpoints/*__${model}__*__seed$seed" > /dev/null && trained=0
        echo "$trained $model $seed"
    done
done | sort -s -k 1,1 | cut -d ' ' -f 2- > "$QUEUE"
datasets "${PAPER[@]}"
for _ in $(seq "${WORKERS:-2}"); do lane & done
wait
alone_again
