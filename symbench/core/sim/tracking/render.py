"""A climb on video: the states a tracked climb went through (`Recording`, the `observe`
hook of `track`), rendered offscreen by MuJoCo and encoded as an animated WebP, which
browsers play without plugins.

The scene is the climb's own MjSpec (`model.build_spec`) with a checkered wall, a coloured
base and a light added for the eye only: its joints are the simulated ones, so a recorded
qpos sets the pose. The camera is fixed for the whole clip (`climb_camera`), looking at the
wall along its normal, a little from above and aside, at the middle of a path of base
positions (the reference's), far enough to see the robot anywhere on it.

Rendering needs an OpenGL backend, which MuJoCo picks from MUJOCO_GL when it is first
imported: `use_software_gl()` chooses OSMesa (software: Debian package libosmesa6) unless
another was chosen, and must run before anything imports mujoco (symbench's simulator sets
MUJOCO_GL=disable when it loads first).
"""

from __future__ import annotations

import io
import os
from dataclasses import dataclass, field

import numpy as np
from PIL import Image, ImageDraw, ImageFont

from symbench.core.common.errors import SymbenchError
from symbench.core.sim.scene.scenario import Scenario

WIDTH, HEIGHT = 320, 240  # pixels of one view
FPS = 20  # frames a second of climb time: 50 ms a frame, exact in WebP's milliseconds
HOLD_S = 1.0  # the last frame stays this long before the clip loops
QUALITY = 70  # lossy WebP quality: a 2.6 s side-by-side clip stays well under 1 MB
WALL = ([0.62, 0.66, 0.70], [0.50, 0.54, 0.58])  # the wall's checker colours (5 cm squares)
BASE_RGBA = [0.90, 0.45, 0.10, 1.0]
VIEW_FROM = (0.35, 0.35)  # the camera's offset from the wall normal: upwards, sideways
MARGIN = 1.15  # the camera's distance: this much more than just fitting robot and path
WHITE, FAILED_RGB = (255, 255, 255), (255, 90, 70)  # the labels' colours


def use_software_gl() -> None:
    """Render with OSMesa unless MUJOCO_GL chose a backend; only before mujoco loads."""
    os.environ.setdefault("MUJOCO_GL", "osmesa")
    if os.environ["MUJOCO_GL"] == "osmesa":
        os.environ.setdefault("PYOPENGL_PLATFORM", "osmesa")


@dataclass
class Recording:
    """An `observe` hook for `track`: the time and qpos after every physics step."""

    times: list[float] = field(default_factory=list)
    qpos: list[np.ndarray] = field(default_factory=list)

    def __call__(self, physics) -> None:
        self.times.append(float(physics.data.time))
        self.qpos.append(physics.data.qpos.copy())

    def at(self, times: np.ndarray, initial: np.ndarray) -> list[np.ndarray]:
        """The recorded state at or before each time: `initial` before the first step,
        the last one after the end (a failed climb's clip holds its last state)."""
        index = np.searchsorted(np.asarray(self.times), times, side="right") - 1
        return [self.qpos[i] if i >= 0 else initial for i in index]


@dataclass(frozen=True)
class Camera:
    lookat: tuple[float, float, float]
    distance: float
    azimuth: float  # degrees, MuJoCo's free camera
    elevation: float


def frame_times(seconds: float, fps: int = FPS) -> np.ndarray:
    """The clip's frame times over a climb of `seconds`, its end included."""
    return np.arange(int(np.floor(seconds * fps + 1e-9)) + 1) / fps


class ClimbRenderer:
    """Frames of one scenario's climb from recorded states, WIDTH x HEIGHT each."""

    def __init__(self, scenario: Scenario, width: int = WIDTH, height: int = HEIGHT) -> None:
        import mujoco

        from symbench.core.sim.scene.setup import Climb
        from symbench.core.sim.scene.task import load_climb

        climb = Climb.from_scenario(scenario)
        env = load_climb(climb)
        env.reset()
        self.initial = env.physics.data.qpos.copy()  # where `track` starts too
        self.normal = np.asarray(climb.arena.normal, dtype=np.float64)
        self.model = _dressed(climb).compile()
        if self.model.nq != len(self.initial):
            raise SymbenchError("render: the dressed scene has other joints than the climb's")
        self.data = mujoco.MjData(self.model)
        self.reach = self._reach()
        self.renderer = _offscreen(self.model, width, height)

    def _reach(self) -> float:
        """How far the robot reaches from its base: the radius the camera must fit."""
        import mujoco

        self.data.qpos[:] = self.initial
        mujoco.mj_forward(self.model, self.data)
        robot = self.model.geom_bodyid > 0
        offsets = np.linalg.norm(self.data.geom_xpos[robot] - self.initial[:3], axis=1)
        return float(np.max(offsets + self.model.geom_rbound[robot]))

    def camera(self, base_path: np.ndarray) -> Camera:
        """Fixed on the middle of `base_path` (base positions, (n, 3)), along the wall's
        normal tilted by VIEW_FROM, seeing the robot anywhere on the path."""
        centre = 0.5 * (base_path.min(axis=0) + base_path.max(axis=0))
        radius = self.reach + float(np.max(np.linalg.norm(base_path - centre, axis=1)))
        up, side = VIEW_FROM
        sideways = np.cross([0.0, 0.0, 1.0], self.normal)
        back = self.normal + up * np.array([0.0, 0.0, 1.0]) + side * sideways
        back /= np.linalg.norm(back)
        half_fov = np.radians(self.model.vis.global_.fovy / 2)
        return Camera(
            (float(centre[0]), float(centre[1]), float(centre[2])),
            MARGIN * radius / float(np.tan(half_fov)),
            float(np.degrees(np.arctan2(-back[1], -back[0]))),
            float(np.degrees(np.arcsin(-back[2]))),
        )

    def frames(self, poses: list[np.ndarray], camera: Camera) -> list[np.ndarray]:
        """(height, width, 3) uint8 images of the robot at each qpos, seen by `camera`."""
        import mujoco

        view = mujoco.MjvCamera()
        view.type = mujoco.mjtCamera.mjCAMERA_FREE
        view.lookat[:] = camera.lookat
        view.distance, view.azimuth, view.elevation = (
            camera.distance,
            camera.azimuth,
            camera.elevation,
        )
        out = []
        # the first frame after the camera moved differs from the next ones in a few pixels
        # (Mesa): one is drawn and dropped, so that the same states give the same pixels
        for qpos in [*poses[:1], *poses]:
            self.data.qpos[:] = qpos
            mujoco.mj_forward(self.model, self.data)
            self.renderer.update_scene(self.data, camera=view)
            out.append(self.renderer.render().copy())
        return out[1:]

    def close(self) -> None:
        self.renderer.close()


def _dressed(climb):
    """The climb's MjSpec with a checkered wall, an orange base and a light."""
    import mujoco

    from symbench.core.sim.scene.mjcf import SURFACE, build_spec

    spec = build_spec(climb.spec, climb.arena)
    spec.add_texture(
        name="wall",
        type=mujoco.mjtTexture.mjTEXTURE_2D,
        builtin=mujoco.mjtBuiltin.mjBUILTIN_CHECKER,
        rgb1=WALL[0],
        rgb2=WALL[1],
        width=64,
        height=64,
    )
    material = spec.add_material(name="wall", texrepeat=[10, 10], texuniform=True)
    material.textures[mujoco.mjtTextureRole.mjTEXROLE_RGB] = "wall"
    spec.geom(SURFACE).material = "wall"
    spec.geom("base_shell").rgba = BASE_RGBA
    normal = climb.arena.normal
    spec.worldbody.add_light(
        pos=list(3.0 * normal),
        dir=list(-normal),
        type=mujoco.mjtLightType.mjLIGHT_DIRECTIONAL,
        castshadow=False,
    )
    return spec


def _offscreen(model, width: int, height: int):
    """MuJoCo's offscreen renderer, or a one-line error saying what the machine lacks."""
    import mujoco

    try:
        return mujoco.Renderer(model, height=height, width=width)
    except Exception as exc:
        backend = os.environ.get("MUJOCO_GL", "")
        raise SymbenchError(
            f"cannot render offscreen with MUJOCO_GL={backend!r} ({type(exc).__name__}: "
            f"{exc}); set MUJOCO_GL=osmesa before symbench loads MuJoCo, with the OSMesa "
            "library installed (Debian: apt-get install -y libosmesa6)"
        ) from None


def labelled(frame: np.ndarray, title: str, note: str = "", failed: bool = False) -> Image.Image:
    """`frame` with `title` at the top left and `note` at the bottom left (red: failed)."""
    image = Image.fromarray(frame)
    draw = ImageDraw.Draw(image)
    font = ImageFont.load_default(size=14)
    colour = FAILED_RGB if failed else WHITE
    for xy, text, fill in (((6, 4), title, WHITE), ((6, image.height - 20), note, colour)):
        draw.text(xy, text, fill=fill, font=font, stroke_width=2, stroke_fill=(0, 0, 0))
    return image


def side_by_side(left: Image.Image, right: Image.Image) -> Image.Image:
    both = Image.new("RGB", (left.width + right.width, max(left.height, right.height)))
    both.paste(left, (0, 0))
    both.paste(right, (left.width, 0))
    return both


def webp(frames: list[Image.Image], fps: int = FPS, hold_s: float = HOLD_S) -> bytes:
    """An animated, looping, lossy WebP of `frames`; the same frames give the same bytes."""
    if not frames:
        raise SymbenchError("webp: a clip needs at least one frame")
    step = round(1000 / fps)
    durations = [step] * (len(frames) - 1) + [max(step, round(1000 * hold_s))]
    out = io.BytesIO()
    frames[0].save(
        out,
        format="WEBP",
        save_all=True,
        append_images=frames[1:],
        duration=durations,
        loop=0,
        quality=QUALITY,
        method=4,  # 6 is 20x slower for 1% less
    )
    return out.getvalue()
