"""Clips of the closed loop on the site (`symbench leaderboard --html DIR --clips`): which
models are shown, a one-line error when a checkpoint is missing, and (slow) tiny models
trained on the smoke preset, their clips rendered, encoded and shown on the robot's page.

Rendering uses OSMesa (MUJOCO_GL=osmesa), which MuJoCo picks only when it is first imported:
the slow test builds the site in a child process. The Debian package libosmesa6 is
installed with apt-get when it is missing; the test fails, never skips, when that fails."""

from __future__ import annotations

import html
import io
import json
import os
import subprocess
import sys
from collections.abc import Iterator
from pathlib import Path

import numpy as np
import pytest
from cli_invoke import error_line, invoke
from PIL import Image
from system_packages import ensure_osmesa

from symbench.core.board.leaderboard import aggregate, load_records
from symbench.core.board.site.clips import choose, shows
from symbench.core.board.site.names import MARKER, GroupKey, clip_file
from symbench.core.common.errors import SymbenchError
from symbench.core.config.presets import dataset_id
from symbench.core.runs.results import write_record

HEXA = dataset_id("hexa", "smoke")
NOISY = dataset_id("hexa", "smoke-noisy")
SCORES = {"sdnn": 0.8, "gnn": 0.5, "ffnn": 0.2}  # the mean closed-loop score of each model
RMSE = {"sdnn": 0.3, "gnn": 0.1, "ffnn": 0.2}  # ranks them another way


def _write(folder: Path, make_record, scores=SCORES, split="iid", seeds=(1, 0)) -> Path:
    """Records of three models on hexa's smoke dataset, their closed loop trained on the
    noisy variant (seed 0 written last: the choice must not depend on the file order)."""
    folder.mkdir(exist_ok=True)
    for model, score in scores.items():
        for seed in seeds:
            record = make_record(model=model, split=split, seed=seed, rmse=RMSE[model])
            record["metrics"]["closed-loop"] = {
                "trained_on": NOISY,
                "pd_normalized_score": None if score is None else score + seed / 100,
                "judged": {"checkpoint_sha256": f"{model}{seed}".encode().hex().ljust(64, "0")},
            }
            write_record(record, folder / f"{model}-{split}-seed{seed}.json")
    return folder


def _choices(folder: Path) -> list[tuple[str, str, int, str]]:
    records = load_records(folder)
    return [
        (c.role, c.key.model, c.record.seed, c.ranked_by)
        for c in choose(aggregate(records), records)
    ]


def test_the_best_and_the_worst_by_closed_loop_score_seed_0(tmp_path, make_record):
    assert _choices(_write(tmp_path / "r", make_record)) == [
        ("best", "sdnn", 0, "closed-loop score"),
        ("worst", "ffnn", 0, "closed-loop score"),
    ]


def test_without_a_score_the_test_rmse_ranks(tmp_path, make_record):
    unscored = dict.fromkeys(SCORES)
    assert _choices(_write(tmp_path / "r", make_record, unscored)) == [
        ("best", "gnn", 0, "test torque RMSE"),
        ("worst", "sdnn", 0, "test torque RMSE"),
    ]


def test_only_iid_groups_that_ran_the_closed_loop_qualify(tmp_path, make_record):
    folder = _write(tmp_path / "r", make_record, {"gnn": 0.5})
    _write(folder, make_record, {"sdnn": 0.9}, split="unseen-heading")
    record = make_record(model="ffnn", rmse=0.01)  # no closed loop: nothing to show
    write_record(record, folder / "ffnn-iid-seed0.json")
    assert _choices(folder) == [("best", "gnn", 0, "closed-loop score")]
    records = load_records(folder)
    rows = aggregate(records)
    key = GroupKey(HEXA, "paper", "iid", "gnn", "acc", "torch")
    assert [c.key for c in choose(rows, records)] == [key]


def test_a_missing_checkpoint_is_one_line_and_writes_nothing(tmp_path, make_record, monkeypatch):
    monkeypatch.setenv("MUJOCO_GL", "disable")  # undone after the test, whatever the CLI sets
    monkeypatch.delenv("PYOPENGL_PLATFORM", raising=False)
    results = _write(tmp_path / "r", make_record)
    site = tmp_path / "site"
    result = invoke("leaderboard", "--results", results, "--html", site, "--clips")
    best = next(r for p, r in load_records(results) if p.name == "sdnn-iid-seed0.json")
    folder = results / "checkpoints" / best.key() / best.dataset.content_hash[:12]
    assert error_line(result, 1) == (
        f"Error: no closed-loop checkpoint for the clip of {results}/sdnn-iid-seed0.json: "
        f"nothing at {folder}/{NOISY}-*/iid__next/best; give --clips-from the results folder "
        "of its run"
    )
    assert not site.exists()


def _kept_site(site: Path, records: list, caption: str, judged: str | None = None) -> None:
    """A site an earlier build made, holding the clips of the choices among `records`, each
    with the sidecar that names what it shows (another judged network when `judged`)."""
    (site / "clips").mkdir(parents=True)
    (site / MARKER).write_text("built\n")
    for choice in choose(aggregate(records), records):
        r = choice.record
        clip = site / clip_file(r.robot, r.dataset.id, choice.role, r.model.name)
        clip.write_bytes(f"webp of {r.model.name}".encode())
        shown = shows(r) | ({"checkpoint_sha256": judged} if judged else {})
        clip.with_suffix(".json").write_text(json.dumps({"shows": shown, "caption": caption}))


def test_a_clip_whose_checkpoint_is_gone_is_kept_from_the_site_it_replaces(
    tmp_path, make_record, monkeypatch
):
    monkeypatch.setenv("MUJOCO_GL", "disable")
    monkeypatch.delenv("PYOPENGL_PLATFORM", raising=False)
    results = _write(tmp_path / "r", make_record)
    site = tmp_path / "site"
    _kept_site(site, load_records(results), "held 2.00 s of 2.00 s (kept)")
    result = invoke("leaderboard", "--results", results, "--html", site, "--clips")
    assert result.exit_code == 0, result.output
    page = (site / f"boards/hexa__{HEXA}.html").read_text()
    assert page.count("held 2.00 s of 2.00 s (kept)") == 2
    for model in ("sdnn", "ffnn"):
        clip = next((site / "clips").glob(f"*-{model}.webp"))
        assert clip.read_bytes() == f"webp of {model}".encode()
        assert json.loads(clip.with_suffix(".json").read_text())["caption"].endswith("(kept)")


def test_a_kept_clip_of_another_network_is_not_shown(tmp_path, make_record, monkeypatch):
    monkeypatch.setenv("MUJOCO_GL", "disable")
    monkeypatch.delenv("PYOPENGL_PLATFORM", raising=False)
    results = _write(tmp_path / "r", make_record)
    site = tmp_path / "site"
    _kept_site(site, load_records(results), "a retrained network's climb", judged="f" * 64)
    result = invoke("leaderboard", "--results", results, "--html", site, "--clips")
    assert "no closed-loop checkpoint for the clip of" in error_line(result, 1)
    assert (site / "clips" / f"hexa__{HEXA}-best-sdnn.webp").read_bytes() == b"webp of sdnn"


def test_a_page_built_without_clips_says_so_and_the_others_keep_theirs(
    tmp_path, make_record, monkeypatch
):
    """`--without-clips DATASET`: that page needs no checkpoint and says why it has no clip;
    another dataset's page still shows its clips (here kept from the earlier build)."""
    monkeypatch.setenv("MUJOCO_GL", "disable")
    monkeypatch.delenv("PYOPENGL_PLATFORM", raising=False)
    results = _write(tmp_path / "r", make_record)
    site = tmp_path / "site"
    _kept_site(site, load_records(results), "held 2.00 s of 2.00 s (kept)")
    for path, record in load_records(results):  # the same runs on the noisy dataset
        again = make_record(model=record.model.name, seed=record.seed, rmse=RMSE["gnn"])
        again["dataset"]["id"] = NOISY
        again["metrics"]["closed-loop"] = {"trained_on": NOISY, "pd_normalized_score": 0.5}
        write_record(again, results / f"noisy-{path.name}")
    left_out = invoke(
        "leaderboard", "--results", results, "--html", site, "--clips", "--without-clips", NOISY
    )
    assert left_out.exit_code == 0, left_out.output
    kept = (site / f"boards/hexa__{HEXA}.html").read_text()
    assert kept.count("held 2.00 s of 2.00 s (kept)") == 2
    page = (site / f"boards/hexa__{NOISY}.html").read_text()
    section = page[page.index('<section id="clips">') :]
    section = section[: section.index("</section>")]
    assert "built without them" in section and "<img" not in section
    assert not list((site / "clips").glob(f"hexa__{NOISY}*"))
    # without the flag, the noisy page's missing checkpoints stop the build
    assert "no closed-loop checkpoint" in error_line(
        invoke("leaderboard", "--results", results, "--html", site, "--clips"), 1
    )


def test_without_clips_names_a_dataset_of_the_board(tmp_path, make_record):
    results = _write(tmp_path / "r", make_record)
    args = ("leaderboard", "--results", results, "--html", tmp_path / "site")
    assert error_line(invoke(*args, "--clips", "--without-clips", "hexa-nothing"), 1) == (
        "Error: --without-clips hexa-nothing: no board page of that dataset"
    )
    assert "--without-clips needs --clips" in error_line(invoke(*args, "--without-clips", HEXA), 2)


def test_clips_need_the_site(tmp_path, make_record):
    result = invoke("leaderboard", "--results", _write(tmp_path / "r", make_record), "--clips")
    assert "--clips and --clips-from need --html" in error_line(result, 2)


def test_a_site_without_clips_has_no_clip_section(site):
    page = (site / f"boards/hexa__{HEXA}.html").read_text()
    assert 'id="clips"' not in page and not (site / "clips").exists()


# --- slow: real models, rendered ---------------------------------------------------------

MODELS = ("sdnn", "ffnn")


@pytest.fixture(scope="module")
def trained(tmp_path_factory) -> Iterator[Path]:
    """Results of tiny sdnn and ffnn models on hexa's smoke preset with the closed loop, in a
    private home (its smoke datasets simulated there)."""
    from symbench.core.runs.runner import RunSpec, run

    folder = tmp_path_factory.mktemp("clips")
    before = os.environ.get("SYMBENCH_HOME")
    os.environ["SYMBENCH_HOME"] = str(folder / "home")
    try:
        for model in MODELS:
            spec = RunSpec(
                model=model,
                robot="hexa",
                preset="smoke",
                evaluators=("torque-error", "closed-loop"),
                output=folder / "results",
                progress=False,
                workers=1,
                max_steps=20,
            )
            run(spec)
        yield folder
    finally:
        if before is None:
            del os.environ["SYMBENCH_HOME"]
        else:
            os.environ["SYMBENCH_HOME"] = before


def _build(folder: Path, site: Path) -> subprocess.CompletedProcess:
    """`symbench leaderboard --html SITE --clips` as a user runs it: MUJOCO_GL unset."""
    environment = {
        k: v for k, v in os.environ.items() if k not in ("MUJOCO_GL", "PYOPENGL_PLATFORM")
    }
    environment["SYMBENCH_HOME"] = str(folder / "home")
    command = [Path(sys.executable).parent / "symbench", "leaderboard", "--clips"]
    command += ["--results", folder / "results", "--html", site]
    return subprocess.run(command, env=environment, capture_output=True, text=True)


@pytest.mark.slow
def test_the_clip_model_is_the_records(trained):
    """Loaded from its checkpoint, the closed loop's model tracks the evaluator's references
    exactly as it did in the run."""
    from symbench.core.board.site.clips import closed_loop_model, closed_loop_setup
    from symbench.core.data.dataset import load_dataset

    for path, record in load_records(trained / "results"):
        metrics = record.metrics["closed-loop"]
        dataset = load_dataset(record.dataset.id)
        model = closed_loop_model(path, record, trained / "results").load()
        setup = closed_loop_setup(record, dataset)
        results = setup.track_model(model.predict, model.entry.view, setup.references)
        at_headline = [results[setup.job(i, setup.headline)] for i in range(len(setup.references))]
        held = [r.time_to_failure_s for r in at_headline]
        rmse = [r.joint_rmse_rad for r in at_headline]
        assert float(np.mean(held)) == pytest.approx(metrics["pd_time_to_failure_s"], rel=1e-12)
        assert float(np.mean(rmse)) == pytest.approx(metrics["pd_joint_rmse_rad"], rel=1e-12)


@pytest.mark.slow
def test_a_checkpoint_that_is_not_the_judged_network_is_refused(trained, tmp_path):
    """The same model trained again elsewhere differs in its last bits: one weight moved."""
    import shutil

    from symbench.core.board.site.clips import closed_loop_model, judged_model

    results = shutil.copytree(trained / "results", tmp_path / "results")
    path, record = next((p, r) for p, r in load_records(results) if r.model.name == "sdnn")
    assert judged_model(path, record, results).sha256() == shows(record)["checkpoint_sha256"]
    stored = closed_loop_model(path, record, results)
    model = stored.load()
    name = sorted(model.params)[0]
    model.params[name] = model.params[name] + np.float32(1e-6)
    model.save(stored.folder)
    with pytest.raises(SymbenchError, match="is not the network it judged"):
        judged_model(path, record, results)


@pytest.mark.slow
def test_clips_are_rendered_encoded_and_shown(trained, tmp_path):
    from symbench.core.sim.tracking.render import frame_times

    ensure_osmesa()
    done = _build(trained, tmp_path / "site")
    assert done.returncode == 0, done.stderr[-3000:]
    page = (tmp_path / "site" / f"boards/hexa__{HEXA}.html").read_text()
    clips = sorted((tmp_path / "site" / "clips").glob("*.webp"))
    assert len(clips) == 2  # the best and the worst of two models
    records = {r.model.name: r for _, r in load_records(trained / "results")}
    for clip in clips:  # each with the sidecar that names what it shows
        sidecar = json.loads(clip.with_suffix(".json").read_text())
        assert sidecar["shows"] == shows(records[clip.stem.rsplit("-", 1)[1]])
        assert sidecar["caption"] in " ".join(html.unescape(page).split())
    for clip in clips:
        model = clip.stem.rsplit("-", 1)[1]
        assert f'src="../clips/{clip.name}"' in page
        image = Image.open(io.BytesIO(clip.read_bytes()))
        assert image.format == "WEBP" and image.size == (640, 240)
        assert image.n_frames == len(frame_times(1.0))  # the whole smoke climb
        assert clip.stat().st_size < 1_000_000
        held = records[model].metrics["closed-loop"]["pd_time_to_failure_s"]
        assert f"held {held:.2f} s of 1.00 s" in page  # one reference in smoke
    again = _build(trained, tmp_path / "again")
    assert again.returncode == 0, again.stderr[-3000:]
    for clip in clips:  # another process, the same bytes
        assert (tmp_path / "again" / "clips" / clip.name).read_bytes() == clip.read_bytes()
