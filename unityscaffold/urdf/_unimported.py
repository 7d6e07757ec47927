"""Mesh files ROS#'s importer cannot make as checked here, and why: each reason says what
ROS# and Unity do with such a file, and the hint what a user can do instead."""

from __future__ import annotations

__all__ = ["refusal"]

_CONVERT = "convert the mesh to STL or COLLADA (.dae), which import as ROS# makes them"

# Formats Unity reads through its FBX SDK importer, axis system, unit and node transforms and all
_FBX_SDK = (".fbx", ".dxf", ".3ds")
# Formats only a Unity package reads (glTFast, UnityGLTF), which ROS# 2.2.1 does not use
_GLTF = (".gltf", ".glb")


def refusal(suffix: str) -> tuple[str, str]:
    """``(reason, hint)`` for a mesh file named ``…<suffix>`` (lower case, may be empty)."""
    if suffix in _FBX_SDK:
        return (
            f"ROS# instantiates the model Unity imports from a {suffix} file, whose root pose "
            "follows the file's axis system (its UpAxis, FrontAxis and CoordAxis settings), its "
            "unit (UnitScaleFactor) and its top nodes' transforms, and no Unity-written scene "
            "at hand shows the pose Unity 2022.3 gives it",
            _CONVERT,
        )
    if suffix in _GLTF:
        return (
            f"Unity 2022.3 imports {suffix} files only with a package (glTFast, UnityGLTF) "
            "that ROS# 2.2.1 does not use: ROS#'s importer finds no model at the mesh's path "
            "and leaves the geometry out",
            f"{_CONVERT}, or to OBJ for a visual without <material>",
        )
    kind = f"a {suffix} file" if suffix else "a file without extension"
    return (
        f"Unity 2022.3 imports no model from {kind} by itself (its own model formats are "
        ".fbx, .dae, .dxf and .obj; others need their 3D application installed): ROS#'s "
        "importer finds no model at the mesh's path and leaves the geometry out",
        _CONVERT,
    )
