"""urdf stage: a robot's URDF, read exactly, and turned into what ROS#'s importer would build.

``read_urdf`` follows URDF's grammar into the frozen model of ``model`` (all problems of a file
reported at once, each at its line and column); ``resolve_meshes`` finds the file a
``package://`` or ``$(find pkg)`` mesh names. The stage is pure: it reads and returns values;
``apply`` is to consume them (see ``docs/architecture.md``).
"""

from unityscaffold.urdf._load import parse_urdf, read_urdf
from unityscaffold.urdf._packages import ResolvedMesh, resolve_meshes
from unityscaffold.urdf.model import Robot

__all__ = ["ResolvedMesh", "Robot", "parse_urdf", "read_urdf", "resolve_meshes"]
