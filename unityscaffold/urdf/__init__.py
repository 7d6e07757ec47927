"""urdf stage: a robot's URDF, read exactly, and turned into what ROS#'s importer would build.

``import_robot`` is the stage: the URDF read into the frozen model of ``model`` (all problems
of a file reported at once, each at its line and column), its meshes found in their packages
(``package://``, ``$(find pkg)``, ``file://``, paths), and the result: the GameObjects with
their components and fields (``objects``), and the asset files (materials, STL meshes).
``read_urdf`` and ``resolve_meshes`` are its first steps on their own. The stage is pure: it
reads and returns values, which ``apply`` is to consume (see ``docs/architecture.md``).

The names below are imported on first use (``__getattr__``): apply's scene code imports the
value types of ``objects`` on every run, and a manifest without ``robots:`` should not pay for
loading the reader and the importer as well (see ``bench/bench_startup.py``).
"""

from __future__ import annotations

import importlib
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from unityscaffold.urdf._import import RobotImport, import_robot
    from unityscaffold.urdf._load import parse_urdf, read_urdf
    from unityscaffold.urdf._packages import ResolvedMesh, resolve_meshes
    from unityscaffold.urdf.model import Robot

__all__ = [
    "ResolvedMesh",
    "Robot",
    "RobotImport",
    "import_robot",
    "parse_urdf",
    "read_urdf",
    "resolve_meshes",
]

# name -> the module (in this package) that defines it
_HOMES = {
    "ResolvedMesh": "_packages",
    "Robot": "model",
    "RobotImport": "_import",
    "import_robot": "_import",
    "parse_urdf": "_load",
    "read_urdf": "_load",
    "resolve_meshes": "_packages",
}


def __getattr__(name: str) -> object:
    home = _HOMES.get(name)
    if home is None:  # a submodule, imported by the import system after this refusal
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    value = getattr(importlib.import_module(f"{__name__}.{home}"), name)
    globals()[name] = value
    return value
