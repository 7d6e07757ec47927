"""Checks across entries: duplicate names, clashing generated classes, repeated components,
topics that publish on a ROS 1 action's own topics."""

from __future__ import annotations

from collections.abc import Sequence

from unityscaffold.errors import SourceLocation
from unityscaffold.manifest._read import Reader
from unityscaffold.manifest.model import (
    Action,
    Component,
    Direction,
    Role,
    SceneObject,
    Service,
    Topic,
)

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
    places: dict[tuple[str, str, int], SourceLocation] = {}
    for o in objects:
        if o.sibling_index is not None:
            place = (o.scene, o.path.rpartition("/")[0], o.sibling_index)
            if place in places:
                r.error(
                    o.locations.of("sibling_index"),
                    f"sibling_index {o.sibling_index} is taken by another object "
                    + (f"among the children of '{place[1]}'" if place[1] else "among the roots"),
                    hint=f"the other one is on line {places[place].line}; give each its own",
                )
            places.setdefault(place, o.locations.of("sibling_index"))
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


# actionlib's topics under a ROS 1 action's name, by the side that publishes each
_ACTION_TOPICS = {
    "goal": Role.CLIENT,
    "cancel": Role.CLIENT,
    "status": Role.SERVER,
    "feedback": Role.SERVER,
    "result": Role.SERVER,
}
# what a second publisher beside the action's own script would put on each
_INTRUDES = {
    "goal": "goals its client does not track",
    "cancel": "cancels of goals its client tracks",
    "status": "status lists of goals its server does not hold (a client reads each list as the "
    "server's whole state)",
    "feedback": "feedback for goals its server does not carry out",
    "result": "results for goals its server does not carry out",
}


def _action_topic_publishers(r: Reader, topics: Sequence[Topic], actions: Sequence[Action]) -> None:
    """ROS 1: a topic that publishes on one of an action's five topics, beside that action.

    One listening (a subscriber on its feedback or status) is left alone: it adds nothing to
    the wire. One publishing would mix its messages into the action's own streams.
    """
    owners: dict[str, tuple[Action, str]] = {}
    for action in actions:
        for part in _ACTION_TOPICS:
            owners.setdefault(f"{_graph_name(action.name).rstrip('/')}/{part}", (action, part))
    for topic in topics:
        found = owners.get(_graph_name(topic.name))
        if topic.direction is not Direction.PUBLISH or found is None:
            continue
        action, part = found
        side = _ACTION_TOPICS[part]
        line = action.locations.item.line
        if side is action.role:
            said = f"which its {side.value} (line {line}) publishes already"
            hint = f"drop this entry: the action's script publishes {part} itself"
        else:
            said = (
                f"which its {side.value} publishes (Unity is its {action.role.value}, line {line})"
            )
            hint = (
                f"drop this entry: Unity would stand in for the action's {side.value} to its own "
                f"{action.role.value}"
            )
        r.error(
            topic.locations.of("name"),
            f"topic '{topic.name}' is the {part} topic of action '{action.name}', {said}; "
            f"publishing on it too would add {_INTRUDES[part]}",
            hint=hint,
        )


def check_across(
    r: Reader,
    topics: Sequence[Topic],
    services: Sequence[Service],
    components: Sequence[Component],
    objects: Sequence[SceneObject] = (),
    actions: Sequence[Action] = (),
    *,
    ros: int | None = None,
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
    if ros == 1:  # a ROS 2 action travels as rosbridge's action operations, not as topics
        _action_topic_publishers(r, topics, actions)
    _component_repeats(r, components)
    _object_repeats(r, objects)
