"""A project's own MonoBehaviour as the catalog describes ROS#'s: bases, ``[RequireComponent]``s
and serialized fields with what Unity stores for each, read from the script's ``.cs``.

Each field also gets the text Unity writes for it on a new component, from its C# initializer
(see ``unity/initializers.py``), so that apply writes a new component in full.

With these a manifest's values for the project's scripts are checked like those for ROS#'s
(a misspelled field gets "did you mean", ``@Path`` gives the GameObject, its transform or the
component that fits the declared type). Unlike the catalog's extractor this reader never fails:
a type it cannot place keeps the kind ``raw:<C# type>`` and its value is written as given; a
file it cannot read, or without the class named like the file, gives no facts at all.
"""

from __future__ import annotations

import re
from collections.abc import Callable, Mapping
from dataclasses import dataclass
from pathlib import Path

from unityscaffold.unity._emit import emit_field
from unityscaffold.unity.behaviours import Kind, unity_class
from unityscaffold.unity.catalog import CatalogField, CatalogScript
from unityscaffold.unity.csharp import (
    NEVER_SERIALIZED,
    PRIMITIVES,
    UNITY_ASSETS,
    UNITY_COMPONENTS,
    UNITY_STRUCTS,
    RawField,
    SourceError,
    TypeDecl,
    element_type,
    parse_file,
    split_top,
)
from unityscaffold.unity.initializers import field_default
from unityscaffold.unity.values import FieldValue

__all__ = ["ProjectFacts", "read_script_facts"]

# Unity's component classes beyond those ROS# names (the catalog's list), that a project's field
# may hold.
_MORE_COMPONENTS = frozenset(
    {
        "Component",
        "Behaviour",
        "BoxCollider",
        "SphereCollider",
        "CapsuleCollider",
        "MeshCollider",
        "Canvas",
        "CanvasRenderer",
        "CanvasGroup",
        "AudioSource",
        "Animator",
        "SkinnedMeshRenderer",
        "FixedJoint",
        "SpringJoint",
        "CharacterJoint",
        "CharacterController",
        "Button",
        "Slider",
        "Toggle",
        "InputField",
        "ScrollRect",
        "Dropdown",
    }
)
_REQUIRE = re.compile(r"(?:UnityEngine\.)?RequireComponent\s*\(")
_TYPEOF = re.compile(r"typeof\s*\(\s*([\w.]+)\s*\)")
_ROOTS = {"MonoBehaviour": ("MonoBehaviour",), "ScriptableObject": ("ScriptableObject",)}


@dataclass(frozen=True, slots=True)
class ProjectFacts:
    script: CatalogScript
    enums: dict[str, dict[str, int]]  # full C# name -> member -> value, for the fields' enums


#: A class name -> the facts of another script (the project's or ROS#'s), for base classes.
Lookup = Callable[[str], "ProjectFacts | CatalogScript | None"]


def read_script_facts(
    path: Path, class_name: str, lookup: Lookup, is_script: Callable[[str], bool]
) -> ProjectFacts | None:
    """The facts of the class Unity binds ``path`` to (``class_name``, the file's name, or else
    the file's one MonoBehaviour); None when they cannot be read.

    ``lookup`` gives the facts of a base class; ``is_script`` tells whether a field's type is a
    MonoBehaviour the project or ROS# has (a field of that type holds a reference).
    """
    try:
        data = path.read_bytes()
        decls = parse_file(data.decode("utf-8-sig", errors="replace"), path.name)
    except (OSError, SourceError, ValueError, IndexError):
        return None
    decl = unity_class(decls, class_name, lambda base: _base_kind(lookup, base)).decl
    if decl is None:
        return None
    class_name = decl.name
    enums = {d.name: d for d in decls if d.kind == "enum"}
    nested = {d.name: d for d in decls if d.kind in ("class", "struct") and _serializable(d)}
    used: dict[str, dict[str, int]] = {}
    bases: tuple[str, ...] = ()
    inherited: tuple[CatalogField, ...] = ()
    requires = set(_requires(decl))
    base = _base_class(decl)
    if base is not None:
        bare = base.split("<")[0].rsplit(".", 1)[-1]
        found = _ROOTS.get(bare) or _base_facts(lookup, bare)
        if isinstance(found, tuple):
            bases = found
        elif found is not None:
            script = found.script if isinstance(found, ProjectFacts) else found
            bases = (script.class_name, *script.bases)
            inherited = script.fields
            requires |= set(script.requires)
            if isinstance(found, ProjectFacts):
                used.update(found.enums)
        else:
            bases = (bare,)
    own = []
    for raw in decl.fields:
        if raw.serialized:
            kind = _kind(raw.type, enums, used, is_script)
            if kind is not None:
                name = raw.name.lstrip("@")
                value = _value(kind, raw, _Context(enums, used, is_script, nested))
                own.append(CatalogField(name, raw.type, kind, _text(name, value)))
    script = CatalogScript(
        class_name=class_name,
        namespace=decl.namespace,
        path=path.as_posix(),
        bases=bases,
        attachable=True,
        requires=tuple(sorted(requires)),
        fields=(*inherited, *own),
        guids=(),
    )
    return ProjectFacts(script, used)


def _base_kind(lookup: Lookup, name: str) -> Kind | None:
    found = _ROOTS.get(name) or _base_facts(lookup, name)
    if found is None:
        return None
    bases = found if isinstance(found, tuple) else _script(found).bases
    return Kind.COMPONENT if bases[-1:] == ("MonoBehaviour",) else Kind.OTHER


def _script(found: ProjectFacts | CatalogScript) -> CatalogScript:
    return found.script if isinstance(found, ProjectFacts) else found


@dataclass(frozen=True, slots=True)
class _Context:
    """What a field's type is looked up in: the file's enums and ``[Serializable]`` types."""

    enums: Mapping[str, TypeDecl]
    used: dict[str, dict[str, int]]
    is_script: Callable[[str], bool]
    nested: Mapping[str, TypeDecl]


def _serializable(decl: TypeDecl) -> bool:
    names = {p.split("(")[0].strip() for a in decl.attributes for p in split_top(a)}
    return bool(names & {"Serializable", "System.Serializable"})


def _value(kind: str, raw: RawField, ctx: _Context, depth: int = 0) -> FieldValue | None:
    """What Unity writes for the field on a new component (see ``unity/initializers.py``); a
    ``[Serializable]`` class or struct of the same file without an initializer is written
    inline with its own fields' values. None when that is not a plain value."""
    bare = raw.type.rsplit(".", 1)[-1]
    decl = ctx.nested.get(bare) if kind.startswith("raw:") else None
    if decl is None or depth > 8:
        return field_default(kind, raw.initializer, ctx.used, raw.type)
    if raw.initializer not in (None, f"new {raw.type}()", "new()") or not decl.fields:
        return None
    inner: dict[str, FieldValue] = {}
    for field in decl.fields:
        if not field.serialized:
            continue
        field_kind = _kind(field.type, ctx.enums, ctx.used, ctx.is_script)
        if field_kind is None:
            continue
        value = _value(field_kind, field, ctx, depth + 1)
        if value is None:
            return None
        inner[field.name.lstrip("@")] = value
    return inner or None


def _text(name: str, value: FieldValue | None) -> str | None:
    """The text after ``name:`` (None for no value, or a string ending in ``]``, which Unity 6
    quotes and earlier versions do not)."""
    if value is None or (isinstance(value, str) and value.endswith("]")):
        return None
    return "\n".join(emit_field(name, value))[len(name) + 3 :]


def _base_facts(lookup: Lookup, name: str) -> ProjectFacts | CatalogScript | None:
    try:
        return lookup(name)
    except RecursionError:  # classes deriving from each other: not valid C# anyway
        return None


def _base_class(decl: TypeDecl) -> str | None:
    """The base class among the listed bases: the first that is not an interface (IName)."""
    for base in decl.bases:
        bare = base.split("<")[0].rsplit(".", 1)[-1]
        if not re.fullmatch(r"I[A-Z]\w*", bare):
            return base
    return None


def _requires(decl: TypeDecl) -> list[str]:
    return [
        t.rsplit(".", 1)[-1]
        for attribute in decl.attributes
        for part in split_top(attribute)
        if _REQUIRE.match(part)
        for t in _TYPEOF.findall(part)
    ]


def _kind(
    written: str,
    enums: Mapping[str, TypeDecl],
    used: dict[str, dict[str, int]],
    is_script: Callable[[str], bool],
) -> str | None:
    """What Unity stores for a field of C# type ``written`` (None: Unity does not store it)."""
    text = written.removeprefix("UnityEngine.").removeprefix("System.")
    inner = element_type(text)
    if inner is not None:
        kind = _kind(inner, enums, used, is_script)
        if kind is None or kind.endswith("[]") or kind.startswith("raw:"):
            return None if kind is None else f"raw:{written}"
        return f"{kind}[]"
    if text in PRIMITIVES:
        return PRIMITIVES[text]
    if NEVER_SERIALIZED.match(text):
        return None
    if text in UNITY_STRUCTS:
        return text
    bare = text.rsplit(".", 1)[-1]
    if bare in enums:
        decl = enums[bare]
        used[decl.full_name] = dict(decl.members)
        return f"enum:{decl.full_name}"
    if bare in UNITY_COMPONENTS or bare in UNITY_ASSETS or bare in _MORE_COMPONENTS:
        return f"ref:{bare}"
    if is_script(bare):
        return f"ref:{bare}"
    return f"raw:{written}"
