"""Checks across entries: duplicate names, clashing generated classes, repeated components."""

from __future__ import annotations

from collections.abc import Sequence

from unityscaffold.errors import SourceLocation
from unityscaffold.manifest._read import Reader
from unityscaffold.manifest.model import Action, Component, SceneObject, Service, Topic

__all__ = ["check_across"]

Entry = Topic | Service | Action


def _graph_name(name: str) -> str:
    # rosbridge resolves relative names in the root namespace, so cmd_vel is /cmd_vel
    return "/" + name.lstrip("/")


def _duplicates(r: Reader, items: Sequence[Entry], label: str) -> set[int]:
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


def _class_clashes(r: Reader, items: Sequence[tuple[str, Entry]]) -> None:
    # Compared without case: Unity needs file name == class name, and the file systems of
    # Windows and macOS would merge CmdVelPublisher.cs and CmdvelPublisher.cs.
    seen: dict[str, tuple[str, Entry]] = {}
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
    # apply recognises a component by scene + GameObject + script (+ id), so two entries with
    # the same of all would fight over one component
    first: dict[tuple[str, str, str], Component] = {}
    for c in components:
        key = (c.scene, c.gameobject, f"{c.guid}:{c.dll_class}" if c.guid else c.script)
        other = first.get(key)
        if other is None:
            first[key] = c
            continue
        if c.key is not None and other.key is not None and c.key != other.key:
            continue
        line = other.locations.item.line
        if c.key is not None and c.key == other.key:
            hint = f"the entry on line {line} has this id; give each instance its own"
        elif c.key is None and other.key is None:
            hint = (
                f"merge its fields into the entry on line {line}, or give both an 'id:' "
                "to have two instances"
            )
        else:
            hint = f"give this entry and the one on line {line} each an 'id:'"
        r.error(
            c.locations.of("id") if c.key else c.locations.item,
            f"component '{c.script}' is listed twice for GameObject '{c.gameobject}'",
            hint=hint,
        )


def _object_repeats(r: Reader, objects: Sequence[SceneObject]) -> None:
    seen: dict[tuple[str, str], SourceLocation] = {}
    for o in objects:
        key = (o.scene, o.path)
        if key in seen:
            r.error(
                o.locations.of("path"),
                f"object '{o.path}' is declared twice",
                hint=f"merge it into the entry on line {seen[key].line}",
            )
        seen.setdefault(key, o.locations.of("path"))
        kinds: dict[tuple[str, str | None], SourceLocation] = {}
        for b in o.components:
            if (b.type, b.key) in kinds:
                r.error(
                    b.location,
                    f"{b.type} is listed twice on '{o.path}'",
                    hint="give each one its own 'id:' to have two",
                )
            kinds.setdefault((b.type, b.key), b.location)


def check_across(
    r: Reader,
    topics: Sequence[Topic],
    services: Sequence[Service],
    components: Sequence[Component],
    objects: Sequence[SceneObject] = (),
    actions: Sequence[Action] = (),
) -> None:
    kinds: tuple[tuple[str, Sequence[Entry]], ...] = (
        ("topic", topics),
        ("service", services),
        ("action", actions),
    )
    generated: list[tuple[str, Entry]] = []
    for label, items in kinds:
        repeated = _duplicates(r, items, label)
        generated += [(label, item) for i, item in enumerate(items) if i not in repeated]
    _class_clashes(r, generated)
    _component_repeats(r, components)
    _object_repeats(r, objects)
