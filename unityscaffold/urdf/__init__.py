"""urdf stage: a robot's URDF, read exactly, and turned into what ROS#'s importer would build.

``import_robot`` is the stage: the URDF read into the frozen model of ``model`` (all problems
of a file reported at once, each at its line and column), its ``package://`` and
``$(find pkg)`` meshes found, and the result: the GameObjects with their components and fields
(``objects``), and the asset files (materials, STL meshes). ``read_urdf`` and
``resolve_meshes`` are its first steps on their own. The stage is pure: it reads and returns
values, which ``apply`` is to consume (see ``docs/architecture.md``).
"""

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
