"""ROS#'s scripts as data: per release, each script's GUID, class, bases and serialized fields.

``rossharp_catalog.json`` beside this module is written by ``scripts/update_rossharp_catalog.py``
from ROS#'s sources and the ``.cs.meta`` GUIDs of each release. It lets a project name ROS#'s
stock components before Unity has downloaded the package (no ``Library/``), and lets a manifest's
field names and values be checked against the C# fields before anything is written.

A field's ``unity`` kind says what Unity stores: ``int``, ``float``, ``bool``, ``string``,
``enum:<full C# name>``, a Unity struct (``Vector3``, ``Quaternion``, ``Color``...),
``ref:<class>`` (a reference to a GameObject, a component or a script), or any of these
followed by ``[]`` (an array or ``List<>``). A field's ``default`` is the text Unity writes for
it on a new component, from its C# initializer (absent when that is not a plain value).
"""

from __future__ import annotations

import hashlib
import json
from collections.abc import Callable, Iterable
from dataclasses import dataclass
from functools import cache

from unityscaffold.resources import rossharp_catalog_text

__all__ = [
    "CatalogField",
    "CatalogScript",
    "ScriptCatalog",
    "imported_by_unity",
    "rossharp_catalog",
    "scripts_fingerprint",
]


def imported_by_unity(path: str) -> bool:
    """Whether Unity imports the file at ``path`` (``/``-separated, inside a package): not in a
    folder ending with ``~`` (``Samples~``) or starting with ``.``, which Unity skips."""
    return not any(part.endswith("~") or part.startswith(".") for part in path.split("/")[:-1])


def scripts_fingerprint(scripts: Iterable[tuple[str, str]]) -> str:
    """One digest of a package's scripts: ``(path inside the package, GUID)`` of every ``.cs``
    Unity imports. Two copies of a release give the same digest whatever their ``package.json``
    says (ROS# 2.2.1's says 2.2.0), and releases whose GUIDs differ give different ones."""
    lines = sorted(f"{path}\t{guid}\n" for path, guid in scripts if imported_by_unity(path))
    return hashlib.sha256("".join(lines).encode("utf-8")).hexdigest()


@dataclass(frozen=True, slots=True)
class CatalogField:
    name: str
    csharp: str  # the type as written in C#
    unity: str  # what Unity stores (see the module docstring)
    # the text Unity writes after "name:" on a new component (its C# initializer), or None
    # when the initializer is not a value this tool can work out
    default: str | None = None


@dataclass(frozen=True, slots=True)
class CatalogScript:
    class_name: str
    namespace: str
    path: str  # inside the package
    bases: tuple[str, ...]  # nearest first, ending at MonoBehaviour or ScriptableObject
    attachable: bool  # a concrete, non-generic runtime MonoBehaviour
    requires: tuple[str, ...]  # [RequireComponent] classes, bases' included
    fields: tuple[CatalogField, ...]
    guids: tuple[tuple[str, str], ...]  # (release, GUID)

    def guid(self, release: str) -> str | None:
        return dict(self.guids).get(release)

    def field(self, name: str) -> CatalogField | None:
        return next((f for f in self.fields if f.name == name), None)


@dataclass(frozen=True, slots=True)
class ScriptCatalog:
    package: str
    sources: str  # the release whose sources gave the classes and fields
    releases: tuple[str, ...]
    enums: dict[str, dict[str, int]]  # full C# name -> member -> value
    scripts: tuple[CatalogScript, ...]
    fingerprints: dict[str, str]  # scripts_fingerprint -> release

    def releases_agreeing(self, guid_at: Callable[[str], str | None]) -> tuple[str, ...]:
        """The releases whose scripts' GUIDs are those ``guid_at`` reads (path inside the
        package -> its GUID, None when absent): 86 files that tell most releases apart."""
        found = {s.path: guid_at(s.path) for s in self.scripts}
        return tuple(
            r for r in self.releases if all(found[s.path] == s.guid(r) for s in self.scripts)
        )

    def release_with(self, fingerprint: str) -> str | None:
        """The release whose scripts have ``fingerprint``, or None (another or a changed copy)."""
        return self.fingerprints.get(fingerprint)

    def named(self, class_name: str) -> CatalogScript | None:
        return next((s for s in self.scripts if s.class_name == class_name), None)

    def class_names(self, release: str) -> dict[str, str]:
        """GUID -> class name of every script the release has."""
        return {g: s.class_name for s in self.scripts if (g := s.guid(release)) is not None}

    def all_class_names(self) -> dict[str, str]:
        """GUID -> class name over every release (GUIDs differ between some releases)."""
        return {guid: s.class_name for s in self.scripts for _, guid in s.guids}


@cache
def rossharp_catalog() -> ScriptCatalog:
    data = json.loads(rossharp_catalog_text())
    scripts = tuple(
        CatalogScript(
            class_name=s["class"],
            namespace=s["namespace"],
            path=s["path"],
            bases=tuple(s["bases"]),
            attachable=s["attachable"],
            requires=tuple(s["requires"]),
            fields=tuple(
                CatalogField(f["name"], f["type"], f["unity"], f.get("default"))
                for f in s["fields"]
            ),
            guids=tuple(s["guids"].items()),
        )
        for s in data["scripts"]
    )
    fingerprints = {digest: release for release, digest in data["fingerprints"].items()}
    return ScriptCatalog(
        data["package"],
        data["sources"],
        tuple(data["releases"]),
        data["enums"],
        scripts,
        fingerprints,
    )
