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
    desired = [
        DesiredFile(directory / rel, data, create_only=True)
        for rel, data in _template_files(context) + _scene_files(context["product_guid"])
    ]
    manifest = starter_manifest(ros, MAIN_SCENE, schema=SCHEMA_FILE)
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
