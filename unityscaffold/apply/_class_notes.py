"""Which warnings about the message classes a runtime ships apply shows as notes.

A class that garbles or drops messages is named on every apply: nothing generated can mend it.
A class that differs only in the values a new instance starts with (ROS-TCP-Connector's ROS 1
``QuaternionMsg`` starts with ``w = 1``, ROS's with 0) matters only where Unity builds such a
message to send, so it is named only for an entry that sends one, and only when that entry's
script is written (created or changed): once it has been said, an unchanged project does not
say it again, and ``--check`` says it exactly when apply would.
"""

from __future__ import annotations

from collections.abc import Iterable
from pathlib import Path

from unityscaffold.apply._code import CodePlan, PlannedScript
from unityscaffold.interfaces.model import ActionSpec, Interface, MessageSpec, ServiceSpec
from unityscaffold.interfaces.registry import Registry
from unityscaffold.manifest.model import Direction, Role, Topic

__all__ = ["class_notes"]


def _sent(script: PlannedScript, spec: Interface) -> tuple[MessageSpec, ...]:
    """The messages Unity builds and sends through ``script``."""
    item = script.item
    if isinstance(item, Topic):
        publishes = item.direction is Direction.PUBLISH
        return (spec,) if publishes and isinstance(spec, MessageSpec) else ()
    client = item.role is Role.CLIENT
    if isinstance(spec, ServiceSpec):
        return (spec.request,) if client else (spec.response,)
    if isinstance(spec, ActionSpec):
        return (spec.goal,) if client else (spec.result, spec.feedback)
    return ()


def _held(registry: Registry, roots: Iterable[MessageSpec]) -> set[str]:
    """The full names of ``roots`` and of every message they hold, at any depth."""
    seen: set[str] = set()
    pending = list(roots)
    while pending:
        spec = pending.pop()
        if spec.full_name in seen:
            continue
        seen.add(spec.full_name)
        for field in spec.fields:
            if field.type.is_message:
                nested = registry.find(field.type.base)
                if isinstance(nested, MessageSpec):
                    pending.append(nested)
    return seen


def class_notes(code: CodePlan, registry: Registry, written: set[Path]) -> list[str]:
    """The shipped classes' warnings to show, given the files this apply writes."""
    sent: set[str] | None = None  # worked out only if a warning needs it
    notes = []
    for skipped in code.messages.skipped:
        if skipped.warning is None:
            continue
        if skipped.default_of is not None:
            if sent is None:
                sent = _sent_by_written_scripts(code.scripts, registry, written)
            if skipped.default_of not in sent:
                continue
        notes.append(skipped.warning)
    return notes


def _sent_by_written_scripts(
    scripts: Iterable[PlannedScript], registry: Registry, written: set[Path]
) -> set[str]:
    roots: list[MessageSpec] = []
    for script in scripts:
        spec = registry.find(script.item.type)
        if script.path in written and spec is not None:
            roots += _sent(script, spec)
    return _held(registry, roots)
