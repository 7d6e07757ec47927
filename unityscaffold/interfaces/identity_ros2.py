"""ROS 2 type identity: the RIHS01 type hash of REP 2011, as rosidl computes it.

The hash is the sha256 of a JSON text: the type's description (name, and each field's name and
type as ``type_id``/``capacity``/``string_capacity``/``nested_type_name``) followed by the
descriptions of every type it refers to, sorted by name; default values are left out. A
service is described as a type with ``request_message``, ``response_message`` and
``event_message`` fields; an action with its goal, result, feedback, two services and feedback
message.
"""

from __future__ import annotations

import hashlib
import json
from typing import Any

from unityscaffold.errors import LocatedError, SourceLocation
from unityscaffold.interfaces.model import (
    ActionSpec,
    ArrayKind,
    Field,
    Interface,
    MessageSpec,
    ServiceSpec,
    TypeRef,
)
from unityscaffold.interfaces.registry import Registry

__all__ = ["Ros2Identity"]

_TYPE_IDS = {
    "int8": 2,
    "uint8": 3,
    "int16": 4,
    "uint16": 5,
    "int32": 6,
    "uint32": 7,
    "int64": 8,
    "uint64": 9,
    "float32": 10,
    "float64": 11,
    "char": 3,
    "bool": 15,
    "byte": 16,
    "string": 17,
    "wstring": 18,
}
_NESTED = 1
_BOUNDED_STRING_OFFSET = 4  # string 17 -> bounded string 21, wstring 18 -> 22
_ARRAY_OFFSETS = {
    ArrayKind.NONE: 0,
    ArrayKind.FIXED: 48,
    ArrayKind.BOUNDED: 96,
    ArrayKind.UNBOUNDED: 144,
}
_EMPTY_PLACEHOLDER = Field(TypeRef("uint8"), "structure_needs_at_least_one_member")

_Description = dict[str, Any]


def _field_type(ref: TypeRef) -> dict[str, Any]:
    if ref.is_message:
        type_id = _NESTED
    else:
        type_id = _TYPE_IDS[ref.base]
        if ref.string_bound is not None:
            type_id += _BOUNDED_STRING_OFFSET
    return {
        "type_id": type_id + _ARRAY_OFFSETS[ref.array],
        "capacity": ref.size or 0,
        "string_capacity": ref.string_bound or 0,
        "nested_type_name": ref.base if ref.is_message else "",
    }


def _describe(name: str, fields: tuple[Field, ...], source: str | None = None) -> _Description:
    try:
        described = [
            {"name": f.name, "type": _field_type(f.type)} for f in fields or (_EMPTY_PLACEHOLDER,)
        ]
    except KeyError:
        raise _no_type_id(name, fields, source) from None
    return {"type_name": name, "fields": described}


def _no_type_id(name: str, fields: tuple[Field, ...], source: str | None) -> LocatedError:
    """The error for a field of ROS 1's ``time`` or ``duration``: rosidl's parser accepts them
    for compatibility, but they have no type id and no ROS 2 tool generates code for them."""
    field = next(f for f in fields if not f.type.is_message and f.type.base not in _TYPE_IDS)
    ros2 = "builtin_interfaces/Time" if field.type.base == "time" else "builtin_interfaces/Duration"
    return LocatedError.at(
        field.location or SourceLocation(source or name),
        f"'{field.type.base}' is a ROS 1 type; ROS 2 has no type hash or code for it",
        hint=f"write {ros2} instead",
    )


def _json(value: Any) -> str:
    """JSON text as rosidl hashes it (``json.dumps`` with ``", "`` and ``": "`` separators)."""
    return json.dumps(value, ensure_ascii=True, separators=(", ", ": "))


class Ros2Identity:
    """RIHS01 hashes over one registry."""

    def __init__(self, registry: Registry) -> None:
        self.registry = registry
        # per message the registry resolves: its description's JSON text, and the messages
        # its fields name (every hash repeats the descriptions of all the types it uses)
        self._described: dict[str, tuple[str, list[str]]] = {}

    def _pseudo_fields(self, interface: Interface) -> tuple[Field, ...]:
        """The fields rosidl gives a service or action type to describe it."""
        if isinstance(interface, MessageSpec):
            return interface.fields
        if isinstance(interface, ServiceSpec):
            assert interface.event is not None
            parts = (
                ("request_message", interface.request),
                ("response_message", interface.response),
                ("event_message", interface.event),
            )
            return tuple(Field(TypeRef(p.full_name), n) for n, p in parts)
        action_parts: tuple[tuple[str, MessageSpec | ServiceSpec], ...] = (
            ("goal", interface.goal),
            ("result", interface.result),
            ("feedback", interface.feedback),
            ("send_goal_service", interface.services[0]),
            ("get_result_service", interface.services[1]),
            ("feedback_message", interface.derived[0]),
        )
        return tuple(Field(TypeRef(p.full_name), n) for n, p in action_parts)

    def _local_types(self, interface: Interface) -> dict[str, Interface]:
        """Types defined inside ``interface`` that the registry cannot look up by name."""
        local: dict[str, Interface] = {}
        if isinstance(interface, ActionSpec):
            for service in interface.services:
                local[service.full_name] = service
            for message in interface.messages:
                local[message.full_name] = message
        elif isinstance(interface, ServiceSpec):
            for message in interface.parts:
                local[message.full_name] = message
        return local

    def description(self, interface: Interface) -> dict[str, Any]:
        """The hashed form: the type's description and its sorted referenced descriptions."""
        local = self._local_types(interface)
        referenced: dict[str, _Description] = {}
        pending = [f.type.base for f in self._pseudo_fields(interface) if f.type.is_message]
        while pending:
            name = pending.pop()
            if name in referenced:
                continue
            node = local.get(name) or self.registry.message(name)
            fields = self._pseudo_fields(node)
            referenced[name] = _describe(name, fields, node.source)
            pending += [f.type.base for f in fields if f.type.is_message]
        return {
            "type_description": _describe(
                interface.full_name, self._pseudo_fields(interface), interface.source
            ),
            "referenced_type_descriptions": [referenced[n] for n in sorted(referenced)],
        }

    def type_hash(self, interface: Interface) -> str:
        """The RIHS01 hash: of ``description(interface)`` as JSON, whose text is put together
        from each description's own JSON text (the same text, as JSON writes a dict's items and
        a list's values in order with the same separators); descriptions of registry types are
        made once per ``Ros2Identity``."""
        local = self._local_types(interface)
        fields = self._pseudo_fields(interface)
        referenced: dict[str, str] = {}
        pending = [f.type.base for f in fields if f.type.is_message]
        while pending:
            name = pending.pop()
            if name not in referenced:
                referenced[name], uses = self._described_text(name, local)
                pending += uses
        own = _json(_describe(interface.full_name, fields, interface.source))
        others = ", ".join(referenced[n] for n in sorted(referenced))
        text = f'{{"type_description": {own}, "referenced_type_descriptions": [{others}]}}'
        return "RIHS01_" + hashlib.sha256(text.encode("utf-8")).hexdigest()

    def _described_text(self, name: str, local: dict[str, Interface]) -> tuple[str, list[str]]:
        """``name``'s description as JSON text, and the message types its fields name."""
        found = self._described.get(name) if name not in local else None
        if found is None:
            node = local.get(name) or self.registry.message(name)
            fields = self._pseudo_fields(node)
            found = (
                _json(_describe(name, fields, node.source)),
                [f.type.base for f in fields if f.type.is_message],
            )
            if name not in local:  # a local type is its owner's own: not shared
                self._described[name] = found
        return found
