"""An example symbench robot plugin: registers `penta`, a five-legged magnetic climber.

The robot is a folder, `penta/` (robot.toml and README.md), shipped inside this package as
package data and found with importlib.resources, so that it loads from a wheel as from an
editable install. symbench generates the MuJoCo model from the spec.
"""

from importlib.resources import files
from pathlib import Path

from symbench import RobotEntry, hookimpl


def spec_dir() -> Path:
    """The folder of penta's robot.toml inside the installed package."""
    return Path(str(files(__name__) / "penta"))


@hookimpl
def symbench_robots() -> list:
    return [RobotEntry("penta", spec_dir(), "five-legged magnetic climber, hexa's legs, C5")]
