"""Which file a URDF filename names, and in which ROS package (``resolve_file``).

A package's folder comes from the map the caller gives (the manifest's ``packages:``); a
package not in it is looked for beside the URDF (``<urdf folder>/<pkg>``), which is where
ROS#'s importer looks. ``package://pkg/path`` and ``$(find pkg)/path`` name the package; a
``file://`` URI, an absolute path or a path relative to the URDF (``_uris``) names a file,
whose package is the one of those folders that holds it: it is then the same file, with the
same asset path under the robot's folder, as ``package://`` would name (ROS# 2.2.1 reads only
``package://`` and leaves other meshes out with a warning; its asset path is the package and
the path inside it, ``UrdfAssetPathHandler.GetRelativeAssetPathFromUrdfPath``). The file must
exist and lie inside the project, after symbolic links, so that an import is reproducible from
the repository alone.
"""

from __future__ import annotations

import os
import re
from collections.abc import Iterable, Mapping
from dataclasses import dataclass
from pathlib import Path, PurePosixPath

from unityscaffold.errors import DiagnosticSink, SourceLocation
from unityscaffold.urdf._uris import InPackage, OnDisk, Refused, parse_filename
from unityscaffold.urdf.model import Mesh, Robot

__all__ = ["ResolvedMesh", "resolve_file", "resolve_mesh", "resolve_meshes"]


@dataclass(frozen=True, slots=True)
class ResolvedMesh:
    """A file a URDF names (a mesh, a texture): its package, its path inside the package
    (``meshes/arm.stl``, which is also where ROS# puts it under the robot's asset folder) and
    where it is on disk (symbolic links followed)."""

    package: str
    relative: PurePosixPath
    path: Path


@dataclass(frozen=True, slots=True)
class _Lookup:
    """Where a robot's files are looked for."""

    urdf: Path
    packages: Mapping[str, Path]
    project: Path
    sink: DiagnosticSink
    kind: str

    def error(self, where: SourceLocation, filename: str, reason: str, hint: str) -> None:
        self.sink.error(where, f"{self.kind} {filename!r} {reason}", hint=hint)


def resolve_file(
    filename: str,
    where: SourceLocation,
    *,
    urdf: Path,
    packages: Mapping[str, Path],
    project: Path,
    sink: DiagnosticSink,
    kind: str = "mesh",
) -> ResolvedMesh | None:
    """The file a URDF's ``filename`` attribute (written at ``where``) names, for a robot
    read from ``urdf`` with the package folders ``packages``, inside ``project``: any form
    ``_uris`` reads. None after adding the reason to ``sink``, where ``kind`` (``mesh``,
    ``texture``) names what the file is."""
    look = _Lookup(urdf, packages, project, sink, kind)
    named = parse_filename(filename, urdf.parent.absolute())
    if isinstance(named, Refused):
        look.error(where, filename, named.reason, named.hint)
        return None
    if isinstance(named, OnDisk):
        return _on_disk(look, filename, where, named)
    package, relative = named.package, named.relative
    # the path inside the package is also where the file's assets go under the robot's asset
    # folder: a '..' would put them beside it, or outside the project
    if package in (".", "..") or ".." in relative.parts:
        look.error(
            where,
            filename,
            "steps out of its package with '..'",
            f"name the {kind} by its package and a path inside it: package://<package>/<path>",
        )
        return None
    folder = _package_folder(package, urdf, packages)
    if folder is None:
        known = ", ".join(sorted(packages)) or "none"
        look.error(
            where,
            filename,
            f"names package {package!r}, which has no folder",
            f"add {package}: <folder> to the packages map (given: {known}) "
            f"or put the package beside the URDF",
        )
        return None
    return _in_package(look, filename, where, InPackage(package, relative), folder)


def resolve_mesh(
    mesh: Mesh,
    *,
    urdf: Path,
    packages: Mapping[str, Path],
    project: Path,
    sink: DiagnosticSink,
) -> ResolvedMesh | None:
    """The file ``mesh`` names, or None after adding the reason to ``sink``."""
    return resolve_file(
        mesh.filename, mesh.location, urdf=urdf, packages=packages, project=project, sink=sink
    )


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


def _in_package(
    look: _Lookup, filename: str, where: SourceLocation, named: InPackage, folder: Path
) -> ResolvedMesh | None:
    """The file ``named`` in its package's ``folder``, if it is a file inside the project."""
    path = (folder / named.relative).resolve()
    if not _inside(path, look.project.resolve()):
        look.error(
            where,
            filename,
            f"is outside the project: {path}",
            f"keep the files a URDF names inside {look.project.resolve()} so the import is "
            "reproducible",
        )
        return None
    if not path.is_file():
        look.error(
            where,
            filename,
            f"names a file that does not exist: {path}",
            f"check the path inside package {named.package!r} ({folder})",
        )
        return None
    return ResolvedMesh(named.package, named.relative, path)


def _on_disk(
    look: _Lookup, filename: str, where: SourceLocation, named: OnDisk
) -> ResolvedMesh | None:
    """A file named by where it is, as its package names it."""
    real = named.path.resolve()
    project = look.project.resolve()
    if not _inside(real, project):
        look.error(
            where,
            filename,
            f"({named.form}) is outside the project: {real}",
            _installed_hint(named.path, look)
            or f"keep the files a URDF names inside {project} so the import is reproducible",
        )
        return None
    held = _holder(named.path, real, look)
    if held is None:
        look.error(
            where,
            filename,
            f"({named.form}) lies in none of this robot's packages, so it has no asset path "
            f"(looked in: {_looked_in(look, project)})",
            _add_package_hint(real, project, look.urdf),
        )
        return None
    return _in_package(look, filename, where, held[0], held[1])


def _installed_hint(path: Path, look: _Lookup) -> str | None:
    """For a path into a ROS install or devel space (``<prefix>/share/<package>/…``, where
    catkin and ament put a package's files) of one of the robot's packages, which is what a
    URDF expanded on another machine names: the ``package://`` of that file."""
    parts = path.parts
    for at in range(len(parts) - 3, -1, -1):
        name = parts[at + 1]
        if parts[at] == "share" and _package_folder(name, look.urdf, look.packages) is not None:
            inside = "/".join(parts[at + 2 :])
            return (
                f"it is package {name}'s file as installed on another machine: write "
                f"package://{name}/{inside}, or import the .xacro it was expanded from (its "
                f"$(find {name}) is then the package's folder in the repository)"
            )
    return None


def _holder(path: Path, real: Path, look: _Lookup) -> tuple[InPackage, Path] | None:
    """The package that holds the file at ``path`` (``real`` after symbolic links), and the
    package's folder: the deepest such folder, then the first name (folders may nest)."""
    candidates = dict(look.packages)
    beside = look.urdf.parent.absolute()
    if _inside(path, beside) and path != beside:
        first = path.relative_to(beside).parts[0]
        if first not in candidates and (beside / first).is_dir():
            candidates[first] = beside / first
    found: list[tuple[int, str, PurePosixPath, Path]] = []
    for name, folder in candidates.items():
        for there, inside in ((path, _normal(folder)), (real, folder.resolve())):
            if _inside(there, inside) and there != inside:
                relative = PurePosixPath(there.relative_to(inside).as_posix())
                found.append((-len(inside.parts), name, relative, folder))
                break
    if not found:
        return None
    _, name, relative, folder = min(found)
    return InPackage(name, relative), folder


def _package_folder(package: str, urdf: Path, packages: Mapping[str, Path]) -> Path | None:
    if package in packages:
        return packages[package]
    beside = urdf.parent / package
    return beside if beside.is_dir() else None


def _inside(path: Path, folder: Path) -> bool:
    return path == folder or folder in path.parents


def _normal(folder: Path) -> Path:
    return Path(os.path.normpath(folder.absolute()))


def _shown(folder: Path, project: Path) -> str:
    """``folder`` relative to the project (the manifest's folder) when it is inside it."""
    real = folder.resolve()
    return real.relative_to(project).as_posix() if _inside(real, project) else str(real)


def _looked_in(look: _Lookup, project: Path) -> str:
    listed = [
        f"{name} ({_shown(folder, project)})" for name, folder in sorted(look.packages.items())
    ]
    beside = _shown(look.urdf.parent, project)
    return ", ".join([*listed, f"any package folder beside the URDF ({beside}/<package>)"])


_PACKAGE_NAME = re.compile(rb"<name>\s*([^<\s]+)\s*</name>")


def _add_package_hint(path: Path, project: Path, urdf: Path) -> str:
    """What to add to ``packages`` for the file at ``path``: the ROS package (a folder with a
    ``package.xml``, named by its ``<name>``) that holds it; else the folder that holds both
    it and the URDF (``x_description`` of ``x_description/urdf/x.urdf`` and
    ``../meshes/base.stl``, the usual layout), named as itself."""
    for folder in path.parents:
        if not _inside(folder, project):
            break
        manifest = folder / "package.xml"
        if manifest.is_file():
            match = _PACKAGE_NAME.search(manifest.read_bytes())
            name = match[1].decode("utf-8", "replace") if match else folder.name
            return _package_hint(name, folder, path, project)
    common = Path(os.path.commonpath([path, urdf.parent.resolve()]))
    if _inside(common, project) and common != project:
        return _package_hint(common.name, common, path, project)
    return (
        "add the package that holds it to the entry's `packages` "
        "(<package>: <its folder, relative to the manifest>), or name it "
        "package://<package>/<path>"
    )


def _package_hint(name: str, folder: Path, path: Path, project: Path) -> str:
    return (
        f"add its package to the entry's `packages` ({name}: {_shown(folder, project)}, "
        f"relative to the manifest), or name it "
        f"package://{name}/{path.relative_to(folder).as_posix()}"
    )
