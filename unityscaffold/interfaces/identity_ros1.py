"""ROS 1 type identity: md5sum and full definition text, exactly as genmsg computes them.

md5 text: constants first (``TYPE NAME=TEXT``), then fields; a builtin field is written with
its type as stored (array suffix kept), a message field as the md5 of that message (array
suffix dropped); lines joined by newlines, surrounding whitespace stripped. A service's md5 is
the md5 of its request's md5 text followed directly by its response's.

Full text: the type's own text, then for each message it uses (depth first, field order, first
occurrence) a line of 80 ``=``, ``MSG: pkg/Name`` and that message's text; the final newline
is dropped.
"""

from __future__ import annotations

import hashlib

from unityscaffold.errors import LocatedError, SourceLocation
from unityscaffold.interfaces.model import MessageSpec, ServiceSpec
from unityscaffold.interfaces.registry import Registry

__all__ = ["Ros1Identity"]

_SEPARATOR = "=" * 80 + "\n"


class Ros1Identity:
    """md5sums and full texts over one registry, each computed once."""

    def __init__(self, registry: Registry) -> None:
        self.registry = registry
        self._md5: dict[str, str] = {}
        self._open: list[str] = []  # messages whose md5 is being computed, outermost first

    def md5_text(self, spec: MessageSpec) -> str:
        lines = [f"{c.type} {c.name}={c.text}" for c in spec.constants]
        self._open.append(spec.full_name)
        try:
            for field in spec.fields:
                if field.type.is_builtin:
                    lines.append(f"{field.type_text or field.type} {field.name}")
                else:
                    nested = self.registry.field_type(spec, field)
                    if nested.full_name in self._open:
                        raise _cycle(self._open, nested, field.location or spec.source)
                    lines.append(f"{self.md5sum(nested)} {field.name}")
        finally:
            self._open.pop()
        return "\n".join(lines).strip()

    def md5sum(self, spec: MessageSpec | ServiceSpec) -> str:
        if isinstance(spec, ServiceSpec):
            text = self.md5_text(spec.request) + self.md5_text(spec.response)
            return hashlib.md5(text.encode()).hexdigest()
        cached = self._md5.get(spec.full_name)
        if cached is None:
            cached = hashlib.md5(self.md5_text(spec).encode()).hexdigest()
            self._md5[spec.full_name] = cached
        return cached

    def dependencies(self, spec: MessageSpec) -> list[MessageSpec]:
        """Messages ``spec`` uses, depth first in field order, each once."""
        ordered: dict[str, MessageSpec] = {}

        def walk(current: MessageSpec) -> None:
            for field in current.fields:
                if field.type.is_message:
                    nested = self.registry.field_type(current, field)
                    # genmsg lists a dependency before its own dependencies, and keeps the
                    # first occurrence of each. One seen before was walked then: its own
                    # dependencies are all listed already (and a cycle ends here).
                    if nested.full_name not in ordered:
                        ordered[nested.full_name] = nested
                        walk(nested)

        walk(spec)
        return list(ordered.values())

    def full_text(self, spec: MessageSpec) -> str:
        parts = [spec.text, "\n"]
        for dependency in self.dependencies(spec):
            parts += [_SEPARATOR, f"MSG: {dependency.full_name}\n", dependency.text, "\n"]
        return "".join(parts)[:-1]


def _cycle(
    open_names: list[str], nested: MessageSpec, where: SourceLocation | str | None
) -> LocatedError:
    """The error for a message that contains itself (through ``open_names``), at the field that
    closes the cycle: its md5 would need its own md5."""
    cycle = " -> ".join([*open_names[open_names.index(nested.full_name) :], nested.full_name])
    location = (
        where if isinstance(where, SourceLocation) else SourceLocation(where or nested.full_name)
    )
    return LocatedError.at(
        location,
        f"types refer to each other in a cycle: {cycle}",
        hint="ROS messages cannot contain themselves",
    )
