"""Plain-data descriptions of interfaces, for ``msgs show`` and ``msgs list`` (text and JSON)."""

from __future__ import annotations

from typing import Any

from unityscaffold.interfaces.identity_ros1 import Ros1Identity
from unityscaffold.interfaces.identity_ros2 import Ros2Identity
from unityscaffold.interfaces.model import (
    ActionSpec,
    Constant,
    Dialect,
    Field,
    Interface,
    MessageSpec,
    ServiceSpec,
)
from unityscaffold.interfaces.registry import Registry

__all__ = ["Describer"]

_SEPARATOR = "=" * 80 + "\n"


def _field(field: Field) -> dict[str, Any]:
    default = list(field.default) if isinstance(field.default, tuple) else field.default
    return {
        "name": field.name,
        "type": str(field.type),
        "base": field.type.base,
        "array": field.type.array.value,
        "size": field.type.size,
        "string_bound": field.type.string_bound,
        "default": default,
        "comment": "\n".join(field.comment),
    }


def _constant(constant: Constant) -> dict[str, Any]:
    return {
        "name": constant.name,
        "type": constant.type,
        "value": constant.value,
        "text": constant.text,
        "comment": "\n".join(constant.comment),
    }


class Describer:
    """Turns interfaces of one registry into dictionaries with identity and source."""

    def __init__(self, registry: Registry) -> None:
        self.registry = registry
        self.ros1 = Ros1Identity(registry)
        self.ros2 = Ros2Identity(registry)

    def _source(self, interface: Interface) -> str | None:
        file = self.registry.file_of(interface)
        return str(file.path) if file else interface.source

    def definition(self, message: MessageSpec) -> str:
        """The full definition: genmsg's text in ROS 1; the same layout over ROS 2 texts."""
        if message.dialect is Dialect.ROS1:
            return self.ros1.full_text(message)
        parts = [message.text.rstrip("\n"), "\n"]
        for dependency in self.ros1.dependencies(message):
            parts += [
                _SEPARATOR,
                f"MSG: {dependency.short_full_name}\n",
                dependency.text.rstrip("\n"),
                "\n",
            ]
        return "".join(parts)[:-1]

    def identity(self, interface: Interface) -> dict[str, Any]:
        if self.registry.dialect is Dialect.ROS1:
            md5 = self.ros1.md5sum(interface) if not isinstance(interface, ActionSpec) else None
            return {"md5sum": md5, "type_hash": None}
        return {"md5sum": None, "type_hash": self.ros2.type_hash(interface)}

    def message(self, message: MessageSpec) -> dict[str, Any]:
        return {
            "type": message.full_name,
            "kind": "msg",
            "md5sum": self.identity(message)["md5sum"],
            "definition": self.definition(message),
            "fields": [_field(f) for f in message.fields],
            "constants": [_constant(c) for c in message.constants],
            "source": self._source(message),
        }

    def describe(self, interface: Interface) -> dict[str, Any]:
        """The JSON shape of ``msgs show``."""
        # Unknown field types and cycles first, all at once and each at the field using it.
        self.registry.closure([interface])
        if isinstance(interface, MessageSpec):
            return self.message(interface)
        base = {
            "type": interface.full_name,
            "kind": interface.kind.value,
            "md5sum": self.identity(interface)["md5sum"],
            "definition": interface.text,
            "fields": [],
            "constants": [],
            "source": self._source(interface),
        }
        if isinstance(interface, ServiceSpec):
            base["request"] = self.message(interface.request)
            base["response"] = self.message(interface.response)
        else:
            base["goal"] = self.message(interface.goal)
            base["result"] = self.message(interface.result)
            base["feedback"] = self.message(interface.feedback)
        return base
