"""Is a registered robot's spec where its entry says? A plugin package whose wheel was built
without its robot folders as package data registers the robot all the same (the hook's code
is in the wheel), and only a robot.toml that is not there tells; the one-line problem names
the plugin and the `package-data` glob that ships every robot folder of a package.
"""

from __future__ import annotations

from pathlib import Path

from symbench.core.plugin import registry

PACKAGE_DATA = '[tool.setuptools.package-data] <package> = ["*/robot.toml", "*/README.md"]'


def unshipped(name: str) -> str:
    """'' when the registered robot `name` has its robot.toml, else what is wrong and how a
    plugin package fixes it, in one line."""
    path = Path(registry.robot(name).spec_dir) / "robot.toml"
    if path.is_file():
        return ""
    return (
        f"robot '{name}' of {registry.provider('robots', name)}: its spec {path} does not "
        "exist; a plugin package ships each robot folder as package data, which a wheel "
        f"leaves out unless its pyproject.toml says so: {PACKAGE_DATA}"
    )
