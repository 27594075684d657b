"""Clips of the closed loop on a board page (`symbench leaderboard --html --clips`): the best
and the worst model of the dataset climbing beside the expert, so the difference is seen.

- Which models: among the page's groups on the iid split whose records ran the closed-loop
  evaluator, the best and the worst by mean `pd_normalized_score` (the closed loop's
  headline, between the PD alone and the expert's feedforward); where no group has that
  score (it is undefined when the two hold alike), by mean test torque RMSE. Ties keep the
  table's order. The group's seed-0 record is shown (its lowest seed, when it has no 0).
- Which model file: the closed loop's own, the run's architecture trained on the `next`
  variant of `trained_on`, loaded from the checkpoint the run left under its results folder
  (asked for by run key: `symbench.core.runs.trained_models.trained_model`): nothing is
  retrained, and a missing checkpoint is an error naming it, as is one whose content hash is
  not the network the record's closed loop judged (`judged.checkpoint_sha256`: a model
  trained again, by other code or on a CPU of another kernel class, is not the record's).
- Kept clips: each clip is written with a sidecar (`.json` beside the `.webp`) naming what it
  shows (the record's seal and the judged network's hash) and its caption. A build into an
  existing site copies a clip whose sidecar names the same record and network when that
  network's checkpoint is gone (results are not kept between machines): the same network
  on the same reference, so the same climb.
- Which climb: the first reference the evaluator tracked (`ClosedLoopSetup`, the evaluator's
  own: the first reference the expert holds), at the preset's headline PD fraction, the
  model in the evaluator's whole batch. The expert's side is the closed loop's oracle (the
  expert's recorded torques replayed with the same gains: its climb again, to rounding),
  since a recorded reference lacks the passive ankle joints a pose needs.

Each clip is rendered by symbench.core.sim.tracking.render (both sides from one fixed camera on the
reference's path, so a model that strays is seen straying; a failed climb holds its last
state) and written as `clips/<robot>__<dataset>-<best|worst>-<model>.webp`.
"""

from __future__ import annotations

import json
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING

import pandas as pd
from PIL import Image

from symbench.core.board.leaderboard import COLUMNS, protocol_of
from symbench.core.board.site import names
from symbench.core.board.site.columns import CLOSED_LOOP
from symbench.core.board.site.names import GroupKey
from symbench.core.board.site.pages import group_of, row_key
from symbench.core.common.atomic import write_bytes_atomic
from symbench.core.common.errors import SymbenchError
from symbench.core.config.presets import preset
from symbench.core.runs.closed_loop import ClosedLoopSetup, Reference
from symbench.core.runs.results import RecordV1
from symbench.core.runs.trained_models import StoredModel, TrainedModelNotFound, trained_model
from symbench.core.sim.tracking.learned_control import Tracking
from symbench.core.sim.tracking.render import (
    Camera,
    ClimbRenderer,
    Recording,
    frame_times,
    labelled,
    side_by_side,
    webp,
)

if TYPE_CHECKING:
    from symbench.core.data.dataset import Dataset
    from symbench.core.training.trained_model import TrainedModel

SPLIT = "iid"
SCORE = COLUMNS[(CLOSED_LOOP, "pd_normalized_score")]
RMSE = COLUMNS[("torque-error", "rmse")]


@dataclass(frozen=True)
class Clip:
    title: str
    path: str  # the WebP, relative to the site's root
    entry: str  # the group's entry page
    caption: str


@dataclass(frozen=True)
class Choice:
    role: str  # "best" or "worst"
    key: GroupKey
    path: Path  # the record shown
    record: RecordV1
    ranked_by: str


def choose(rows: pd.DataFrame, records: list[tuple[Path, RecordV1]]) -> list[Choice]:
    """The best and the worst group among one page's aggregate `rows` (one when a single
    group qualifies, none when none ran the closed loop on iid), each with its record."""
    shown: dict[GroupKey, tuple[Path, RecordV1]] = {}
    for path, record in records:
        key = group_of(record)
        if key.split == SPLIT and "trained_on" in record.metrics.get(CLOSED_LOOP, {}):
            if key not in shown or record.seed < shown[key][1].seed:
                shown[key] = (path, record)
    candidates = rows[[row_key(row) in shown for _, row in rows.iterrows()]]
    if candidates.empty:
        return []
    column = f"{SCORE}_mean"
    scored = candidates[candidates[column].notna()] if column in candidates else candidates[:0]
    if scored.empty:
        ranked, by = candidates.sort_values(f"{RMSE}_mean", kind="stable"), "test torque RMSE"
    else:
        ranked = scored.sort_values(column, ascending=False, kind="stable")
        by = "closed-loop score"
    ends = [("best", ranked.iloc[0]), ("worst", ranked.iloc[-1])][: min(len(ranked), 2)]
    return [Choice(role, row_key(row), *shown[row_key(row)], by) for role, row in ends]


@dataclass(frozen=True)
class KeptClip:
    """A clip an earlier build rendered of the same record and judged network."""

    webp: bytes
    caption: str


def shows(record: RecordV1) -> dict[str, str] | None:
    """What a clip of `record` shows: the record (its seal) and the network its closed loop
    judged (its content hash); None for a record that does not name that network."""
    judged = record.metrics[CLOSED_LOOP].get("judged") or {}
    sha, seal = judged.get("checkpoint_sha256"), getattr(record, "seal", None)  # schema 1: none
    return None if sha is None or seal is None else {"record_seal": seal, "checkpoint_sha256": sha}


def _sidecar(path: Path) -> Path:
    return path.with_suffix(".json")


def kept_clip(site: Path, choice: Choice) -> KeptClip | None:
    """The clip of `choice` in the built `site`, when its sidecar says it shows the same
    record and judged network; None otherwise."""
    record = choice.record
    path = site / names.clip_file(record.robot, record.dataset.id, choice.role, record.model.name)
    try:
        sidecar = json.loads(_sidecar(path).read_text())
        webp = path.read_bytes()
    except (OSError, ValueError):
        return None
    if (
        not isinstance(sidecar, dict)
        or shows(record) is None
        or sidecar.get("shows") != shows(record)
    ):
        return None
    caption = sidecar.get("caption")
    return KeptClip(webp, caption) if isinstance(caption, str) else None


def judged_model(path: Path, record: RecordV1, results: Path) -> TrainedModel:
    """The closed loop's model of `record`, loaded from under `results` and checked to be the
    network the record judged."""
    model = closed_loop_model(path, record, results).load()
    expected = (shows(record) or {}).get("checkpoint_sha256")
    if expected is not None and model.sha256() != expected:
        raise SymbenchError(
            f"the closed-loop checkpoint for the clip of {path} is not the network it judged "
            f"(content hash {model.sha256()[:12]}... against {expected[:12]}...: trained "
            "again, by other code or on a CPU of another kernel class); give --clips-from the "
            "results folder of its run"
        )
    return model


def closed_loop_model(path: Path, record: RecordV1, results: Path) -> StoredModel:
    """The closed loop's model of `record` (at `path`) under `results`, as the run left it;
    an error naming what is missing otherwise."""
    trained_on = record.metrics[CLOSED_LOOP]["trained_on"]
    try:
        return trained_model(results, record, SPLIT, "next", trained_on)
    except TrainedModelNotFound as missing:
        if missing.found:
            raise SymbenchError(
                f"several closed-loop checkpoints for {path} "
                f"({', '.join(map(str, missing.found))}): remove the stale ones"
            ) from None
        raise SymbenchError(
            f"no closed-loop checkpoint for the clip of {path}: nothing at "
            f"{missing.where}; give --clips-from the results folder of its run"
        ) from None


# per (robot, dataset): each clip's choice with its model, or the clip kept from a build;
# None for a page left without clips (`--without-clips`)
ClipPlan = dict[tuple[str, str], tuple[tuple[Choice, "TrainedModel | KeptClip"], ...] | None]


def clip_plan(
    table: pd.DataFrame,
    records: list[tuple[Path, RecordV1]],
    results: Path,
    kept: Path | None = None,
    without: frozenset[str] = frozenset(),
) -> ClipPlan:
    """Per (robot, dataset) of the aggregate `table`: the clips' choices, each with its
    judged model under `results` or, where that is missing or not the judged network, its
    clip kept in the built site `kept`; all found before anything is rendered or written.
    The datasets in `without` get None: their pages are built without clips."""

    def shown(choice: Choice) -> TrainedModel | KeptClip:
        reused = None if kept is None else kept_clip(kept, choice)
        try:
            return judged_model(choice.path, choice.record, results)
        except SymbenchError:
            if reused is None:
                raise
            return reused

    unknown = sorted(without - set(table["dataset"]))
    if unknown:
        raise SymbenchError(f"--without-clips {unknown[0]}: no board page of that dataset")
    return {
        (str(robot), str(did)): (
            None if did in without else tuple((c, shown(c)) for c in choose(rows, records))
        )
        for (robot, did), rows in table.groupby(["robot", "dataset"], sort=True)
    }


def closed_loop_setup(record: RecordV1, dataset: Dataset) -> ClosedLoopSetup:
    """The closed loop the evaluator of `record` ran: its split's test climbs, its preset."""
    test = dataset.split_indices(record.split, record.seed).test
    return ClosedLoopSetup(dataset, test, preset(record.dataset.preset).closed_loop)


@dataclass
class Scene:
    """A reference climb with the expert's side of its clip, shared by the page's models."""

    references: list[Reference]  # all the evaluator tracked; the clip's is the first
    renderer: ClimbRenderer
    camera: Camera  # the clip's, fixed on the expert's path
    expert: list[Image.Image]  # the expert's labelled frames


def draw_clips(
    planned: tuple[tuple[Choice, TrainedModel | KeptClip], ...], site: Path
) -> tuple[Clip, ...]:
    """The clips of one board page (its part of `clip_plan`), written under `site` with
    their sidecars: kept ones copied, the others rendered."""
    scenes: dict[str, Scene] = {}
    datasets: list[Dataset] = []  # the page's one dataset, loaded when a clip is rendered
    clips = []
    try:
        for choice, model in planned:
            record = choice.record
            path = names.clip_file(record.robot, record.dataset.id, choice.role, record.model.name)
            if isinstance(model, KeptClip):
                webp, caption = model.webp, model.caption
            else:
                datasets = datasets or [_dataset(record)]
                webp, caption = _clip(choice, model, datasets[0], scenes)
            write_bytes_atomic(site / path, webp)
            sidecar = {"shows": shows(record), "caption": caption}
            text = json.dumps(sidecar, indent=1, sort_keys=True) + "\n"
            write_bytes_atomic(_sidecar(site / path), text.encode())
            title = f"{choice.role.capitalize()} by {choice.ranked_by}: {record.model.name}"
            clips.append(Clip(title, path, names.entry_page(choice.key), caption))
        return tuple(clips)
    finally:
        for scene in scenes.values():
            scene.renderer.close()


def _clip(
    choice: Choice, model: TrainedModel, dataset: Dataset, scenes: dict[str, Scene]
) -> tuple[bytes, str]:
    """The clip of `choice` (WebP bytes) and its caption: the closed loop tracked again with
    `model`, the network it judged."""
    record = choice.record
    setup = closed_loop_setup(record, dataset)
    headline = setup.headline
    scene = _scene(record, setup, scenes)
    learned = Recording()
    # the evaluator's whole batch, the clip's job (the first reference at the headline
    # fraction) observed
    shown = setup.job(0, headline)
    tracked = setup.track_model(model.predict, model.entry.view, scene.references, {shown: learned})
    result = tracked[shown]
    scenario = scene.references[0][0]
    times = frame_times(scenario.seconds)
    poses = learned.at(times, scene.renderer.initial)
    fell = f"failed at {result.time_to_failure_s:.2f} s"
    title = f"{record.model.name} (PD {headline:g})"
    frames = []
    for expert, frame, t in zip(
        scene.expert, scene.renderer.frames(poses, scene.camera), times, strict=True
    ):
        failed = not result.attached and t >= result.time_to_failure_s
        frames.append(side_by_side(expert, labelled(frame, title, fell if failed else "", failed)))
    return webp(frames), _caption(choice, result, scenario.seconds, headline)


def _scene(record: RecordV1, setup: ClosedLoopSetup, scenes: dict[str, Scene]) -> Scene:
    """The reference climbs of `record`'s closed loop, with the expert's frames of the
    first; made once per references and gains."""
    key = json.dumps([setup.scenarios, setup.gains(setup.headline)], sort_keys=True)
    if key in scenes:
        return scenes[key]
    references = setup.references  # the evaluator skips those the expert fell on too
    if not references:
        raise SymbenchError(
            f"no clip for {record.key()}: the expert fell on every closed-loop reference"
        )
    scenario, arrays = references[0]
    expert = Recording()
    setup.oracle(scenario, arrays, observe=expert)
    renderer = ClimbRenderer(scenario)
    camera = renderer.camera(arrays["base_pos"])
    times = frame_times(scenario.seconds)
    frames = renderer.frames(expert.at(times, renderer.initial), camera)
    labels = [labelled(f, "expert", f"t = {t:.2f} s") for f, t in zip(frames, times)]
    scenes[key] = Scene(references, renderer, camera, labels)
    return scenes[key]


def _dataset(record: RecordV1) -> Dataset:
    """The record's dataset from the cache, with the record's content hash."""
    from symbench.core.data.dataset import load_dataset

    dataset = load_dataset(record.dataset.id)
    if dataset.content_hash != record.dataset.content_hash:
        raise SymbenchError(
            f"no clip for {record.key()}: it was made on dataset {record.dataset.id} with "
            f"content hash {record.dataset.content_hash[:12]}..., the cache holds "
            f"{dataset.content_hash[:12]}..."
        )
    return dataset


def _caption(choice: Choice, result: Tracking, horizon: float, headline: float) -> str:
    r, key = choice.record, choice.key
    metrics = r.metrics[CLOSED_LOOP]
    climb = (metrics.get("orbits") or ["?"])[0]
    outcome = "held the whole climb" if result.attached else f"failed: {result.failure}"
    return (
        f"{r.model.name} ({key.variant}, {key.backend}, {protocol_of(r)} protocol), split "
        f"{r.split}, seed {r.seed}, trained for the closed loop on {metrics['trained_on']}; "
        f"PD at {headline:g} of the servo gains on the evaluator's first reference climb "
        f"({climb}): held {result.time_to_failure_s:.2f} s of {horizon:.2f} s, {outcome}."
    )
