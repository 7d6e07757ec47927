"""``scaffold init``: a new Unity project that ``scaffold apply`` can work on at once.

The files come from the package's ``templates/unity_project/`` (``*.jinja`` ones rendered),
the starter manifest from ``manifest.starter_manifest``. The project's ``productGUID`` (which
also salts the GUIDs of generated ``.meta`` files) is derived from the project's folder name,
so the same command gives the same files. The scene, its folder and
``ProjectSettings/EditorBuildSettings.asset`` (which lists the scene for builds) share GUIDs
derived from it, so Unity finds ``.meta`` files on first open instead of making random ones.
"""

from __future__ import annotations

import hashlib
import json
from pathlib import Path

from unityscaffold.apply._inside import check_inside
from unityscaffold.apply._rossharp import DEFAULT_VERSION
from unityscaffold.errors import UserError
from unityscaffold.fileout import DesiredFile, FileChange, plan_files, write_files
from unityscaffold.manifest import starter_manifest
from unityscaffold.resources import schema_text, template_environment, template_folder
from unityscaffold.unity.meta import folder_meta, guid_for

__all__ = ["MAIN_SCENE", "SCHEMA_FILE", "init_project"]

MAIN_SCENE = "Assets/Scenes/Main.unity"
#: The manifest's JSON Schema, copied beside robot.yaml for editors (the installed package's
#: copy is out of reach inside site-packages); ``scaffold schema -o`` refreshes it.
SCHEMA_FILE = "robot.schema.json"
_TEMPLATE_ROOT = "unity_project"
_RENAMES = {"gitignore": ".gitignore", "gitattributes": ".gitattributes"}


def _template_files(context: dict[str, str]) -> list[tuple[str, bytes]]:
    files = []
    for source, data in template_folder(_TEMPLATE_ROOT).items():
        if source.rsplit("/", 1)[-1] == "README.md":
            continue
        relative = _RENAMES.get(source, source)
        if relative == "ProjectSettings/EditorBuildSettings.asset.jinja":
            continue  # rendered with the scene's GUID by _scene_files
        if relative.endswith(".jinja"):
            template = template_environment().get_template(f"{_TEMPLATE_ROOT}/{source}")
            files.append((relative[: -len(".jinja")], template.render(**context).encode("utf-8")))
        else:
            files.append((relative, data))
    return files


def _scene_files(salt: str) -> list[tuple[str, bytes]]:
    """The ``.meta`` files of the scene and its folder, and the build settings listing it."""
    folder = MAIN_SCENE.rsplit("/", 1)[0]
    scene_guid = guid_for(salt, MAIN_SCENE)
    scene_meta = (
        f"fileFormatVersion: 2\nguid: {scene_guid}\nDefaultImporter:\n  externalObjects: {{}}\n"
        "  userData: \n  assetBundleName: \n  assetBundleVariant: \n"
    )
    build_settings = template_environment().get_template(
        f"{_TEMPLATE_ROOT}/ProjectSettings/EditorBuildSettings.asset.jinja"
    )
    return [
        (f"{folder}.meta", folder_meta(guid_for(salt, folder)).encode("utf-8")),
        (f"{MAIN_SCENE}.meta", scene_meta.encode("utf-8")),
        (
            "ProjectSettings/EditorBuildSettings.asset",
            build_settings.render(scene=MAIN_SCENE, guid=scene_guid).encode("utf-8"),
        ),
    ]


_PACKAGES = "Packages/manifest.json"
_ROSSHARP = "com.siemens.ros-sharp"


def _existing_scenes(directory: Path) -> list[str]:
    """The scenes a project already has, project-relative and sorted."""
    assets = directory / "Assets"
    if not assets.is_dir():
        return []
    return sorted(p.relative_to(directory).as_posix() for p in assets.rglob("*.unity"))


def _pinned_packages(directory: Path, template: bytes) -> DesiredFile | None:
    """An existing ``Packages/manifest.json`` with ROS# added, pinned as the template pins it;
    None when there is none or it already names ROS# (its choice is kept)."""
    path = directory / _PACKAGES
    try:
        data = json.loads(path.read_text(encoding="utf-8"))
    except FileNotFoundError:
        return None
    except (OSError, ValueError) as exc:
        raise UserError(
            f"cannot read {path}: {exc}",
            hint=f"fix it, or add {_ROSSHARP} to its dependencies yourself",
        ) from None
    deps = data.get("dependencies") if isinstance(data, dict) else None
    if not isinstance(deps, dict):
        raise UserError(
            f"{path} has no 'dependencies' object", hint="Unity's package manifest needs one"
        )
    if _ROSSHARP in deps:
        return None
    wanted = json.loads(template)["dependencies"][_ROSSHARP]
    # Unity keeps dependencies sorted and indents with two spaces: its next save changes nothing
    data["dependencies"] = dict(sorted({**deps, _ROSSHARP: wanted}.items()))
    return DesiredFile(path, (json.dumps(data, indent=2, ensure_ascii=False) + "\n").encode())


def init_project(directory: Path, ros: int, *, force: bool = False) -> list[FileChange]:
    """Write a template Unity project into ``directory``; refuses a non-empty folder."""
    if directory.exists() and not directory.is_dir():
        raise UserError(f"{directory} exists and is not a folder")
    if directory.is_dir() and any(directory.iterdir()) and not force:
        raise UserError(
            f"{directory} is not empty",
            hint="choose a new folder, or pass --force to add the template's files "
            "(existing files are kept)",
        )
    name = directory.resolve().name
    context = {
        "product_name": name,
        "product_guid": hashlib.md5(f"unityscaffold-init:{name}".encode()).hexdigest(),
        "rossharp_version": DEFAULT_VERSION,
    }
    files = _template_files(context)
    scenes = _existing_scenes(directory)
    if scenes:  # --force into a project: its scenes are the ones to wire, add none
        files = [(rel, data) for rel, data in files if not rel.startswith(MAIN_SCENE)]
    else:
        files += _scene_files(context["product_guid"])
    desired = [DesiredFile(directory / rel, data, create_only=True) for rel, data in files]
    pin = _pinned_packages(directory, dict(files)[_PACKAGES])
    if pin is not None:
        desired = [d for d in desired if d.path != pin.path] + [pin]
    manifest = starter_manifest(ros, scenes[0] if scenes else MAIN_SCENE, schema=SCHEMA_FILE)
    desired.append(
        DesiredFile(directory / "robot.yaml", manifest.encode("utf-8"), create_only=True)
    )
    desired.append(
        DesiredFile(directory / SCHEMA_FILE, schema_text().encode("utf-8"), create_only=True)
    )
    # --force may add to a folder whose Assets/ (or another part) is a link: apply's rule holds
    check_inside(directory, (d.path for d in desired))
    changes = plan_files(desired)
    write_files(changes)
    return changes
