"""A push on the robot's base: a constant external force over a short window of a climb.

The closed loop's perturbation (symbench/core/runs/closed_loop.py): the expert climbs each
reference pushed, and every row tracking it (oracle, floor, model) is pushed alike, at the
same physics steps. The expert's whole-body controller reacts to it; a learned feedforward
must carry the robot through states off the nominal climb, which its training data (the
noisy variant) covers. The force is given in the surface's frame, so that it means the same
on every slope: along the slope's downhill direction, across it, and off the surface.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class Push:
    """`force` (N: downhill, across the slope, off the surface) on the base's centre of mass
    during the physics steps from `start_s` for `duration_s`."""

    start_s: float
    duration_s: float
    force: tuple[float, float, float]

    def steps(self, dt: float) -> range:
        """The indices of the physics steps it acts on (step k runs from k dt to (k + 1) dt)."""
        start = int(round(self.start_s / dt))
        return range(start, start + max(1, int(round(self.duration_s / dt))))

    def world_force(self, normal: np.ndarray) -> np.ndarray:
        """The force in world coordinates on the surface of unit `normal` (on a floor or a
        ceiling, where no direction is downhill, `downhill` is world x)."""
        normal = np.asarray(normal, dtype=np.float64)
        down = np.array([0.0, 0.0, -1.0]) - normal * -normal[2]
        if np.linalg.norm(down) < 1e-9:
            down = np.array([1.0, 0.0, 0.0]) - normal * normal[0]
        down /= np.linalg.norm(down)
        across = np.cross(normal, down)
        a, b, c = self.force
        return a * down + b * across + c * normal

    def to_dict(self) -> dict[str, float | list[float]]:
        return {"start_s": self.start_s, "duration_s": self.duration_s, "force": list(self.force)}
