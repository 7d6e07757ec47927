"""Component field values: YAML scalars, lists and mappings, and ``@`` object references."""

from __future__ import annotations

import re

from unityscaffold.manifest import _spec as spec
from unityscaffold.manifest._read import Reader, describe
from unityscaffold.manifest._yaml import YMap, YNode, YScalar, YSeq
from unityscaffold.manifest.model import (
    CSHARP_IDENTIFIER,
    ComponentField,
    EmptyReference,
    FieldValue,
    ObjectPath,
    StructValue,
)

__all__ = ["parse_reference", "read_fields"]

EXPECT_REFERENCE = "@Path/To/GameObject or @Path/To/GameObject:ComponentClass"
_FIELD_NAME = re.compile(CSHARP_IDENTIFIER)
# How YAML writes a null on purpose; a key with nothing after it is null too, but is more
# likely a value left out by mistake.
_WRITTEN_NULL = re.compile(r"(?:null|Null|NULL|~|!!null)(?![\w~])")


def parse_reference(text: str) -> ObjectPath | None:
    """``@Robot/base_link`` or ``@RosConnector:RosConnector`` as an ObjectPath; None if bad.

    The component part is split at the last ``:`` so that a GameObject name may hold one.
    """
    body = text[1:]
    path, component = body, None
    if ":" in body:
        path, component = body.rsplit(":", 1)
        if not re.search(spec.NAMESPACE, component):
            return None
    if not re.search(spec.GAMEOBJECT, path):
        return None
    return ObjectPath(path, component)


def read_fields(r: Reader, m: YMap) -> tuple[ComponentField, ...]:
    entry = m.get("fields")
    if entry is None or (isinstance(entry.value, YScalar) and entry.value.value is None):
        return ()
    if not isinstance(entry.value, YMap):
        r.invalid(entry, "a mapping of field name to value")
        return ()
    fields = []
    for field in entry.value.entries:
        if not _FIELD_NAME.fullmatch(field.key):
            r.error(
                field.key_location,
                f"invalid field name '{field.key}'",
                expected="the C# name of a serialized field, e.g. Topic",
            )
        value = _value(r, field.value, field.key)
        if value is not None:
            fields.append(ComponentField(field.key, value, field.value.location))
    return tuple(fields)


def _written_null(node: YScalar) -> bool:
    where = node.location
    text = where.source_line or ""
    return _WRITTEN_NULL.match(text, max(where.col - 1, 0)) is not None


def _value(r: Reader, node: YNode, name: str) -> FieldValue | None:
    if isinstance(node, YSeq):
        items = [_value(r, item, name) for item in node.items]
        return tuple(i for i in items if i is not None)
    if isinstance(node, YMap):
        members = [(e.key, _value(r, e.value, e.key)) for e in node.entries]
        return StructValue(tuple((k, v) for k, v in members if v is not None))
    value = node.value
    if value is None:
        if _written_null(node):
            return EmptyReference()
        r.error(
            node.location,
            f"field '{name}' has no value",
            expected="a number, text, true/false, a list, a mapping, an @reference or null",
            hint="write null for an empty reference (None in the Inspector), or remove the "
            "field to keep the component's default",
        )
        return None
    if isinstance(value, str) and value.startswith("@"):
        if value.startswith("@@"):
            return value[1:]
        reference = parse_reference(value)
        if reference is None:
            r.error(
                node.location,
                f"invalid object reference {describe(node)} in field '{name}'",
                expected=EXPECT_REFERENCE,
                hint="write '@@' at the start for text that begins with '@'",
            )
        return reference
    assert isinstance(value, (bool, int, float, str))
    return value
