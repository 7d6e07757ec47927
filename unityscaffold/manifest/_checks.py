"""Checks across entries: duplicate names, clashing generated classes, repeated components."""

from __future__ import annotations

from collections.abc import Sequence

from unityscaffold.errors import SourceLocation
from unityscaffold.manifest._read import Reader
from unityscaffold.manifest.model import Component, Service, Topic

__all__ = ["check_across"]


def _graph_name(name: str) -> str:
    # rosbridge resolves relative names in the root namespace, so cmd_vel is /cmd_vel
    return "/" + name.lstrip("/")


def _duplicates(r: Reader, items: Sequence[Topic | Service], label: str) -> set[int]:
    """Report every repeat of a name at the repeat; return the indexes of the repeats."""
    first: dict[str, SourceLocation] = {}
    repeats: set[int] = set()
    for index, item in enumerate(items):
        key = _graph_name(item.name)
        here = item.locations.of("name")
        if key in first:
            repeats.add(index)
            r.error(
                here,
                f"duplicate {label} '{item.name}'",
                hint=f"'{key}' is already listed on line {first[key].line}; "
                f"each {label} appears once",
            )
        else:
            first[key] = here
    return repeats


def _class_clashes(r: Reader, items: Sequence[tuple[str, Topic | Service]]) -> None:
    # Compared without case: Unity needs file name == class name, and the file systems of
    # Windows and macOS would merge CmdVelPublisher.cs and CmdvelPublisher.cs.
    seen: dict[str, tuple[str, Topic | Service]] = {}
    for label, item in items:
        if not item.class_name:
            continue
        key = item.class_name.lower()
        if key not in seen:
            seen[key] = (label, item)
            continue
        other_label, other = seen[key]
        at = "class" if item.locations.has("class") else "name"
        same_case = (
            ""
            if other.class_name == item.class_name
            else f" (same file name as '{other.class_name}' on case-insensitive systems)"
        )
        r.error(
            item.locations.of(at),
            f"{label} '{item.name}' would generate class '{item.class_name}', like "
            f"{other_label} '{other.name}' on line {other.locations.item.line}{same_case}",
            hint="give one of them its own 'class:'",
        )


def _component_repeats(r: Reader, components: Sequence[Component]) -> None:
    # apply recognises a component by scene + GameObject + script, so two entries would fight
    first: dict[tuple[str, str, str], SourceLocation] = {}
    for c in components:
        key = (c.scene, c.gameobject, c.script)
        if key in first:
            r.error(
                c.locations.item,
                f"component '{c.script}' is listed twice for GameObject '{c.gameobject}'",
                hint=f"merge its fields into the entry on line {first[key].line}",
            )
        else:
            first[key] = c.locations.item


def check_across(
    r: Reader, topics: Sequence[Topic], services: Sequence[Service], components: Sequence[Component]
) -> None:
    repeated_topics = _duplicates(r, topics, "topic")
    repeated_services = _duplicates(r, services, "service")
    generated: list[tuple[str, Topic | Service]] = [
        ("topic", t) for i, t in enumerate(topics) if i not in repeated_topics
    ]
    generated += [("service", s) for i, s in enumerate(services) if i not in repeated_services]
    _class_clashes(r, generated)
    _component_repeats(r, components)
