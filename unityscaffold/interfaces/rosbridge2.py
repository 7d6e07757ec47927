"""What rosbridge for ROS 2 (rosbridge_suite's ``ros2`` branch, 2.x) cannot carry, found in a
type's fields: ``apply`` notes it at the manifest entry that uses the type.

rosbridge 2.x converts between JSON and rclpy's message objects by the field types rclpy
reports (``rosbridge_library/internal/message_conversion.py``). Three kinds of field fall
outside what it converts; a message holding one is dropped, whichever way it goes (the runtime
tests show each through ROS#'s client and through a plain JSON client alike):

- ``wstring`` (any array of it too): not among the types it knows;
- bounded strings, ``string<=N``: rclpy names them ``string<N>``, which it does not know either;
- ``byte`` arrays and sequences (``byte[]``, ``byte[N]``, ``byte[<=N]``): rclpy holds them as a
  list of one-byte ``bytes`` objects, which rosbridge hands to the JSON encoder as they are.
"""

from __future__ import annotations

from dataclasses import dataclass

from unityscaffold.interfaces.model import MessageSpec, TypeRef
from unityscaffold.interfaces.registry import Registry

#: Where each kind of field is reported upstream, and what a user can do instead.
LIMITS = {
    "wstring": (
        "https://github.com/RobotWebTools/rosbridge_suite/issues/1297",
        "use string (UTF-8) on the ROS side for what Unity sees",
    ),
    "bounded string": (
        "https://github.com/RobotWebTools/rosbridge_suite/pull/827 (not merged)",
        "use an unbounded string on the ROS side for what Unity sees",
    ),
    "byte array": (
        "https://github.com/RobotWebTools/rosbridge_suite/pull/1315 (not merged)",
        "use uint8[] (rosbridge carries it as base64 text) on the ROS side for what Unity sees",
    ),
}


@dataclass(frozen=True, slots=True)
class Uncarried:
    """A field rosbridge 2.x cannot carry: its path from the message (``.a.b[]``), its type
    as written, and which of ``LIMITS`` it falls under."""

    path: str
    type: str
    kind: str


def _kind(field_type: TypeRef) -> str | None:
    if field_type.base == "wstring":
        return "wstring"
    if field_type.base == "string" and field_type.string_bound is not None:
        return "bounded string"
    if field_type.base == "byte" and field_type.is_array:
        return "byte array"
    return None


def uncarried_fields(registry: Registry, spec: MessageSpec) -> tuple[Uncarried, ...]:
    """Every field of ``spec``, nested messages' included, that rosbridge 2.x cannot carry."""
    found: list[Uncarried] = []
    for field in spec.fields:
        path = f".{field.name}{'[]' if field.type.is_array else ''}"
        kind = _kind(field.type)
        if kind:
            found.append(Uncarried(path, str(field.type), kind))
        elif field.type.is_message:
            nested = registry.find(field.type.base)
            if isinstance(nested, MessageSpec):
                inner = uncarried_fields(registry, nested)
                found += [Uncarried(path + u.path, u.type, u.kind) for u in inner]
    return tuple(found)


def describe(fields: tuple[Uncarried, ...]) -> str:
    """One sentence for a note: the fields, then each kind's upstream report and workaround."""
    listed = ", ".join(f"{f.path} ({f.type})" for f in fields[:3])
    if len(fields) > 3:
        listed += f" and {len(fields) - 3} more"
    kinds = sorted({f.kind for f in fields})
    advice = "; ".join(f"{k}: {LIMITS[k][0]}, {LIMITS[k][1]}" for k in kinds)
    return f"rosbridge 2.x cannot carry {listed}: it drops every such message, both ways ({advice})"
