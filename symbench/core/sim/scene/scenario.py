"""What one simulated trajectory is: robot, slope, start pose, gait and seed.

The scene: world z up, gravity (0, 0, -9.81) always. The climbing surface is a plane tilted
by `inclination_deg` (0 floor, 90 wall, 180 ceiling); `heading_deg` rotates the whole scene
(plane and robot start) about world z; `yaw_deg` is the base yaw about the surface normal,
relative to the slope (0: base x points up the slope).

`torque_noise` (N m, default 0) perturbs the expert's execution for data meant for control
(DART-style): Gaussian noise of this standard deviation is added to every joint's servo
command at every control step, seeded from the scenario (`noise_seed`); the recorded torque
stays the expert's own command at the perturbed state. 0 leaves the rollout untouched and
the field out of `to_dict`, so noise-free datasets store what they always did.

`gait_spread` (default 0) makes every step of the climb its own (dataset v7, as the paper
sampled them): each step's swing height and goal offset are drawn around the robot's nominal
values, uniformly within +-`gait_spread` of the nominal swing height and of the step length
(along and across the step direction), from a stream seeded by the climb's `seed`. 0 is the
fixed gait of earlier datasets and is left out of `to_dict` likewise. `direction` is a named
body direction or, for data drawn from continuous distributions, an angle in degrees.
"""

from __future__ import annotations

import json
import math
import zlib
from dataclasses import asdict, dataclass, fields
from typing import Any

from symbench.core.common.errors import SymbenchError

# Step direction in the body frame, as an angle from the base x axis (counter-clockwise).
DIRECTIONS: dict[str, float] = {"forward": 0.0, "left": 90.0, "backward": 180.0, "right": -90.0}


@dataclass(frozen=True)
class Scenario:
    robot: str
    inclination_deg: float = 0.0
    heading_deg: float = 0.0
    yaw_deg: float = 0.0
    direction: str | float = "forward"  # a name of DIRECTIONS, or degrees from the base x axis
    leg_order: tuple[int, ...] | None = None
    seed: int = 0
    seconds: float = 10.0
    torque_noise: float = 0.0  # N m, std of the noise on the executed servo command
    gait_spread: float = 0.0  # relative half-width of each step's swing height and goal draws

    def __post_init__(self) -> None:
        if not 0.0 <= self.inclination_deg <= 180.0:
            raise SymbenchError(
                f"scenario: inclination_deg {self.inclination_deg} is outside 0..180"
            )
        for name in ("heading_deg", "yaw_deg", "seconds", "torque_noise", "gait_spread"):
            if not math.isfinite(getattr(self, name)):
                raise SymbenchError(f"scenario: {name} must be finite")
        if self.seconds <= 0:
            raise SymbenchError(f"scenario: seconds must be positive, got {self.seconds}")
        if self.torque_noise < 0:
            raise SymbenchError(
                f"scenario: torque_noise must not be negative, got {self.torque_noise}"
            )
        if not 0.0 <= self.gait_spread < 1.0:
            raise SymbenchError(f"scenario: gait_spread must be in [0, 1), got {self.gait_spread}")
        if isinstance(self.direction, bool) or not isinstance(self.direction, str | float | int):
            raise SymbenchError(
                f"scenario: direction {self.direction!r} is neither a name nor an angle"
            )
        if isinstance(self.direction, str) and self.direction not in DIRECTIONS:
            raise SymbenchError(
                f"scenario: direction '{self.direction}' is not one of {', '.join(DIRECTIONS)}"
            )
        if not isinstance(self.direction, str):
            if not math.isfinite(self.direction):
                raise SymbenchError("scenario: direction must be finite")
            object.__setattr__(self, "direction", float(self.direction))
        if self.leg_order is not None:
            object.__setattr__(self, "leg_order", tuple(int(i) for i in self.leg_order))

    @property
    def direction_deg(self) -> float:
        if isinstance(self.direction, str):
            return DIRECTIONS[self.direction]
        return self.direction

    def to_dict(self) -> dict[str, Any]:
        d = asdict(self)
        d["leg_order"] = None if self.leg_order is None else list(self.leg_order)
        for name in ("torque_noise", "gait_spread"):  # 0: stored as they always were
            if not d[name]:
                del d[name]
        return d

    def noise_seed(self) -> list[int]:
        """The seed of the torque noise: the scenario's seed and a CRC-32 of its fields, so
        every scenario of a grid draws its own noise, the same on every machine."""
        text = json.dumps(self.to_dict(), sort_keys=True, separators=(",", ":"))
        return [int(self.seed), zlib.crc32(text.encode())]

    @classmethod
    def from_dict(cls, d: dict[str, Any]) -> Scenario:
        known = {f.name for f in fields(cls)}
        unknown = sorted(set(d) - known)
        if unknown:
            raise SymbenchError(f"scenario: unknown field(s) {', '.join(unknown)}")
        if "robot" not in d:
            raise SymbenchError("scenario: missing field 'robot'")
        d = dict(d)
        if d.get("leg_order") is not None:
            d["leg_order"] = tuple(d["leg_order"])
        return cls(**d)
