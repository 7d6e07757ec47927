"""ROS# in one project: which release it uses, and the GUID and class of each of its scripts.

The GUIDs come from the project's own files, never from Unity's cache: an embedded copy under
``Packages/com.siemens.ros-sharp`` (part of the project, committed) gives its ``.meta`` GUIDs;
otherwise the catalog (``unity/rossharp_catalog.json``) gives those of the release pinned in
``Packages/manifest.json``. ROS# regenerated every GUID in 2.1.0 and restored the old ones in
2.2.1, so the release matters. A copy in ``Library/PackageCache`` changes nothing; when it holds
another release than the pin, that is noted (Unity replaces it on its next start). A copy's
release is told by its content, as ``package.json`` may say otherwise (2.2.1's says 2.2.0): the
GUIDs of the catalog's scripts, and where those agree with several releases (2.1.0, 2.1.1 and
2.2.0 share them) the digest of every script's path and GUID; only a copy the catalog does not
know is taken at its ``package.json``'s word.
"""

from __future__ import annotations

import json
import os
import re
from dataclasses import dataclass, field
from pathlib import Path

from unityscaffold.errors import UserError
from unityscaffold.unity.catalog import CatalogScript, rossharp_catalog, scripts_fingerprint
from unityscaffold.unity.meta import read_meta_guid
from unityscaffold.unity.project import ScriptInfo
from unityscaffold.unity.values import ScriptRef

__all__ = ["DEFAULT_VERSION", "PACKAGE", "RESERVED_NAMES", "RosSharp", "pinned_version"]

PACKAGE = "com.siemens.ros-sharp"
DEFAULT_VERSION = "2.2.1"
#: Class names a generated script must not take: every ROS# script class.
RESERVED_NAMES = frozenset(s.class_name for s in rossharp_catalog().scripts)
_VERSION = re.compile(r"#v?(\d+)\.(\d+)\.(\d+)")
_INSTALL_HINT = (
    f'add "{PACKAGE}": "https://github.com/siemens/ros-sharp.git?path=/{PACKAGE}'
    f'#{DEFAULT_VERSION}" to Packages/manifest.json (scaffold init does this)'
)


def pinned_version(project: Path) -> str | None:
    """The ROS# tag pinned in ``Packages/manifest.json`` (``…ros-sharp.git?path=…#2.2.1``)."""
    try:
        data = json.loads((project / "Packages" / "manifest.json").read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return None
    spec = data.get("dependencies", {}).get(PACKAGE) if isinstance(data, dict) else None
    if not isinstance(spec, str):
        return None
    found = _VERSION.search(spec) or _VERSION.search("#" + spec)
    return ".".join(found.groups()) if found else spec


def package_release(folder: Path) -> str | None:
    """The release of the ROS# package in ``folder``, told by its scripts' GUIDs, else by its
    ``package.json``; None when ``folder`` holds no package."""
    try:
        data = json.loads((folder / "package.json").read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return None
    catalog = rossharp_catalog()
    root = str(folder)
    agreeing = catalog.releases_agreeing(
        lambda path: read_meta_guid(os.path.join(root, path + ".meta"))
    )
    if len(agreeing) == 1:
        return agreeing[0]
    if agreeing:  # releases that differ only in other files (2.1.0, 2.1.1, 2.2.0): all of them
        found = catalog.release_with(scripts_fingerprint(_package_scripts(root)))
        if found in agreeing:
            return found
    version = data.get("version") if isinstance(data, dict) else None
    return version if isinstance(version, str) else None


def _package_scripts(root: str) -> list[tuple[str, str]]:
    """(path inside the package, GUID) of every ``.cs`` with a ``.meta`` under ``root``."""
    scripts = []
    # Strings, not Paths, for the thousand files of a release (pathlib's parsing was most of it).
    for directory, _, files in os.walk(root):
        inside = directory[len(root) + 1 :].replace(os.sep, "/")
        for name in files:
            if name.endswith(".cs.meta"):
                guid = read_meta_guid(os.path.join(directory, name))
                if guid is not None:
                    path = f"{inside}/{name}" if inside else name
                    scripts.append((path[: -len(".meta")], guid))
    return scripts


def cached_release(project: Path) -> str | None:
    """The release of the copy Unity keeps in ``Library/PackageCache``, if it has fetched one."""
    for folder in sorted((project / "Library" / "PackageCache").glob(f"{PACKAGE}@*")):
        found = package_release(folder)
        if found is not None:
            return found
    return None


@dataclass(frozen=True, slots=True)
class RosSharp:
    """Where ROS#'s scripts are, for one Unity project."""

    version: str | None  # the pinned release
    installed: dict[str, str]  # class name -> GUID, from an embedded package's .meta files
    installed_version: str | None = None
    notes: tuple[str, ...] = field(default=())

    @classmethod
    def of(cls, project: Path, scripts: dict[str, ScriptInfo]) -> RosSharp:
        embedded = project / "Packages" / PACKAGE
        if (embedded / "package.json").is_file():  # the project's own copy, committed with it
            prefix = f"Packages/{PACKAGE}/"
            installed = {
                info.class_name: guid
                for guid, info in sorted(scripts.items())
                if info.path.startswith(prefix)
            }
            release = package_release(embedded)
            return cls(release or pinned_version(project), installed, release)
        pinned = pinned_version(project)
        cached = cached_release(project)
        notes: tuple[str, ...] = ()
        if cached and pinned and cached != pinned:
            notes = (
                f"ROS# {cached} is installed in Library/PackageCache but Packages/manifest.json "
                f"pins {pinned}: using {pinned}'s script GUIDs (Unity installs {pinned} when it "
                "next opens the project)",
            )
        return cls(pinned, {}, cached, notes)

    @property
    def release(self) -> str:
        """The catalog release the scripts resolve from when the package is not installed."""
        return self.version or DEFAULT_VERSION

    def facts(self, class_name: str) -> CatalogScript | None:
        """What the catalog knows about a ROS# class (its fields, bases, RequireComponent)."""
        return rossharp_catalog().named(class_name)

    def class_names(self) -> dict[str, str]:
        """GUID -> class name of ROS#'s scripts in this project (for listing scenes)."""
        catalog = rossharp_catalog()
        names = catalog.class_names(self.release) if self.version else catalog.all_class_names()
        return {**names, **{guid: name for name, guid in self.installed.items()}}

    def script(self, class_name: str) -> ScriptRef:
        """The ``m_Script`` reference of a ROS# runtime script."""
        facts = self.facts(class_name)
        namespace = facts.namespace if facts else "RosSharp.RosBridgeClient"
        guid = self.installed.get(class_name)
        if guid is None and not self.installed and self.version is None:
            raise UserError(
                f"cannot find ROS#'s {class_name} script: ROS# is not installed in this project",
                hint=_INSTALL_HINT,
            )
        if guid is None and facts is not None:
            guid = facts.guid(self.release)
            if guid is None and self.release not in rossharp_catalog().releases:
                known = ", ".join(rossharp_catalog().releases)
                raise UserError(
                    f"Packages/manifest.json pins ROS# {self.release}, which the catalog of "
                    f"ROS#'s scripts does not know (it knows {known})",
                    hint="pin one of those releases, or embed the package under Packages/ so "
                    "that its own .meta files give the GUIDs",
                )
        if guid is None:
            raise UserError(
                f"ROS# {self.release} has no script {class_name}",
                hint="check the class name against ROS#'s Runtime folder",
            )
        return ScriptRef(guid, class_name=class_name, namespace=namespace)
