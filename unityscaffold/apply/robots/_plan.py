"""The file half of the ``robots:`` section: each URDF imported once per plan (``urdf``
stage), and the asset files it makes (materials, STL meshes and prefabs, copied models and
their textures) with their ``.meta`` files.

The scene half (``_place``) places the same import into the robot's scene.
"""

from __future__ import annotations

import math
from collections.abc import Iterable
from dataclasses import dataclass
from pathlib import Path, PurePosixPath
from typing import TYPE_CHECKING

from unityscaffold.errors import LocatedError, located_at
from unityscaffold.fileout import DesiredFile
from unityscaffold.manifest.model import Manifest
from unityscaffold.manifest.robot_entry import RobotEntry
from unityscaffold.unity import AssetRef, InlineMap
from unityscaffold.unity.mesh import MESH_FILE_ID
from unityscaffold.unity.meta import folder_meta, meta_guid, native_format_meta

if TYPE_CHECKING:
    from unityscaffold.urdf import RobotImport

__all__ = ["PlannedRobot", "plan_robots"]

_MATERIAL_FILE_ID = 2100000  # a Material inside its .mat (class 21 × 100000)
_MAIN_OBJECT = {".mat": _MATERIAL_FILE_ID, ".asset": MESH_FILE_ID}


@dataclass(frozen=True, slots=True)
class PlannedRobot:
    """One ``robots:`` entry with its import: where the robot goes (``gameobject``), its asset
    folder (``assets``, project-relative), the files there, and the GUID of each asset by its
    path inside that folder (``Materials/blue.mat``)."""

    entry: RobotEntry
    imported: RobotImport
    gameobject: str
    assets: str
    files: tuple[DesiredFile, ...]  # regenerated freely; tracked in the lock
    metas: tuple[DesiredFile, ...]  # .meta files: written only if missing
    guids: dict[str, str]
    folders: tuple[str, ...] = ()  # the asset folders holding them, each with a .meta

    def notes(self) -> list[str]:
        """What the import warns of: the xacro's warnings, and each link whose inertia ROS#'s
        float32 closed forms turn into NaN (``urdf._inertia``), which the import keeps, as
        the editor's does, though Unity's physics cannot simulate such a link."""
        found = list(self.imported.robot.notes)
        for _, obj in self.imported.objects.walk():
            if any(_not_finite(c.field(n)) for c in obj.components for n in _INERTIA):
                found.append(
                    f"robot {self.gameobject}: link {obj.name}'s inertia tensor gives ROS#'s "
                    "importer NaN or infinite inertia values, as in Unity's editor (its "
                    "float32 closed forms cannot diagonalize it); Unity's physics cannot "
                    "simulate that link (see "
                    "https://github.com/Unity-Technologies/Unity-Robotics-Hub/issues/343): give "
                    "it a diagonal tensor or larger entries"
                )
        return found

    def asset_refs(self) -> dict[str, AssetRef]:
        """The native assets it writes (``.mat`` materials, Mesh ``.asset`` files) by project
        path, as a field refers to them: known from the plan, so that an ``objects:`` entry can
        name one on the apply that first writes it (its ``.meta`` is not on disk yet)."""
        copied = (asset.path for asset in self.imported.model_assets)  # a textured .mat
        native = [*self.imported.files, *(p for p in copied if PurePosixPath(p).suffix == ".mat")]
        return {
            f"{self.assets}/{relative}": AssetRef(
                _MAIN_OBJECT[PurePosixPath(relative).suffix], self.guids[relative], 2
            )
            for relative in native
        }


_INERTIA = ("m_InertiaTensor", "m_InertiaRotation")  # the Rigidbody's, from urdf._inertia


def _not_finite(value: object) -> bool:
    return isinstance(value, InlineMap) and not all(
        isinstance(v, float | int) and math.isfinite(v) for _, v in value.items
    )


def plan_robots(manifest: Manifest, salt: str) -> list[PlannedRobot]:
    planned = [_plan(manifest, entry, salt) for entry in manifest.robots]
    _refuse_shared_gameobjects(planned)
    _refuse_clashing_assets(planned, manifest.project_root)
    return planned


def _refuse_shared_gameobjects(planned: Iterable[PlannedRobot]) -> None:
    """Two robots at one GameObject would each rebuild it as its own on every apply (and
    ``--check`` would pass while both report updates); only the URDF knows the default name,
    so the manifest reader cannot see this."""
    first: dict[tuple[str, str], PlannedRobot] = {}
    for robot in planned:
        key = (robot.entry.scene, robot.gameobject)
        other = first.setdefault(key, robot)
        if other is not robot:
            raise LocatedError.at(
                robot.entry.locations.of("gameobject"),
                f"a second robot at GameObject '{robot.gameobject}' in {robot.entry.scene}",
                hint=f"the robot on line {other.entry.locations.item.line} is there already; "
                "give each robot its own `gameobject`",
            )


def _refuse_clashing_assets(planned: Iterable[PlannedRobot], root: Path) -> None:
    """Robots may share an asset folder (two of one URDF do) as long as they want the same
    files there; two materials of one name and different colours cannot both be written."""
    first: dict[Path, tuple[bytes, PlannedRobot]] = {}
    for robot in planned:
        for file in robot.files:
            content, other = first.setdefault(file.path, (file.content, robot))
            if content != file.content:
                raise LocatedError.at(
                    robot.entry.locations.of("assets"),
                    f"{file.path.relative_to(root).as_posix()} would differ from the one the "
                    f"robot on line {other.entry.locations.item.line} puts there",
                    hint="give each of these robots its own `assets` folder",
                )


def _check_inputs(entry: RobotEntry) -> None:
    """The URDF and the package folders the entry names exist."""
    if not entry.urdf.is_file():
        raise LocatedError.at(
            entry.locations.of("urdf"),
            f"URDF file {entry.urdf} not found",
            expected="a .urdf file, relative to the manifest",
            hint="the path is relative to the manifest's folder",
        )
    for name, folder in entry.packages:
        if not folder.is_dir():
            raise LocatedError.at(
                entry.locations.of("packages"),
                f"the folder of package {name}, {folder}, does not exist",
                hint="package folders are relative to the manifest's folder",
            )


def _plan(manifest: Manifest, entry: RobotEntry, salt: str) -> PlannedRobot:
    from unityscaffold.urdf import import_robot  # loaded by manifests with robots only

    _check_inputs(entry)
    root = manifest.project_root
    with located_at(entry.locations.of("urdf")):
        imported = import_robot(
            entry.urdf,
            packages=dict(entry.packages),
            project=manifest.path.parent,
            plugin_newline=entry.plugin_newline,
            xacro_args=dict(entry.args),
            xacro_env=dict(entry.env),
        )
    _check_default_names(imported, entry)
    name = imported.robot.name
    assets = entry.assets or f"Assets/Urdf/{name}"
    files, metas, guids = [], [], {}
    for relative, text in imported.files.items():
        asset = f"{assets}/{relative}"
        guid = meta_guid(root / f"{asset}.meta", salt, asset)
        guids[relative] = guid
        main = _MAIN_OBJECT[PurePosixPath(relative).suffix]
        files.append(DesiredFile(root / asset, text.encode("utf-8")))
        # like a script's: an existing .meta keeps its GUID, so it is only ever created (and
        # pruned with its asset)
        meta = native_format_meta(guid, main).encode()
        metas.append(DesiredFile(root / f"{asset}.meta", meta, create_only=True))
    _model_files(imported, root, assets, salt, guids, files, metas)
    every = [*imported.files, *(model.path for model in imported.model_assets)]
    folders = _folders(assets, every)
    return PlannedRobot(
        entry,
        imported,
        entry.gameobject or name,
        assets,
        tuple(files),
        tuple(metas + _folder_metas(root, folders, salt)),
        guids,
        tuple(folders),
    )


# Unity refuses these in an asset's name on every platform
_NOT_IN_FOLDER_NAMES = frozenset('/\\:*?"<>|')


def _check_default_names(imported: RobotImport, entry: RobotEntry) -> None:
    """The robot's name, where it stands for what the entry leaves out: as the asset folder
    (``Assets/Urdf/<name>``), ``..``, ``.`` or a separator would put the files elsewhere (and
    the lock would refuse their paths on the next run); as the GameObject, ``/`` would make the
    robot the child of another object, and no name at all is no path."""
    name = imported.robot.name
    unusable = []
    if entry.gameobject is None and (not name or "/" in name):
        unusable.append(("a GameObject name", "`gameobject`"))
    bad = {c for c in name if c in _NOT_IN_FOLDER_NAMES or not c.isprintable()}
    if entry.assets is None and (bad or not name.strip(". ")):
        unusable.append(("a folder name under Assets/Urdf", "`assets`"))
    if unusable:
        raise LocatedError.at(
            imported.robot.location,
            f"the robot's name {name!r} is not usable as "
            + " or ".join(what for what, _ in unusable),
            hint="rename the robot, or give its manifest entry "
            + " and ".join(key for _, key in unusable)
            + f" (line {entry.locations.item.line})",
        )


def _model_files(
    imported: RobotImport,
    root: Path,
    assets: str,
    salt: str,
    guids: dict[str, str],
    files: list[DesiredFile],
    metas: list[DesiredFile],
) -> None:
    """The STL prefabs, the copied models and their textures (``RobotImport.model_assets``):
    every GUID first, as a prefab names its Mesh assets by theirs."""
    for model in imported.model_assets:
        asset = f"{assets}/{model.path}"
        guids[model.path] = meta_guid(root / f"{asset}.meta", salt, asset)
    for model in imported.model_assets:
        asset = f"{assets}/{model.path}"
        files.append(DesiredFile(root / asset, model.content(guids.__getitem__)))
        meta = model.meta(guids[model.path]).encode()
        metas.append(DesiredFile(root / f"{asset}.meta", meta, create_only=True))


def _folders(assets: str, files: Iterable[str]) -> list[str]:
    """Each folder on the way to the files, below ``Assets``."""
    folders: set[str] = set()
    for relative in files:
        parts = f"{assets}/{relative}".split("/")[:-1]
        folders.update("/".join(parts[: i + 1]) for i in range(1, len(parts)))
    return sorted(folders)


def _folder_metas(root: Path, folders: Iterable[str], salt: str) -> list[DesiredFile]:
    """A ``.meta`` for each folder, made once (Unity would make them itself, with random
    GUIDs)."""
    metas = []
    for folder in folders:
        guid = meta_guid(root / f"{folder}.meta", salt, folder)
        metas.append(
            DesiredFile(root / f"{folder}.meta", folder_meta(guid).encode(), create_only=True)
        )
    return metas
