"""A manifest's field values checked against the C# field they set, before anything is written.

The kinds are the catalog's (``unity/catalog.py``): what Unity stores for the field's C# type.
A value that does not fit gives a located error saying what the field expects. Vectors, rotations
and colours are written inline (``{x: 0, y: 1, z: 0}``) as Unity writes them, so that Unity's next
save changes nothing. References go through ``resolve``, which knows the scene.
"""

from __future__ import annotations

import difflib
from collections.abc import Callable, Mapping, Sequence

from unityscaffold.errors import LocatedError, SourceLocation
from unityscaffold.manifest.model import (
    ComponentField,
    EmptyReference,
    ObjectPath,
    StructValue,
    value_text,
)
from unityscaffold.manifest.model import FieldValue as ManifestValue
from unityscaffold.unity import Enum, ObjectRef
from unityscaffold.unity.catalog import CatalogField
from unityscaffold.unity.values import FieldValue, InlineMap

__all__ = ["Resolver", "check_names", "typed_value"]

#: (reference, the class the field declares) -> the reference to write.
Resolver = Callable[[ObjectPath, str, SourceLocation], FieldValue]

_STRUCTS: dict[str, tuple[str, ...]] = {
    "Vector2": ("x", "y"),
    "Vector3": ("x", "y", "z"),
    "Vector4": ("x", "y", "z", "w"),
    "Quaternion": ("x", "y", "z", "w"),
    "Color": ("r", "g", "b", "a"),
    "Color32": ("r", "g", "b", "a"),
    "Rect": ("x", "y", "width", "height"),
}


def check_names(
    class_name: str, known: Sequence[CatalogField], given: Sequence[ComponentField]
) -> None:
    """Every field the manifest sets exists on the class (with "did you mean" when close)."""
    names = [f.name for f in known]
    for item in given:
        if item.name in names:
            continue
        close = difflib.get_close_matches(item.name, names, n=1)
        if not close:
            close = [n for n in names if n.lower() == item.name.lower()]
        hint = (
            f"did you mean {close[0]}?" if close else "its fields: " + (", ".join(names) or "none")
        )
        raise LocatedError.at(item.location, f"{class_name} has no field {item.name}", hint=hint)


def _describe(kind: str) -> str:
    if kind.endswith("[]"):
        return f"a list of {_describe(kind[:-2])}"
    if kind.startswith("enum:"):
        return f"a member of the enum {kind[5:].rsplit('.', 1)[-1]}"
    if kind.startswith("ref:"):
        return f"a reference to a {kind[4:].rsplit('.', 1)[-1]} (@Path or @Path:Class, or null)"
    if kind in _STRUCTS:
        return f"a {kind} such as {{{', '.join(f'{k}: 0' for k in _STRUCTS[kind])}}}"
    return {"int": "an integer", "float": "a number", "bool": "true or false"}.get(
        kind, f"a {kind}"
    )


def typed_value(
    kind: str,
    value: ManifestValue,
    where: SourceLocation,
    field: str,
    enums: Mapping[str, Mapping[str, int]],
    resolve: Resolver,
) -> FieldValue:
    """``value`` as the field of ``kind`` stores it; a located error when it does not fit."""

    def wrong() -> LocatedError:
        return LocatedError.at(
            where,
            f"{field} expects {_describe(kind)}, not {value_text(value)}",
            hint=_hint(kind, value),
        )

    if kind.endswith("[]"):
        if not isinstance(value, tuple):
            raise wrong()
        return [typed_value(kind[:-2], v, where, field, enums, resolve) for v in value]
    if kind.startswith("ref:"):
        if isinstance(value, EmptyReference):
            return ObjectRef(0)
        if not isinstance(value, ObjectPath):
            raise wrong()
        return resolve(value, kind[4:], where)
    if kind == "bool":
        if not isinstance(value, bool):
            raise wrong()
        return value
    if kind == "int":
        if isinstance(value, bool) or not isinstance(value, int):
            raise wrong()
        return value
    if kind == "float":
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            raise wrong()
        return value
    if kind == "string":
        if not isinstance(value, str):
            raise wrong()
        return value
    if kind.startswith("enum:"):
        members = enums.get(kind[5:], {})
        if isinstance(value, str) and value in members:
            return Enum(members[value])
        if isinstance(value, int) and not isinstance(value, bool) and value in members.values():
            return Enum(value)
        raise LocatedError.at(
            where,
            f"{field} expects a member of the enum {kind[5:].rsplit('.', 1)[-1]}, "
            f"not {value_text(value)}",
            hint="its members: " + ", ".join(members),
        )
    if kind in _STRUCTS:
        return _struct(kind, value, wrong)
    if isinstance(value, EmptyReference):
        raise wrong()
    return value  # type: ignore[return-value]  # a struct the catalog does not detail


def _hint(kind: str, value: ManifestValue) -> str | None:
    """What to write instead, for the mistakes a reference invites."""
    if kind.startswith("ref:") and isinstance(value, StructValue):
        return "write null for an empty reference; other objects are named by @Path"
    if kind.startswith("ref:") and not kind.endswith("[]") and isinstance(value, str):
        return f'a reference starts with @: "@{value}"'
    if isinstance(value, EmptyReference):
        return (
            "null is an empty reference, only for fields that hold an object or component; "
            "remove the field to keep the component's default"
        )
    return None


def _struct(kind: str, value: ManifestValue, wrong: Callable[[], LocatedError]) -> FieldValue:
    keys = _STRUCTS[kind]
    if isinstance(value, StructValue):
        items = value.as_dict()
        if set(items) != set(keys):
            raise wrong()
        numbers = [items[k] for k in keys]
    elif isinstance(value, tuple) and len(value) == len(keys):
        numbers = list(value)
    else:
        raise wrong()
    if any(isinstance(n, bool) or not isinstance(n, (int, float)) for n in numbers):
        raise wrong()
    return InlineMap(tuple(zip(keys, numbers, strict=True)))  # type: ignore[arg-type]
