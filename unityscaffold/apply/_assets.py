"""A built-in component's asset fields (a MeshFilter's ``m_Mesh``, a MeshRenderer's
``m_Materials``): a manifest names the asset, apply writes the reference Unity keeps.

An asset is one of Unity's built-in resources by name (``Plane``, ``Default-Material``) or a
native asset in the project by its path (``Assets/Materials/Red.mat``, a Mesh ``.asset``): its
main object, whose fileID is its class ID times 100000, and the GUID of its ``.meta``.
"""

from __future__ import annotations

import re
from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import Path, PurePosixPath

from unityscaffold.errors import LocatedError, SourceLocation
from unityscaffold.manifest.model import EmptyReference, value_text
from unityscaffold.manifest.model import FieldValue as ManifestValue
from unityscaffold.unity.builtins import BUILTIN_MATERIALS, BUILTIN_MESHES
from unityscaffold.unity.meta import read_meta_guid
from unityscaffold.unity.values import AssetRef, FieldValue, ObjectRef

__all__ = ["asset_value"]

_HEADER_RE = re.compile(rb"^--- !u!(\d+) &(-?\d+)", re.M)


@dataclass(frozen=True, slots=True)
class _AssetClass:
    class_id: int
    suffix: str  # the extension of a native asset holding one
    builtins: dict[str, AssetRef]


_CLASSES = {
    "Mesh": _AssetClass(43, ".asset", BUILTIN_MESHES),
    "Material": _AssetClass(21, ".mat", BUILTIN_MATERIALS),
}


def asset_value(
    kind: str,
    value: ManifestValue,
    where: SourceLocation,
    field: str,
    project_root: Path,
    planned: Mapping[str, AssetRef],
) -> FieldValue:
    """``value`` (a name, a path, null, or a list of them for ``asset:Class[]``) as the
    references Unity stores; a located error for anything it cannot name. ``planned`` are the
    assets this apply writes (a robot's materials), by path: named by the plan's GUIDs, the
    same on the first apply, before they are on disk, as on every later one."""
    if kind.endswith("[]"):
        if not isinstance(value, tuple):
            raise _wrong(kind, value, where, field)
        return [asset_value(kind[:-2], item, where, field, project_root, planned) for item in value]
    if isinstance(value, EmptyReference):
        return ObjectRef(0)
    wanted = _CLASSES[kind.removeprefix("asset:")]
    if not isinstance(value, str) or not value:
        raise _wrong(kind, value, where, field)
    if value in wanted.builtins:
        return wanted.builtins[value]
    if not value.startswith(("Assets/", "Packages/")):
        raise _wrong(kind, value, where, field)
    if value in planned and value.endswith(wanted.suffix):
        return planned[value]
    return _project_asset(value, wanted, where, field, project_root)


def _wrong(kind: str, value: ManifestValue, where: SourceLocation, field: str) -> LocatedError:
    name = kind.removeprefix("asset:").removesuffix("[]")
    wanted = _CLASSES[name]
    many = "a list of " if kind.endswith("[]") else ""
    return LocatedError.at(
        where,
        f"{field} expects {many}{name} assets, not {value_text(value)}",
        expected=f"a built-in {name.lower()} ({', '.join(wanted.builtins)}), the path of a "
        f"{wanted.suffix} file in the project (Assets/…{wanted.suffix}), or null",
        hint=f"a {name.lower()} inside a model file (.fbx, .dae) is set in Unity",
    )


def _project_asset(
    path: str, wanted: _AssetClass, where: SourceLocation, field: str, project_root: Path
) -> AssetRef:
    parts = PurePosixPath(path).parts
    if ".." in parts or "\\" in path or not path.endswith(wanted.suffix):
        raise LocatedError.at(
            where,
            f"{field}: '{path}' is not a {wanted.suffix} file inside the project",
            hint=f"write the path from the project root, e.g. Assets/Meshes/Part{wanted.suffix}",
        )
    file = project_root.joinpath(*parts)
    try:
        head = file.read_bytes()[:4096]
    except OSError:
        raise LocatedError.at(
            where, f"{field}: no file {path} in the project", hint="check the path and its case"
        ) from None
    main = _HEADER_RE.search(head)
    if main is None or int(main.group(1)) != wanted.class_id:
        raise LocatedError.at(
            where,
            f"{field}: {path} holds no {next(k for k, v in _CLASSES.items() if v is wanted)}",
            hint="save the file from Unity with Asset Serialization set to Force Text",
        )
    guid = read_meta_guid(file.with_name(file.name + ".meta"))
    if guid is None:
        raise LocatedError.at(
            where,
            f"{field}: {path} has no .meta file, so no GUID to refer to it by",
            hint="open the project in Unity once so that it imports the file",
        )
    return AssetRef(int(main.group(2)), guid, 2)
