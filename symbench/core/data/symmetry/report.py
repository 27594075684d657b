"""How symmetric a dataset is: `symbench data symmetry ID`.

**Image pairs.** Trajectory B is the image of trajectory A under a rotation g of the robot's
group when B's scenario is A's with every field mapped by g the way the simulator builds a
twin (`symbench.core.sim.scene.setup.turn_gait`, the one map that `Climb.turned` uses): the
yaw grows by g's angle (a multiple of 360 / rotation order degrees), the body step direction
turns back by it, the leg order is relabelled by g's leg permutation, and slope, heading,
seed and the other fields stay. Then B is A seen with turned base axes and relabelled legs:
`act_on_raw(g, A)` relabels A's legs and turns its base axes the way B's are turned; on a
perfectly symmetric robot it equals B. Reflections are not paired (no scenario field says
that one climb is another's mirror image).

**How the scenario is read.** A generated dataset stores the simulator's input: its
direction and leg order are those of the yaw's first symmetry sector, which the simulator
turns with the base (`scenario_gait`, as `Climb.from_scenario` does), so two scenarios that
differ only in yaw by g's angle are images. An imported log stores what the robot did
(`recorded`): the leg order in which its legs stepped and the base-frame direction it
stepped in, mapped by g as they are. An imported dataset with no image pair read so but some
read as the simulator's input (an export of a generated dataset) is read as the simulator's;
the report says which reading it used.

**Alignment.** Two logs of one motion may start at different phases of the gait (one logger
started earlier). Each pair (images and repeats) is aligned on its lift-offs (a row where a
leg's magnet flag, else its contact flag, drops from 1 to 0): among the shifts that put the
first lift-off of a leg in one log on a lift-off of the same leg in the other (and no
shift), the one whose flags then differ in the fewest rows, ties to the smallest shift, is
kept when the flags differ in at most `ALIGN_TOLERANCE` of the rows both then have (at least
half the shorter log). Otherwise the pair could not be aligned: it is compared row by row
and the report says so. Without known flags every pair is compared row by row.

**The error after relabelling**, per column, is the RMS of `g . A - B` over the pairs'
aligned rows (quaternions up to sign), relative to the column's RMS in B. Columns are
gathered into groups: joint states (q, qd, qdd), torques (tau) and base (position,
orientation, velocities, acceleration); a group's relative error is the RMS of its columns'
relative errors. Contact and magnet flags are compared as the share of rows where a flag
differs.

**The noise floor** is what two recordings of the same scenario would differ by:

- `repeats`: when some scenario appears more than once (a real robot's repeated runs), the
  RMS difference between repeats (aligned like the images), per column;
- `high-frequency`: otherwise, the dataset's own sampling noise: per scalar channel, the
  noise sigma estimated from third differences (white noise of sigma gives third differences
  of variance 20 sigma^2; a robust scale, 1.4826 x median absolute deviation, ignores the
  rare jumps at contact changes), times sqrt(2) for the difference of two recordings. A
  smooth signal's own third differences count as noise here, so this floor is an upper
  bound on the sampling noise.

A floor from repeats tells nothing when the repeats are not one motion: when some repeat
pair could not be aligned (their flags say they step differently), or when a group's floor
is at least its image error and at least `UNINFORMATIVE_FLOOR` of the signal (repeats that
differ as much as images, and as much as the signal itself). Then no verdict is given; the
report names the scenario fields the dataset lacks that would tell the motions apart.

A dataset whose error is at the float-precision level (`FLOAT_PRECISION`) is exactly
symmetric (a generated dataset); one whose error is below an informative floor is symmetric
within its noise; anything above is a measurable asymmetry, reported as the ratio
error / floor.

**Constructed pairs.** A dataset of climbs drawn from continuous distributions (v7) holds
no image pairs. For a generated one they are then made on purpose
(`symbench.core.data.twins.symmetry_report`; with `--twins N` also when it holds some): N of
its climbs simulated again beside their images under every rotation of the group, and the
report says so (`constructed`).

The pieces: `pairing.py` finds the image and repeat pairs, `symbench.core.data.twins`
constructs them, `measure.py` compares them against the floor, `plot.py` draws the figure;
this module holds the report itself.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

from symbench.core.common.errors import SymbenchError
from symbench.core.data.symmetry.alignment import Alignment
from symbench.core.symmetry.groups import GroupElement

GROUPS: dict[str, tuple[str, ...]] = {
    "joint states": ("q", "qd", "qdd"),
    "torques": ("tau",),
    "base": ("base_pos", "base_quat", "base_linvel", "base_angvel", "base_linacc"),
}
FLAGS = ("contact", "magnet")
FLOAT_PRECISION = 1e-6  # relative error below this: symmetric up to rounding


class NoImagePairsError(SymbenchError):
    """No two trajectories of the dataset are images of each other: nothing to measure."""


@dataclass(frozen=True)
class Twins:
    """How a report's image pairs were constructed (the report's `constructed`)."""

    source: str  # the dataset whose climbs were simulated again
    dataset: str  # the derived dataset of originals and twins
    climbs: int  # climbs of the source simulated again, each with its twins
    of: int  # the source's climbs, among which they were evenly spaced
    step_deg: float  # the group's symmetry step: twin k's yaw is k steps further
    rotations: int  # twins per climb: one per rotation of the group but the identity
    reproduced: bool  # every original simulated again has the source's bytes
    found_none: bool = False  # the source holds no image pair (else they were asked for)

    def sentence(self) -> str:
        return (
            "image pairs constructed on purpose, not found"
            + (" (the dataset itself holds none)" if self.found_none else "")
            + f": {self.climbs} of the {self.of} climbs of {self.source}, evenly spaced, "
            f"simulated again beside their images under each of the group's {self.rotations} "
            f"rotations (the yaw turned by multiples of {self.step_deg:g} degrees), kept as "
            f"{self.dataset}; the originals simulated again "
            + ("match" if self.reproduced else "differ from")
            + " the source's files"
        )

    def to_dict(self) -> dict[str, Any]:
        return {
            "source": self.source,
            "dataset": self.dataset,
            "climbs": self.climbs,
            "of": self.of,
            "step_deg": self.step_deg,
            "rotations": self.rotations,
            "originals_reproduced": self.reproduced,
            "source_holds_none": self.found_none,
            "note": self.sentence(),
        }


@dataclass(frozen=True)
class Pair:
    """Trajectory `b` is trajectory `a` acted on by `element` (ids as in the dataset)."""

    a: int
    b: int
    element: GroupElement
    rows: int
    relative_error: dict[str, float]  # per column group
    alignment: Alignment = field(default_factory=Alignment)


@dataclass
class SymmetryReport:
    dataset: str
    robot: str
    group: str
    trajectories: int
    floor_source: str  # "repeats" or "high-frequency"
    pairs: list[Pair] = field(default_factory=list)
    repeats: int = 0  # pairs of trajectories of one scenario
    columns: dict[str, dict[str, float]] = field(default_factory=dict)
    groups: dict[str, dict[str, Any]] = field(default_factory=dict)
    flags: dict[str, float] = field(default_factory=dict)
    plot: str | None = None
    reading: str = "recorded"  # how the scenarios were read: "simulator" or "recorded"
    repeat_alignments: list[tuple[int, int, Alignment]] = field(default_factory=list)
    floor_note: str | None = None  # why the floor from repeats tells nothing, when it does not
    constructed: Twins | None = None  # how the pairs were made, when not found (`data.twins`)

    @property
    def unaligned(self) -> list[Pair]:
        return [p for p in self.pairs if not p.alignment.aligned]

    def to_dict(self) -> dict[str, Any]:
        return {
            "dataset": self.dataset,
            "robot": self.robot,
            "group": self.group,
            "trajectories": self.trajectories,
            "scenario_reading": self.reading,
            "image_pairs": len(self.pairs),
            "image_pairs_were": "found" if self.constructed is None else "constructed",
            "constructed": None if self.constructed is None else self.constructed.to_dict(),
            "repeat_pairs": self.repeats,
            "floor": self.floor_source,
            "floor_note": self.floor_note,
            "groups": self.groups,
            "columns": self.columns,
            "flag_mismatch": self.flags,
            "pairs": [
                {
                    "a": p.a,
                    "b": p.b,
                    "element": p.element.name,
                    "rows": p.rows,
                    "relative_error": p.relative_error,
                    "alignment": p.alignment.to_dict(),
                }
                for p in self.pairs
            ],
            "repeats": [
                {"a": a, "b": b, "alignment": al.to_dict()} for a, b, al in self.repeat_alignments
            ],
            "plot": self.plot,
        }


def verdict(relative_error: float, relative_floor: float, uninformative: str | None = None) -> str:
    """The verdict on a group; `uninformative` says why the floor tells nothing, if so."""
    if relative_error < FLOAT_PRECISION:
        return "exact (float precision)"
    if uninformative:
        return f"no verdict: {uninformative}"
    if relative_error <= relative_floor:
        return "within noise"
    if relative_floor <= 0:
        return "asymmetric (the floor is 0)"
    return f"asymmetric ({relative_error / relative_floor:.3g}x floor)"


def dataset_symmetry(dataset: Any) -> SymmetryReport:
    """The symmetry report of the image pairs `dataset`, a loaded `Dataset`, holds (its
    robot's group and leg frames). A generated dataset's scenarios are read as the
    simulator's input, an imported one's as recorded (see `pair_up`). Without image pairs: a
    `NoImagePairsError`, which for a generated dataset names the command that constructs
    some (`symbench.core.data.twins.symmetry_report` does)."""
    from symbench.core.data.storage.files import read_trajectory
    from symbench.core.data.symmetry.measure import measure

    spec = dataset.spec
    trajectories = {
        int(rec["id"]): read_trajectory(dataset.root / rec["file"], dataset.n_legs)
        for rec in dataset.metadata["trajectories"]
    }
    unknown = dataset.metadata.get("unknown_columns") or ()
    imported = dataset.metadata.get("source") == "imported"
    try:
        return measure(
            trajectories,
            dataset.scenarios,
            spec.group,
            dataset.frames,
            dataset.id,
            dataset.robot,
            unknown,
            reading="auto" if imported else "simulator",
            spec=spec,
        )
    except NoImagePairsError as exc:
        if imported:
            raise
        raise NoImagePairsError(
            f"{exc}; `symbench data symmetry {dataset.id}` constructs pairs on purpose by "
            "simulating some of its climbs again under each rotation (`--twins N`: N climbs)"
        ) from None
