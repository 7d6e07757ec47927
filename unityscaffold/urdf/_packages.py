"""Where a ``<mesh filename>`` is: ``package://pkg/path`` and ``$(find pkg)/path``.

A package's folder comes from the map the caller gives (the manifest's ``packages:``); a
package not in it is looked for beside the URDF (``<urdf folder>/<pkg>``), which is where
ROS#'s importer looks. The file must exist and lie inside the project, so that an import is
reproducible from the repository alone.
"""

from __future__ import annotations

import re
from collections.abc import Iterable, Mapping
from dataclasses import dataclass
from pathlib import Path, PurePosixPath

from unityscaffold.errors import DiagnosticSink
from unityscaffold.urdf.model import Mesh, Robot

__all__ = ["ResolvedMesh", "resolve_mesh", "resolve_meshes"]

_URI_RE = re.compile(r"package://([^/]+)/(.+)|\$\(find ([^)\s]+)\)/(.+)")


@dataclass(frozen=True, slots=True)
class ResolvedMesh:
    """A mesh file: its package, its path inside the package (``meshes/arm.stl``, which is
    also where ROS# puts it under the robot's asset folder) and where it is on disk."""

    package: str
    relative: PurePosixPath
    path: Path


def resolve_mesh(
    mesh: Mesh,
    *,
    urdf: Path,
    packages: Mapping[str, Path],
    project: Path,
    sink: DiagnosticSink,
) -> ResolvedMesh | None:
    """The file ``mesh`` names, or None after adding the reason to ``sink``."""
    match = _URI_RE.fullmatch(mesh.filename)
    where = mesh.location
    if match is None:
        sink.error(
            where,
            f"mesh {mesh.filename!r} names no ROS package",
            hint="write package://<package>/<path> (or $(find <package>)/<path>)",
        )
        return None
    package = match.group(1) or match.group(3)
    relative = PurePosixPath(match.group(2) or match.group(4))
    # the path inside the package is also where the mesh's assets go under the robot's asset
    # folder: a '..' would put them beside it, or outside the project
    if package in (".", "..") or ".." in relative.parts:
        sink.error(
            where,
            f"mesh {mesh.filename!r} steps out of its package with '..'",
            hint="name the mesh by its package and a path inside it: package://<package>/<path>",
        )
        return None
    folder = _package_folder(package, urdf, packages)
    if folder is None:
        known = ", ".join(sorted(packages)) or "none"
        sink.error(
            where,
            f"mesh {mesh.filename!r}: no folder for package {package!r}",
            hint=f"add {package}: <folder> to the packages map (given: {known}) "
            f"or put the package beside the URDF",
        )
        return None
    path = (folder / relative).resolve()
    if not _inside(path, project.resolve()):
        sink.error(
            where,
            f"mesh {mesh.filename!r} is outside the project: {path}",
            hint=f"keep meshes inside {project.resolve()} so the import is reproducible",
        )
        return None
    if not path.is_file():
        sink.error(
            where,
            f"mesh {mesh.filename!r}: no file {path}",
            hint=f"check the path inside package {package!r} ({folder})",
        )
        return None
    return ResolvedMesh(package, relative, path)


def resolve_meshes(
    robot: Robot, *, urdf: Path, packages: Mapping[str, Path], project: Path
) -> dict[str, ResolvedMesh]:
    """Every mesh filename of ``robot`` → its file; all problems in one ``LocatedError``."""
    sink = DiagnosticSink()
    found: dict[str, ResolvedMesh] = {}
    for mesh in _meshes(robot):
        if mesh.filename in found:
            continue
        resolved = resolve_mesh(mesh, urdf=urdf, packages=packages, project=project, sink=sink)
        if resolved is not None:
            found[mesh.filename] = resolved
    sink.raise_if_errors()
    return found


def _meshes(robot: Robot) -> Iterable[Mesh]:
    for link in robot.links:
        for geometry in [v.geometry for v in link.visuals] + [c.geometry for c in link.collisions]:
            if isinstance(geometry, Mesh):
                yield geometry


def _package_folder(package: str, urdf: Path, packages: Mapping[str, Path]) -> Path | None:
    if package in packages:
        return packages[package]
    beside = urdf.parent / package
    return beside if beside.is_dir() else None


def _inside(path: Path, folder: Path) -> bool:
    return path == folder or folder in path.parents
