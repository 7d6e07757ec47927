"""Regenerate ``unityscaffold/unity/rossharp_catalog.json``: the scripts ROS# ships, as data.

A manifest names ROS#'s stock components (``StringPublisher``, ``JointStatePatcher``,
``UrdfLink``...) before Unity has ever downloaded the package, so the tool needs to know, per ROS#
release, each script's GUID and, for checking a manifest's fields before writing, its class:
namespace, base-class chain, ``[RequireComponent]``s and the fields Unity serializes (inherited
ones first, as Unity writes them) with their C# types and, where the C# initializer can be
evaluated exactly, the text Unity writes for the field on a new component (so that apply writes
every field and Unity's next save changes nothing), plus the members of the enums those fields
use. These are facts about ROS#; this extractor and the data it writes are ours.

Inputs:
- a checkout of ROS#'s Unity package ``com.siemens.ros-sharp`` at one release (the classes and
  fields are read from its ``.cs`` files; only that release's sources are read), and
- a table of the GUID of every ``.cs`` file per release (tab-separated ``release``, ``path``,
  ``guid``, paths starting with ``com.siemens.ros-sharp/``), made from ROS#'s git tags with
  ``git show TAG:PATH.meta`` for every ``.cs`` file of the package at each tag.

Run:
    python3 scripts/update_rossharp_catalog.py PATH/TO/com.siemens.ros-sharp PATH/TO/guids.tsv

or set ``UNITYSCAFFOLD_ROSSHARP`` (the package folder) and ``UNITYSCAFFOLD_ROSSHARP_GUIDS`` (the
table). ``--release`` names the checkout's release (default 2.2.1), ``--output`` writes elsewhere,
``--check`` compares instead of writing (exit 1 when the committed file differs).

The C# reader (``unityscaffold/unity/csharp.py``) is small and deliberate: comments and string
contents are blanked, only the first branch of each ``#if`` is kept. This script fails
loudly (exit 2, naming the file) on a field type it cannot classify rather than guessing.
"""

from __future__ import annotations

import argparse
import csv
import json
import os
import re
import sys
from dataclasses import dataclass
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))  # the package's C# reader, also when run from a bare checkout

from _derived import write_or_check  # noqa: E402

from unityscaffold.unity._emit import emit_field  # noqa: E402
from unityscaffold.unity.catalog import scripts_fingerprint  # noqa: E402
from unityscaffold.unity.csharp import (  # noqa: E402
    NEVER_SERIALIZED,
    PRIMITIVES,
    UNITY_ASSETS,
    UNITY_COMPONENTS,
    UNITY_STRUCTS,
    SourceError,
    TypeDecl,
    element_type,
    parse_file,
    split_top,
)
from unityscaffold.unity.initializers import field_default  # noqa: E402

TARGET = ROOT / "unityscaffold" / "unity" / "rossharp_catalog.json"
ENV_PACKAGE = "UNITYSCAFFOLD_ROSSHARP"
ENV_GUIDS = "UNITYSCAFFOLD_ROSSHARP_GUIDS"
PACKAGE = "com.siemens.ros-sharp"
DEFAULT_RELEASE = "2.2.1"
SKIPPED_FOLDERS = ("MessageTypes",)  # thousands of message classes; none is a MonoBehaviour

# Bases outside ROS# and what they derive from, up to the two roots that make a script asset.
EXTERNAL_BASES = {
    "MonoBehaviour": ("MonoBehaviour",),
    "ScriptableObject": ("ScriptableObject",),
    "EditorWindow": ("EditorWindow", "ScriptableObject"),
    "Editor": ("Editor", "ScriptableObject"),
}

_REQUIRE = re.compile(r"(?:UnityEngine\.)?RequireComponent\s*\(")
_TYPEOF = re.compile(r"typeof\s*\(\s*([\w.]+)\s*\)")


# --- the catalog ------------------------------------------------------------------------------


@dataclass(slots=True)
class Package:
    types: list[TypeDecl]

    def named(self, name: str, context: TypeDecl | None = None) -> TypeDecl | None:
        """The package's type called ``name`` (possibly qualified), seen from ``context``."""
        last = name.split("<")[0].rsplit(".", 1)[-1]
        arity = len(_type_arguments(name))
        candidates = [t for t in self.types if t.name == last and len(t.generics) == arity]
        if len(candidates) > 1 and "." in name:
            qualifier = name.split("<")[0].rsplit(".", 2)[-2]
            candidates = [t for t in candidates if qualifier in (*t.outer, t.namespace)] or [
                t for t in candidates if t.full_name.endswith(name.split("<")[0])
            ]
        if len(candidates) > 1 and context is not None:
            nested = [t for t in candidates if t.outer and t.outer[-1] in self.chain(context)]
            candidates = nested or [t for t in candidates if t.namespace == context.namespace]
        if len(candidates) > 1:
            raise SourceError(f"ambiguous type {name}: {[t.full_name for t in candidates]}")
        return candidates[0] if candidates else None

    def base_of(self, decl: TypeDecl) -> str | None:
        for base in decl.bases:
            bare = base.split("<")[0].rsplit(".", 1)[-1]
            target = self.named(base)
            if target is not None and target.kind == "class":
                return base
            if target is None and bare in EXTERNAL_BASES:
                return base
        return None

    def chain(self, decl: TypeDecl) -> list[str]:
        """Base classes, nearest first, ending at an external root."""
        names: list[str] = []
        current: TypeDecl | None = decl
        while current is not None:
            base = self.base_of(current)
            if base is None:
                break
            bare = base.split("<")[0].rsplit(".", 1)[-1]
            target = self.named(base)
            if target is None:
                names.extend(EXTERNAL_BASES[bare])
                break
            names.append(target.name)
            current = target
        return names


def _type_arguments(base: str) -> list[str]:
    if "<" not in base:
        return []
    return split_top(base[base.index("<") + 1 : base.rindex(">")])


def resolve_type(package: Package, written: str, context: TypeDecl) -> str | None:
    """What Unity stores for a field of C# type ``written``, or None when it is not serialized.

    ``int``/``float``/``bool``/``string``; ``enum:<full name>``; a Unity struct by name
    (``Vector3``); ``ref:<class>`` for a UnityEngine.Object (a Unity class or a ROS# script);
    ``T[]`` and ``List<T>`` of these.
    """
    text = written.removeprefix("UnityEngine.").removeprefix("System.")
    element = element_type(text)
    if element is not None:
        inner = resolve_type(package, element, context)
        return None if inner is None or inner.endswith("]") else f"{inner}[]"
    if text in PRIMITIVES:
        return PRIMITIVES[text]
    if NEVER_SERIALIZED.match(text):
        return None
    if text in UNITY_STRUCTS:
        return text
    if text in context.generics or any(text in t.generics for t in _enclosing(package, context)):
        return None  # a message class (T : Message); not [Serializable]
    declared = package.named(text, context)
    if declared is not None:
        if declared.kind == "enum":
            return f"enum:{declared.full_name}"
        chain = package.chain(declared)
        if "MonoBehaviour" in chain:
            return f"ref:{declared.full_name}"
        if "Serializable" in declared.attributes:
            raise SourceError(f"[Serializable] {declared.full_name} is not supported")
        return None  # a plain class or interface: Unity does not serialize it
    bare = text.rsplit(".", 1)[-1]
    if bare in UNITY_COMPONENTS or bare in UNITY_ASSETS:
        return f"ref:{bare}"
    raise SourceError(f"{context.path}: field type {written} of {context.full_name} is unknown")


def _enclosing(package: Package, decl: TypeDecl) -> list[TypeDecl]:
    """The classes ``decl``'s fields may inherit type parameters from."""
    found = []
    current: TypeDecl | None = decl
    while current is not None:
        base = package.base_of(current)
        current = package.named(base) if base else None
        if current is not None:
            found.append(current)
    return found


def serialized_fields(package: Package, decl: TypeDecl) -> list[dict[str, str]]:
    """Inherited fields first, then the class's own, as Unity writes them; each with the text
    Unity writes for it on a new component (``default``, after ``name:``) when its
    initializer is a literal or the field has none (see ``unity/initializers.py``)."""
    lineage = [decl, *_enclosing(package, decl)]
    lineage.reverse()
    enums = {t.full_name: dict(t.members) for t in package.types if t.kind == "enum"}
    fields: list[dict[str, str]] = []
    for owner in lineage:
        for raw in owner.fields:
            if not raw.serialized:
                continue
            resolved = resolve_type(package, raw.type, owner)
            if resolved is None:
                continue
            name = raw.name.lstrip("@")
            field = {"name": name, "type": raw.type, "unity": resolved}
            value = field_default(resolved, raw.initializer, enums, raw.type)
            if value is not None:
                if isinstance(value, str) and value.endswith("]"):
                    # Unity 6 quotes such a string, earlier versions do not: one text cannot do
                    raise SourceError(f"{owner.path}: {name}'s default {value!r} ends in ]")
                field["default"] = "\n".join(emit_field(name, value))[len(name) + 3 :]
            fields.append(field)
    return fields


def read_package(folder: Path) -> Package:
    types: list[TypeDecl] = []
    for path in sorted(folder.rglob("*.cs"), key=lambda p: p.relative_to(folder).as_posix()):
        relative = path.relative_to(folder).as_posix()
        if any(part in SKIPPED_FOLDERS for part in path.relative_to(folder).parts):
            continue
        try:
            types.extend(parse_file(_read_source(path), relative))
        except SourceError as error:
            raise SourceError(f"{relative}: {error}") from None
    return Package(types)


def _read_source(path: Path) -> str:
    """A ``.cs`` file's text: UTF-8 (with or without BOM), else Windows-1252 (a few ROS#
    files carry a Latin-1 copyright sign)."""
    data = path.read_bytes()
    try:
        return data.decode("utf-8-sig")
    except UnicodeDecodeError:
        return data.decode("cp1252")


def read_guids(table: Path) -> dict[str, dict[str, str]]:
    """path (inside the package) -> release -> GUID."""
    found: dict[str, dict[str, str]] = {}
    with table.open(encoding="utf-8", newline="") as handle:
        for row in csv.DictReader(handle, delimiter="\t"):
            path = row["path"].removeprefix(f"{PACKAGE}/")
            found.setdefault(path, {})[row["release"]] = row["guid"]
    return found


def build_catalog(package: Package, guids: dict[str, dict[str, str]], release: str) -> dict:
    releases = sorted({r for by in guids.values() for r in by}, key=_version_key)
    scripts = []
    used_enums: set[str] = set()
    for decl in package.types:
        if decl.kind != "class" or decl.outer:
            continue
        chain = package.chain(decl)
        if not chain or chain[-1] not in ("MonoBehaviour", "ScriptableObject"):
            continue
        if decl.name != Path(decl.path).stem:
            continue  # Unity binds a script asset to the class named like its file only
        if decl.path not in guids or release not in guids[decl.path]:
            raise SourceError(f"{decl.path}: no GUID for release {release} in the table")
        fields = serialized_fields(package, decl)
        for f in fields:
            if f["unity"].startswith("enum:"):
                used_enums.add(f["unity"].removeprefix("enum:").removesuffix("[]"))
        requires = sorted(
            {
                t.rsplit(".", 1)[-1]
                for owner in [decl, *_enclosing(package, decl)]
                for a in owner.attributes
                for part in split_top(a)
                if _REQUIRE.match(part)
                for t in _TYPEOF.findall(part)
            }
        )
        scripts.append(
            {
                "class": decl.name,
                "namespace": decl.namespace,
                "path": decl.path,
                "bases": chain,
                "attachable": chain[-1] == "MonoBehaviour"
                and "abstract" not in decl.modifiers
                and not decl.generics
                and not decl.path.startswith("Editor/"),
                "requires": requires,
                "fields": fields,
                "guids": dict(sorted(guids[decl.path].items(), key=lambda i: _version_key(i[0]))),
            }
        )
    scripts.sort(key=lambda s: (s["class"], s["namespace"]))
    enums = {
        t.full_name: {name: value for name, value in t.members}
        for t in package.types
        if t.kind == "enum" and t.full_name in used_enums
    }
    return {
        "package": PACKAGE,
        "sources": release,
        "about": (
            f"Facts about ROS#'s scripts: GUIDs per release from each release's .cs.meta files; "
            f"classes, base chains, RequireComponent, serialized fields and enums read from the "
            f"{release} sources and assumed for every release that has the same file. Written "
            f"by scripts/update_rossharp_catalog.py; do not edit by hand."
        ),
        "releases": releases,
        # what tells the releases apart in a project's package folder, whatever its package.json
        "fingerprints": {
            r: scripts_fingerprint((p, by[r]) for p, by in guids.items() if r in by)
            for r in releases
        },
        "enums": dict(sorted(enums.items())),
        "scripts": scripts,
    }


def _version_key(text: str) -> tuple[int, ...]:
    return tuple(int(p) for p in text.split("."))


def render(catalog: dict) -> str:
    return json.dumps(catalog, indent=1, ensure_ascii=False) + "\n"


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("package", nargs="?", default=os.environ.get(ENV_PACKAGE))
    parser.add_argument("guids", nargs="?", default=os.environ.get(ENV_GUIDS))
    parser.add_argument("--release", default=DEFAULT_RELEASE)
    parser.add_argument("--output", type=Path, default=TARGET)
    parser.add_argument("--check", action="store_true")
    args = parser.parse_args(argv)
    if not args.package or not args.guids:
        parser.error(
            f"give the package folder and the GUID table (or set {ENV_PACKAGE}, {ENV_GUIDS})"
        )
    try:
        text = render(
            build_catalog(
                read_package(Path(args.package)), read_guids(Path(args.guids)), args.release
            )
        )
    except (SourceError, OSError, KeyError, ValueError) as error:
        print(f"error: {error}", file=sys.stderr)
        return 2
    return write_or_check(args.output, text, args.check)


if __name__ == "__main__":
    sys.exit(main())
