"""Regenerate ``unityscaffold/unity/rossharp_catalog.json``: the scripts ROS# ships, as data.

A manifest names ROS#'s stock components (``StringPublisher``, ``JointStatePatcher``,
``UrdfLink``...) before Unity has ever downloaded the package, so the tool needs to know, per ROS#
release, each script's GUID and, for checking a manifest's fields before writing, its class:
namespace, base-class chain, ``[RequireComponent]``s and the fields Unity serializes (inherited
ones first, as Unity writes them) with their C# types, plus the members of the enums those fields
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

The C# reader is small and deliberate: comments and string contents are blanked, only the first
branch of each ``#if`` is kept, and declarations are split on braces and semicolons. It fails
loudly (exit 2, naming the file) on a field type it cannot classify rather than guessing.
"""

from __future__ import annotations

import argparse
import csv
import json
import os
import re
import sys
from dataclasses import dataclass, field
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
TARGET = ROOT / "unityscaffold" / "unity" / "rossharp_catalog.json"
ENV_PACKAGE = "UNITYSCAFFOLD_ROSSHARP"
ENV_GUIDS = "UNITYSCAFFOLD_ROSSHARP_GUIDS"
PACKAGE = "com.siemens.ros-sharp"
DEFAULT_RELEASE = "2.2.1"
SKIPPED_FOLDERS = ("MessageTypes",)  # thousands of message classes; none is a MonoBehaviour

# Unity's own classes a ROS# field may name, by what Unity stores for them.
PRIMITIVES = {
    "bool": "bool",
    "byte": "int",
    "sbyte": "int",
    "short": "int",
    "ushort": "int",
    "int": "int",
    "uint": "int",
    "long": "int",
    "ulong": "int",
    "float": "float",
    "double": "float",
    "char": "int",
    "string": "string",
}
UNITY_STRUCTS = frozenset(
    {"Vector2", "Vector3", "Vector4", "Quaternion", "Color", "Color32", "Rect", "Bounds"}
)
# UnityEngine.Object subclasses: a field of one of these holds a reference.
UNITY_COMPONENTS = frozenset(
    {
        "Transform",
        "RectTransform",
        "Rigidbody",
        "Camera",
        "Light",
        "Renderer",
        "MeshRenderer",
        "MeshFilter",
        "LineRenderer",
        "Joint",
        "HingeJoint",
        "ConfigurableJoint",
        "ArticulationBody",
        "Collider",
        "MonoBehaviour",
        "RawImage",
        "Image",
        "Text",
    }
)
UNITY_ASSETS = frozenset(
    {
        "GameObject",
        "Material",
        "Mesh",
        "Texture",
        "Texture2D",
        "RenderTexture",
        "Shader",
        "Sprite",
        "Font",
        "TextAsset",
    }
)
# Bases outside ROS# and what they derive from, up to the two roots that make a script asset.
EXTERNAL_BASES = {
    "MonoBehaviour": ("MonoBehaviour",),
    "ScriptableObject": ("ScriptableObject",),
    "EditorWindow": ("EditorWindow", "ScriptableObject"),
    "Editor": ("Editor", "ScriptableObject"),
}
# Types Unity never serializes (the field is skipped, as Unity skips it).
NEVER_SERIALIZED = re.compile(
    r"^(?:System\.)?(?:Dictionary|HashSet|Queue|Stack|Action|Func|Thread|Task|"
    r"ManualResetEvent|DateTime|TimeSpan|object|dynamic|Exception)\b"
)

_MODIFIERS = frozenset(
    {
        "public",
        "private",
        "protected",
        "internal",
        "static",
        "readonly",
        "const",
        "new",
        "volatile",
        "unsafe",
        "override",
        "virtual",
        "abstract",
        "sealed",
        "extern",
        "partial",
    }
)
_TYPE_DECL = re.compile(r"\b(class|struct|interface|enum)\s+(\w+)")
_ATTRIBUTE = re.compile(r"^\s*\[")
_REQUIRE = re.compile(r"(?:UnityEngine\.)?RequireComponent\s*\(")
_TYPEOF = re.compile(r"typeof\s*\(\s*([\w.]+)\s*\)")


class SourceError(Exception):
    """The checkout holds something this reader cannot classify."""


# --- lexing -----------------------------------------------------------------------------------


def clean(text: str) -> str:
    """Comments removed, string and char literal contents blanked, ``#else`` branches dropped."""
    out: list[str] = []
    i, n = 0, len(text)
    while i < n:
        c = text[i]
        if text.startswith("//", i):
            j = text.find("\n", i)
            i = n if j < 0 else j
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2)
            end = n if j < 0 else j + 2
            out.append(" " + "\n" * text.count("\n", i, end))
            i = end
        elif c == '"' or (c in "@$" and text[i + 1 : i + 3].lstrip("@$").startswith('"')):
            j = _string_end(text, i)
            out.append('""' + "\n" * text.count("\n", i, j))
            i = j
        elif c == "'":
            out.append("' '")
            i = _char_end(text, i)
        else:
            out.append(c)
            i += 1
    return _preprocess("".join(out))


def _string_end(text: str, start: int) -> int:
    """The index just past the string literal starting at ``start`` (``"``, ``@"``, ``$"``)."""
    prefix_end = text.index('"', start)
    prefix = text[start:prefix_end]
    verbatim, interpolated = "@" in prefix, "$" in prefix
    j = prefix_end + 1
    while j < len(text):
        c = text[j]
        if (c == "\\" and not verbatim) or (c == '"' and verbatim and text.startswith('""', j)):
            j += 2
        elif c == '"':
            return j + 1
        elif c == "{" and interpolated and text.startswith("{{", j):
            j += 2
        elif c == "{" and interpolated:
            j = _hole_end(text, j)
        else:
            j += 1
    raise SourceError("unterminated string literal")


def _char_end(text: str, start: int) -> int:
    """The index just past the char literal starting at ``start``."""
    j = start + 1
    while j < len(text) and text[j] != "'":
        j += 2 if text[j] == "\\" else 1
    return j + 1


def _hole_end(text: str, start: int) -> int:
    """The index just past the ``}`` closing an interpolation hole opened at ``start``."""
    depth, j = 0, start
    while j < len(text):
        c = text[j]
        if c == '"' or (c in "@$" and text[j + 1 : j + 3].lstrip("@$").startswith('"')):
            j = _string_end(text, j)
            continue
        if c == "'":
            j = _char_end(text, j)
            continue
        if c == "{":
            depth += 1
        elif c == "}":
            depth -= 1
            if depth == 0:
                return j + 1
        j += 1
    raise SourceError("unterminated interpolation")


def _preprocess(text: str) -> str:
    kept: list[str] = []
    skipping: list[bool] = []
    for line in text.split("\n"):
        directive = line.strip()
        if directive.startswith("#if"):
            skipping.append(False)
        elif directive.startswith(("#else", "#elif")):
            if skipping:
                skipping[-1] = True
        elif directive.startswith("#endif"):
            if skipping:
                skipping.pop()
        elif directive.startswith("#"):
            pass  # #region, #pragma ...
        elif not any(skipping):
            kept.append(line)
            continue
        kept.append("")
    return "\n".join(kept)


def _matching(text: str, start: int, open_: str = "{", close: str = "}") -> int:
    """Index of the bracket closing the one at ``start``."""
    depth = 0
    for i in range(start, len(text)):
        if text[i] == open_:
            depth += 1
        elif text[i] == close:
            depth -= 1
            if depth == 0:
                return i
    raise SourceError(f"unbalanced {open_!r}")


def _split_top(text: str, separator: str = ",") -> list[str]:
    """``text`` split on ``separator`` outside (), [], {} and <>."""
    parts, depth, current = [], 0, []
    for c in text:
        if c in "([{<":
            depth += 1
        elif c in ")]}>":
            depth -= 1
        if c == separator and depth == 0:
            parts.append("".join(current))
            current = []
        else:
            current.append(c)
    parts.append("".join(current))
    return [p.strip() for p in parts if p.strip()]


def _strip_attributes(text: str) -> tuple[list[str], str]:
    attributes = []
    text = text.strip()
    while _ATTRIBUTE.match(text):
        end = _matching(text, text.index("["), "[", "]")
        attributes.append(text[text.index("[") + 1 : end])
        text = text[end + 1 :].strip()
    return attributes, text


# --- declarations -----------------------------------------------------------------------------


@dataclass(slots=True)
class RawField:
    name: str
    type: str
    serialized: bool


@dataclass(slots=True)
class TypeDecl:
    kind: str  # class, struct, interface, enum
    name: str
    namespace: str
    outer: tuple[str, ...]
    path: str
    generics: tuple[str, ...] = ()
    bases: tuple[str, ...] = ()
    attributes: tuple[str, ...] = ()
    modifiers: frozenset[str] = frozenset()
    fields: list[RawField] = field(default_factory=list)
    members: list[tuple[str, int]] = field(default_factory=list)  # enums

    @property
    def full_name(self) -> str:
        return ".".join(p for p in (self.namespace, *self.outer, self.name) if p)


def parse_file(text: str, path: str) -> list[TypeDecl]:
    found: list[TypeDecl] = []
    _parse_block(clean(text), "", (), path, found, None)
    return found


def _next_stop(text: str, pos: int) -> int:
    """The next ``;`` or ``{`` outside parentheses and brackets, or -1."""
    depth = 0
    for i in range(pos, len(text)):
        c = text[i]
        if c in "([":
            depth += 1
        elif c in ")]":
            depth -= 1
        elif depth == 0 and c in ";{":
            return i
    return -1


def _parse_block(
    text: str,
    namespace: str,
    outer: tuple[str, ...],
    path: str,
    found: list[TypeDecl],
    owner: TypeDecl | None,
) -> None:
    pos = 0
    while True:
        stop = _next_stop(text, pos)
        if stop < 0:
            return
        head = text[pos:stop].strip()
        if text[stop] == ";":
            if owner is not None and head:
                owner.fields.extend(_fields(head))
            pos = stop + 1
            continue
        end = _matching(text, stop)
        body = text[stop + 1 : end]
        pos = end + 1
        attributes, bare = _strip_attributes(head)
        declaration = _TYPE_DECL.search(bare)
        if bare.startswith("namespace "):
            inner = bare.split(None, 1)[1].strip()
            _parse_block(
                body, f"{namespace}.{inner}" if namespace else inner, (), path, found, None
            )
        elif declaration and "(" not in bare[: declaration.start()] and "=" not in bare:
            decl = _declaration(declaration, bare, attributes, namespace, outer, path)
            found.append(decl)
            if decl.kind == "enum":
                decl.members = _enum_members(body)
            else:
                _parse_block(body, namespace, (*outer, decl.name), path, found, decl)
        elif "=" in bare.split("(", 1)[0] and "=>" not in bare:
            pos = text.index(";", pos) + 1  # a field with a collection initializer
        elif text[pos:].lstrip().startswith("="):
            pos = text.index(";", pos) + 1  # a property with an initializer


def _declaration(
    match: re.Match[str],
    bare: str,
    attributes: list[str],
    namespace: str,
    outer: tuple[str, ...],
    path: str,
) -> TypeDecl:
    modifiers = frozenset(bare[: match.start()].split())
    rest = bare[match.end() :].strip()
    generics: tuple[str, ...] = ()
    if rest.startswith("<"):
        close = _matching(rest, 0, "<", ">")
        generics = tuple(_split_top(rest[1:close]))
        rest = rest[close + 1 :].strip()
    bases: tuple[str, ...] = ()
    if rest.startswith(":"):
        bases = tuple(_split_top(re.split(r"\bwhere\b", rest[1:])[0]))
    return TypeDecl(
        match.group(1),
        match.group(2),
        namespace,
        outer,
        path,
        generics,
        bases,
        tuple(attributes),
        modifiers,
    )


def _enum_members(body: str) -> list[tuple[str, int]]:
    members, value = [], -1
    for item in _split_top(body):
        _, item = _strip_attributes(item)
        name, _, explicit = item.partition("=")
        explicit = explicit.strip()
        value = int(explicit, 0) if explicit else value + 1
        members.append((name.strip(), value))
    return members


def _fields(head: str) -> list[RawField]:
    attributes, rest = _strip_attributes(head)
    if not rest or rest.startswith(("using ", "delegate ")) or "=>" in rest:
        return []
    words = rest.split()
    modifiers = set()
    while words and words[0] in _MODIFIERS:
        modifiers.add(words.pop(0))
    rest = " ".join(words)
    if not rest or rest.startswith(("event ", "delegate ")):
        return []
    type_end = _type_end(rest)
    type_ = re.sub(r"\s+", "", rest[:type_end])
    declarators = _split_top(rest[type_end:])
    if not type_ or not declarators or "(" in declarators[0].split("=", 1)[0]:
        return []  # a method declaration without a body (abstract, extern)
    attribute_names = {a.split("(")[0].strip().rsplit(".", 1)[-1] for a in attributes}
    attribute_names |= {
        p.split("(")[0].strip().rsplit(".", 1)[-1] for a in attributes for p in _split_top(a)
    }
    serialized = (
        not modifiers & {"static", "const", "readonly"}
        and ("public" in modifiers or "SerializeField" in attribute_names)
        and not attribute_names & {"NonSerialized"}
    )
    names = [d.split("=", 1)[0].strip() for d in declarators]
    return [RawField(n, type_, serialized) for n in names if re.fullmatch(r"@?\w+", n)]


def _type_end(text: str) -> int:
    """Where a field's type ends: the first space at generic depth 0 before an identifier."""
    depth = 0
    i = 0
    while i < len(text):
        c = text[i]
        if c == "<":
            depth += 1
        elif c == ">":
            depth -= 1
        elif c == " " and depth == 0:
            after = text[i + 1 :].lstrip()
            if after and not after.startswith(("[", "<", ".", "?", ">", ",")):
                if text[:i].rstrip().endswith((",", ".")):
                    i += 1
                    continue
                return i
        i += 1
    return len(text)


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
    return _split_top(base[base.index("<") + 1 : base.rindex(">")])


def resolve_type(package: Package, written: str, context: TypeDecl) -> str | None:
    """What Unity stores for a field of C# type ``written``, or None when it is not serialized.

    ``int``/``float``/``bool``/``string``; ``enum:<full name>``; a Unity struct by name
    (``Vector3``); ``ref:<class>`` for a UnityEngine.Object (a Unity class or a ROS# script);
    ``T[]`` and ``List<T>`` of these.
    """
    text = written.removeprefix("UnityEngine.").removeprefix("System.")
    if text.endswith("[]"):
        inner = resolve_type(package, text[:-2], context)
        return None if inner is None or inner.endswith("]") else f"{inner}[]"
    if text.startswith(("List<", "Collections.Generic.List<")):
        inner = resolve_type(package, _type_arguments(text)[0], context)
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
    """Inherited fields first, then the class's own, as Unity writes them."""
    lineage = [decl, *_enclosing(package, decl)]
    lineage.reverse()
    fields: list[dict[str, str]] = []
    for owner in lineage:
        for raw in owner.fields:
            if not raw.serialized:
                continue
            resolved = resolve_type(package, raw.type, owner)
            if resolved is None:
                continue
            fields.append({"name": raw.name.lstrip("@"), "type": raw.type, "unity": resolved})
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
                for part in _split_top(a)
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
    if args.check:
        current = args.output.read_text(encoding="utf-8") if args.output.exists() else ""
        if current != text:
            print(f"{args.output} is out of date; run without --check", file=sys.stderr)
            return 1
        return 0
    args.output.write_text(text, encoding="utf-8")
    print(f"wrote {args.output}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
