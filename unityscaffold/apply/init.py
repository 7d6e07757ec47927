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
from typing import Any

from unityscaffold.apply._inside import check_inside
from unityscaffold.apply._rossharp import DEFAULT_VERSION
from unityscaffold.apply._rossharp import PACKAGE as ROSSHARP
from unityscaffold.apply._tcpconnector import PACKAGE as TCP_PACKAGE
from unityscaffold.apply._tcpconnector import PACKAGE_URL as TCP_PACKAGE_URL
from unityscaffold.errors import UserError
from unityscaffold.fileout import DesiredFile, FileChange, plan_files, write_files
from unityscaffold.manifest import starter_manifest
from unityscaffold.manifest.runtime import Runtime
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
#: The package each runtime needs, pinned by its UPM git URL.
_RUNTIME_PACKAGE = {
    Runtime.ROS_SHARP: (
        ROSSHARP,
        f"https://github.com/siemens/ros-sharp.git?path=/{ROSSHARP}#{DEFAULT_VERSION}",
    ),
    Runtime.TCP_CONNECTOR: (TCP_PACKAGE, TCP_PACKAGE_URL),
}


def _existing_scenes(directory: Path) -> list[str]:
    """The scenes a project already has, project-relative and sorted."""
    assets = directory / "Assets"
    if not assets.is_dir():
        return []
    return sorted(p.relative_to(directory).as_posix() for p in assets.rglob("*.unity"))


def _with_dependency(data: dict[str, Any], runtime: Runtime, *, first: bool = False) -> bytes:
    """A package manifest with the runtime's package added: first (the template's place), or
    where Unity, which keeps dependencies sorted, puts it in a manifest it wrote. Indented with
    two spaces as Unity does, so its next save changes nothing."""
    name, url = _RUNTIME_PACKAGE[runtime]
    deps = data["dependencies"]
    data["dependencies"] = (
        {name: url, **deps} if first else dict(sorted({**deps, name: url}.items()))
    )
    return (json.dumps(data, indent=2, ensure_ascii=False) + "\n").encode()


def _pinned_packages(directory: Path, runtime: Runtime) -> DesiredFile | None:
    """An existing ``Packages/manifest.json`` with the runtime's package added, pinned as a new
    project pins it; None when there is none or it already names that package (its choice is
    kept)."""
    path = directory / _PACKAGES
    name = _RUNTIME_PACKAGE[runtime][0]
    try:
        data = json.loads(path.read_text(encoding="utf-8"))
    except FileNotFoundError:
        return None
    except (OSError, ValueError) as exc:
        raise UserError(
            f"cannot read {path}: {exc}",
            hint=f"fix it, or add {name} to its dependencies yourself",
        ) from None
    deps = data.get("dependencies") if isinstance(data, dict) else None
    if not isinstance(deps, dict):
        raise UserError(
            f"{path} has no 'dependencies' object", hint="Unity's package manifest needs one"
        )
    if name in deps:
        return None
    return DesiredFile(path, _with_dependency(data, runtime))


def init_project(
    directory: Path, ros: int, *, force: bool = False, runtime: Runtime = Runtime.ROS_SHARP
) -> list[FileChange]:
    """Write a template Unity project into ``directory`` for ``runtime`` (its package pinned
    in ``Packages/manifest.json``); refuses a non-empty folder."""
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
    }
    files = [
        (rel, _with_dependency(json.loads(data), runtime, first=True) if rel == _PACKAGES else data)
        for rel, data in _template_files(context)
    ]
    scenes = _existing_scenes(directory)
    if scenes:  # --force into a project: its scenes are the ones to wire, add none
        files = [(rel, data) for rel, data in files if not rel.startswith(MAIN_SCENE)]
    else:
        files += _scene_files(context["product_guid"])
    desired = [DesiredFile(directory / rel, data, create_only=True) for rel, data in files]
    pin = _pinned_packages(directory, runtime)
    if pin is not None:
        desired = [d for d in desired if d.path != pin.path] + [pin]
    manifest = starter_manifest(
        ros, scenes[0] if scenes else MAIN_SCENE, schema=SCHEMA_FILE, runtime=runtime
    )
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
