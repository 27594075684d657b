"""What one simulated trajectory is: robot, slope, start pose, gait and seed.

The scene: world z up, gravity (0, 0, -9.81) always. The climbing surface is a plane tilted
by `inclination_deg` (0 floor, 90 wall, 180 ceiling); `heading_deg` rotates the whole scene
(plane and robot start) about world z; `yaw_deg` is the base yaw about the surface normal,
relative to the slope (0: base x points up the slope).
"""

from __future__ import annotations

import math
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
    direction: str = "forward"
    leg_order: tuple[int, ...] | None = None
    seed: int = 0
    seconds: float = 10.0

    def __post_init__(self) -> None:
        if not 0.0 <= self.inclination_deg <= 180.0:
            raise SymbenchError(
                f"scenario: inclination_deg {self.inclination_deg} is outside 0..180"
            )
        for name in ("heading_deg", "yaw_deg", "seconds"):
            if not math.isfinite(getattr(self, name)):
                raise SymbenchError(f"scenario: {name} must be finite")
        if self.seconds <= 0:
            raise SymbenchError(f"scenario: seconds must be positive, got {self.seconds}")
        if self.direction not in DIRECTIONS:
            raise SymbenchError(
                f"scenario: direction '{self.direction}' is not one of {', '.join(DIRECTIONS)}"
            )
        if self.leg_order is not None:
            object.__setattr__(self, "leg_order", tuple(int(i) for i in self.leg_order))

    @property
    def direction_deg(self) -> float:
        return DIRECTIONS[self.direction]

    def to_dict(self) -> dict[str, Any]:
        d = asdict(self)
        d["leg_order"] = None if self.leg_order is None else list(self.leg_order)
        return d

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
