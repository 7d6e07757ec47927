"""A ``robots:`` entry: a URDF put into a scene as ROS#'s importer would, kept as declared."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from unityscaffold.manifest.locations import Locations

__all__ = ["RobotEntry"]


@dataclass(frozen=True, slots=True)
class RobotEntry:
    """One robot. ``urdf`` and the ``packages`` folders are absolute; ``gameobject`` and
    ``assets`` are None until the URDF names the robot (their defaults are the robot's name
    and ``Assets/Urdf/<robot name>``). ``kinematic``, ``gravity`` and ``convex`` are the
    UrdfRobot inspector's switches, None for what the importer sets; ``plugin_newline`` is
    the newline of the plugin texts (``\\r\\n``, as ROS#'s importer writes them on Windows);
    ``args`` are the xacro arguments of a ``.xacro`` ``urdf``, and ``env`` the values its
    ``$(env VAR)`` and ``$(optenv VAR)`` take (the machine's environment is never read)."""

    urdf: Path
    scene: str
    locations: Locations
    gameobject: str | None = None
    packages: tuple[tuple[str, Path], ...] = ()
    assets: str | None = None
    position: tuple[float, float, float] | None = None
    rotation: tuple[float, float, float] | None = None
    kinematic: bool | None = None
    gravity: bool | None = None
    convex: bool | None = None
    plugin_newline: str = "\r\n"
    args: tuple[tuple[str, str], ...] = ()  # xacro arguments, for a .xacro ``urdf``
    env: tuple[tuple[str, str], ...] = ()  # xacro's environment variables, likewise
