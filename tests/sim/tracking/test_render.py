"""Clips of a climb: `track`'s observe hook records without changing what it computes, and
the renderer draws the recorded states into frames and an animated WebP.

Rendering needs MUJOCO_GL=osmesa before mujoco is first imported, and the test suite runs
with MUJOCO_GL=disable (Makefile), so the frames are made in a child process; a machine
without the OSMesa library gets it installed (tests/system_packages.py), or fails, never skips."""

from __future__ import annotations

import io
import itertools
import json
import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
from PIL import Image
from system_packages import ensure_osmesa

from symbench.core.common.errors import SymbenchError
from symbench.core.config.presets import preset
from symbench.core.robot.specs import load_robot
from symbench.core.sim.scene.scenario import Scenario
from symbench.core.sim.tracking.learned_control import expert_reference, track
from symbench.core.sim.tracking.references import oracle_policy
from symbench.core.sim.tracking.render import Recording

SECONDS, FPS = 0.5, 10  # 6 frames of the smoke climb's first half second

CHILD = """
import json, sys
from dataclasses import replace
from pathlib import Path
from symbench.core.sim.tracking.render import use_software_gl
use_software_gl()
import numpy as np
from symbench.core.robot.specs import load_robot
from symbench.core.sim.tracking.learned_control import expert_reference, track
from symbench.core.sim.tracking.references import oracle_policy
from symbench.core.sim.tracking.render import (
    ClimbRenderer, Recording, frame_times, labelled, side_by_side, webp,
)
from symbench.core.sim.scene.scenario import Scenario

fields, fps, out = json.loads(sys.argv[1]), int(sys.argv[2]), Path(sys.argv[3])
scenario = Scenario.from_dict(fields)
reference = expert_reference(scenario).arrays
control = load_robot(scenario.robot).control
recording = Recording()
track(scenario, reference, oracle_policy(reference), (0.1 * control.kp, 0.1 * control.kd),
      observe=recording)
renderer = ClimbRenderer(scenario)
camera = renderer.camera(reference["base_pos"])
times = frame_times(scenario.seconds, fps)
poses = recording.at(times, renderer.initial)
frames = renderer.frames(poses, camera)
again = renderer.frames(poses, camera)
renderer.close()
pairs = [side_by_side(labelled(f, "expert", f"t = {t:.2f} s"), labelled(f, "model", "", True))
         for f, t in zip(frames, times)]
np.savez(out / "frames.npz", frames=np.stack(frames), again=np.stack(again))
(out / "clip.webp").write_bytes(webp(pairs, fps))
(out / "again.webp").write_bytes(webp(pairs, fps))
"""


def _smoke_scenario(seconds: float) -> dict:
    spec = load_robot("hexa")
    first = preset("smoke").scenarios("hexa", spec.n_legs, spec.group.rotation_order)[0]
    return {**first.to_dict(), "seconds": seconds}


@pytest.fixture(scope="module")
def rendered(tmp_path_factory) -> Path:
    """The child's frames and clips of the smoke climb, rendered with OSMesa."""
    ensure_osmesa()
    out = tmp_path_factory.mktemp("render")
    env = {**os.environ, "MUJOCO_GL": "osmesa", "PYOPENGL_PLATFORM": "osmesa"}
    arguments = [json.dumps(_smoke_scenario(SECONDS)), str(FPS), str(out)]
    done = subprocess.run(
        [sys.executable, "-c", CHILD, *arguments], env=env, capture_output=True, text=True
    )
    assert done.returncode == 0, done.stderr[-3000:]
    return out


def test_frames_show_the_robot_moving(rendered):
    with np.load(rendered / "frames.npz") as saved:
        frames, again = saved["frames"], saved["again"]
    assert frames.shape == (int(SECONDS * FPS) + 1, 240, 320, 3) and frames.dtype == np.uint8
    assert all(frame.std() > 10 for frame in frames)  # a scene, not a blank image
    for before, after in itertools.pairwise(frames):
        assert np.any(before != after)  # the robot moves between frames
    np.testing.assert_array_equal(frames, again)  # the same states give the same pixels


def test_the_clip_is_an_animated_webp_of_every_frame(rendered):
    data = (rendered / "clip.webp").read_bytes()
    assert data == (rendered / "again.webp").read_bytes()  # deterministic bytes
    assert len(data) < 200_000
    image = Image.open(io.BytesIO(data))
    assert image.format == "WEBP" and image.size == (640, 240)
    assert image.n_frames == int(SECONDS * FPS) + 1
    image.seek(image.n_frames - 1)
    image.load()


def test_the_observe_hook_changes_nothing_that_track_computes():
    scenario = Scenario.from_dict(_smoke_scenario(1.0))
    reference = expert_reference(scenario).arrays
    control = load_robot("hexa").control
    gains = (0.1 * control.kp, 0.1 * control.kd)
    oracle = oracle_policy(reference)

    def floor(rows):
        return np.zeros_like(reference["tau"][0])

    for policy in (oracle, floor):  # one holds the climb, one fails
        recording = Recording()
        plain = track(scenario, reference, policy, gains)
        observed = track(scenario, reference, policy, gains, observe=recording)
        assert repr(observed) == repr(plain)  # bit for bit (repr: NaN equals NaN)
        # one state after every step taken, the last at the end (the failure's time)
        assert len(recording.times) == plain.steps
        assert recording.times[-1] == pytest.approx(plain.time_to_failure_s)
    assert not plain.attached  # the floor fell, so both branches ran


def test_a_recording_starts_at_the_initial_state_and_holds_its_last():
    recording = Recording([0.1, 0.2], [np.full(2, 1.0), np.full(2, 2.0)])
    poses = recording.at(np.array([0.0, 0.1, 0.15, 0.2, 0.5]), np.zeros(2))
    assert [p[0] for p in poses] == [0.0, 1.0, 1.0, 2.0, 2.0]


def test_no_gl_backend_is_one_line_naming_the_fix(monkeypatch):
    import mujoco

    from symbench.core.sim.tracking import render

    def unavailable(*args, **kwargs):
        raise AttributeError("module 'mujoco.gl_context' has no attribute 'GLContext'")

    monkeypatch.setattr(mujoco, "Renderer", unavailable)
    with pytest.raises(SymbenchError, match="MUJOCO_GL=osmesa.*apt-get install -y libosmesa6"):
        render.ClimbRenderer(Scenario.from_dict(_smoke_scenario(0.1)))
