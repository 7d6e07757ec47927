"""The urdf stage's one entry point: a URDF file in, everything ROS#'s importer would make out."""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from functools import partial
from pathlib import Path, PurePosixPath
from typing import TypeVar

from unityscaffold.errors import DiagnosticSink, LocatedError
from unityscaffold.unity.prefabinstance import ModelInstance
from unityscaffold.urdf._assets import PlannedAsset
from unityscaffold.urdf._configurable import refuse_unchecked_joints
from unityscaffold.urdf._load import read_urdf
from unityscaffold.urdf._packages import ResolvedMesh, resolve_file, resolve_meshes
from unityscaffold.urdf.materials import importer_materials
from unityscaffold.urdf.model import Robot
from unityscaffold.urdf.models import model_plan
from unityscaffold.urdf.objects import ImportedObject, importer_tree
from unityscaffold.urdf.stl import stl_mesh_assets
from unityscaffold.urdf.textures import material_textures

__all__ = ["RobotImport", "import_robot"]

_T = TypeVar("_T")


@dataclass(frozen=True, slots=True)
class RobotImport:
    """What importing one URDF makes.

    ``objects`` is the GameObject tree; ``files`` maps paths relative to the robot's asset
    folder (``Materials/blue.mat``, ``<package>/meshes/arm_0.asset``) to their text, in sorted
    order; ``meshes`` maps each ``<mesh filename>`` to its file.

    ``models`` holds what each mesh geometry object (role ``MODEL``) is, by its key: the
    instance of a prefab or model to place there (``unity.prefabinstance``), whose source is
    one of ``model_assets``: the files that need the GUIDs of other assets to be written, or
    are copies (the STL prefabs and the copied ``.dae`` and ``.obj`` files, ``urdf.models``;
    the textures, ``urdf.textures``; and the ``.mat`` of each material of a texture,
    ``urdf.materials``).
    """

    robot: Robot
    objects: ImportedObject
    files: Mapping[str, str]
    meshes: Mapping[str, ResolvedMesh]
    models: Mapping[str, ModelInstance] = field(default_factory=dict)
    model_assets: tuple[PlannedAsset, ...] = ()


def import_robot(
    urdf: Path,
    *,
    packages: Mapping[str, Path],
    project: Path,
    plugin_newline: str = "\r\n",
    xacro_args: Mapping[str, str] | None = None,
    xacro_env: Mapping[str, str] | None = None,
) -> RobotImport:
    """Read ``urdf``, resolve its meshes against ``packages`` (inside ``project``) and build
    what ROS#'s importer would (a ``.xacro`` expanded with ``xacro_args``, its ``$(env)`` and
    ``$(optenv)`` answered by ``xacro_env``): every problem is a located error, and nothing is
    written."""
    robot = read_urdf(urdf, packages=packages, xacro_args=xacro_args, xacro_env=xacro_env)
    refuse_unchecked_joints(robot)
    sink = DiagnosticSink()  # the meshes', the textures' and the models' problems, together
    meshes = _collected(
        sink, lambda: resolve_meshes(robot, urdf=urdf, packages=packages, project=project)
    )
    materials = importer_materials(robot)
    files = {m.path: m.text() for m in materials if m.textured is None}
    find = partial(resolve_file, urdf=urdf, packages=packages, project=project, kind="texture")
    textured = tuple(material_textures(materials, find, sink))
    counts = _stl_files(meshes or {}, files)
    plan = None if meshes is None else _collected(sink, lambda: model_plan(robot, meshes, counts))
    sink.raise_if_errors()
    assert meshes is not None and plan is not None  # else an error was raised
    objects = importer_tree(robot, plugin_newline=plugin_newline)
    # a texture both a model and a material name is one file
    copied = {asset.path: asset for asset in (*plan.assets, *textured)}
    return RobotImport(
        robot,
        objects,
        dict(sorted(files.items())),
        meshes,
        plan.instances,
        tuple(copied[path] for path in sorted(copied)),
    )


def _collected(sink: DiagnosticSink, stage: Callable[[], _T]) -> _T | None:
    """``stage()``, or None after adding its located errors to ``sink``."""
    try:
        return stage()
    except LocatedError as error:
        sink.diagnostics.extend(error.diagnostics)
        return None


def _stl_files(
    meshes: Mapping[str, ResolvedMesh], files: dict[str, str]
) -> dict[ResolvedMesh, int]:
    """Each STL file's Mesh assets added to ``files``; how many each file was cut into."""
    counts: dict[ResolvedMesh, int] = {}
    for mesh in sorted(set(meshes.values()), key=lambda m: (m.package, str(m.relative))):
        if mesh.relative.suffix.lower() == ".stl":
            folder = PurePosixPath(mesh.package) / mesh.relative.parent
            assets = stl_mesh_assets(mesh.path, mesh.relative.stem)
            counts[mesh] = len(assets)
            for name, text in assets:
                files[str(folder / name)] = text
    return counts
