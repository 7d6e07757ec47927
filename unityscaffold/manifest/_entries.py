"""Reading the ``topics``, ``services`` and ``components`` entries of a manifest."""

from __future__ import annotations

import re
from dataclasses import dataclass
from pathlib import Path
from typing import TypeVar

from unityscaffold.fileout import MAX_NAME_BYTES
from unityscaffold.manifest import _spec as spec
from unityscaffold.manifest._fields import read_fields
from unityscaffold.manifest._paths import project_path
from unityscaffold.manifest._read import Reader
from unityscaffold.manifest._topic_keys import read_rates
from unityscaffold.manifest._yaml import YMap, YNode
from unityscaffold.manifest.model import (
    Action,
    Component,
    Direction,
    Locations,
    Role,
    Service,
    Topic,
    default_class_name,
    is_csharp_identifier,
)
from unityscaffold.manifest.runtime import Runtime

__all__ = [
    "Context",
    "locations",
    "read_action",
    "read_component",
    "read_gameobject",
    "read_scene",
    "read_service",
    "read_topic",
]

EXPECT_NAME = "a ROS name such as /cmd_vel: letters, digits, '_' and '/'"
EXPECT_GAMEOBJECT = "a hierarchy path such as Robot/base_link"
EXPECT_SCENE = "a .unity file inside the project, e.g. Assets/Scenes/Main.unity"
EXPECT_SCRIPT = "a class name such as TwistSubscriber, or a .cs file inside the project"
EXPECT_MSG_TYPE = "a message type such as geometry_msgs/Twist"
EXPECT_SRV_TYPE = "a service type such as std_srvs/Trigger"
EXPECT_ACTION_TYPE = "an action type such as move_base_msgs/action/MoveBase"


@dataclass(frozen=True, slots=True)
class Context:
    """What entries inherit from the top level of the manifest."""

    project_root: Path
    scene: str | None
    scene_written: bool  # a wrong top-level scene is reported once, not for every entry
    create: bool
    connector_gameobject: str
    ros: int | None = None  # the manifest's ROS version, when it is valid
    runtime: Runtime = Runtime.ROS_SHARP


def locations(m: YMap) -> Locations:
    return Locations(m.location, tuple((e.key, e.value.location) for e in m.entries))


def read_scene(r: Reader, m: YMap, ctx: Context, label: str) -> str | None:
    """The entry's scene, or the top-level one; reports an entry left without a scene."""
    entry = m.get("scene")
    if entry is None:
        if ctx.scene is None and not ctx.scene_written:
            where = "under 'connector:'" if label == "connector" else "to this entry"
            r.error(
                m.location,
                f"no scene for this {label}",
                hint=f"add a top-level 'scene:' for every entry, or 'scene:' {where}",
            )
        return ctx.scene
    value = r.text(m, "scene", EXPECT_SCENE, spec.SCENE, hint="a scene file ends in .unity")
    if value is None:
        return None
    return project_path(r, entry, value, ctx.project_root, expected=EXPECT_SCENE)


def read_gameobject(r: Reader, m: YMap, default: str | None) -> str | None:
    entry = m.get("gameobject")
    if entry is None:
        return default
    hint = None
    raw = entry.value
    text = getattr(raw, "value", None)
    if isinstance(text, str) and (text.startswith("/") or text.endswith("/") or "//" in text):
        hint = "paths start at a root GameObject of the scene and have no empty parts"
    return r.text(m, "gameobject", EXPECT_GAMEOBJECT, spec.GAMEOBJECT, hint=hint)


def _name_hint(m: YMap) -> str | None:
    entry = m.get("name")
    value = getattr(entry.value, "value", None) if entry else None
    if not isinstance(value, str):
        return None
    if "//" in value:
        return "remove the doubled '/'"
    if value.endswith("/"):
        return "remove the trailing '/'"
    if value.startswith("~"):
        return "private names (~) do not exist for rosbridge clients; write the full name"
    if any(part[:1].isdigit() for part in value.split("/")):
        return "each part of a name starts with a letter (or '_' after a '/')"
    return "ROS names use only letters, digits, '_' and '/'"


def _ros_name(r: Reader, m: YMap, ctx: Context) -> str | None:
    """A topic or service name; ROS 2 also forbids ``__`` (ROS 1 allows it)."""
    name = r.text(m, "name", EXPECT_NAME, spec.ROS_NAME, hint=_name_hint(m))
    if name is not None and ctx.ros == 2 and "__" in name:
        r.invalid(
            m.get("name"),  # type: ignore[arg-type]
            EXPECT_NAME,
            hint="ROS 2 names may not contain '__' (a doubled underscore); use one '_'",
        )
        return None
    return name


_KIND_LABEL = {"msg": "message", "srv": "service", "action": "action"}
_KIND_SECTION = {"msg": "topics", "srv": "services", "action": "actions"}
_ROS2_ACTION_PART = re.compile(spec.ROS2_ACTION_PART)


def _type_value(m: YMap) -> str | None:
    entry = m.get("type")
    value = getattr(entry.value, "value", None) if entry else None
    return value if isinstance(value, str) else None


def _type_hint(m: YMap, own: str) -> str | None:
    """A hint for a type of another kind than the section's (``own``: msg, srv or action)."""
    value = _type_value(m)
    if value is None:
        return None
    for kind, label in _KIND_LABEL.items():
        if kind != own and f"/{kind}/" in value:
            if kind == "action" and _ROS2_ACTION_PART.search(value):
                return _action_part_hint(value)
            article = "an" if kind == "action" else "a"
            return f"'{value}' is {article} {label} type; list it under '{_KIND_SECTION[kind]}'"
    return None


def _action_part_hint(value: str) -> str:
    package, *_, name = value.split("/")
    owner = name[: name.rindex("_")]
    return (
        f"'{value}' is part of the action {package}/action/{owner}, which rosbridge carries as "
        f"a whole: list {package}/action/{owner} under 'actions' (role: client or server)"
    )


def _no_action_part(
    r: Reader, m: YMap, ctx: Context, expected: str, *, in_actions: bool = False
) -> bool:
    """False (reported) for a ROS 2 type that names a part of an action, such as the
    ``X_SendGoal`` service or the ``X_FeedbackMessage`` message, which only the action's own
    entry can use (rosbridge has no operations for them alone)."""
    value = _type_value(m)
    if ctx.ros != 2 or value is None or not _ROS2_ACTION_PART.search(value):
        return True
    if not in_actions and value.count("/") == 2 and value.split("/")[1] == "action":
        return True  # refused by the section's pattern, with the same hint
    package, *_, name = value.split("/")
    owner = f"{package}/action/{name[: name.rindex('_')]}"
    hint = (
        f"'{value}' is part of the action {owner}; name the action itself: type: {owner}"
        if in_actions
        else _action_part_hint(value)
    )
    r.invalid(m.get("type"), expected, hint=hint)  # type: ignore[arg-type]
    return False


# The longest file a script class gets is its user half's .meta: Name.User.cs.meta.
_MAX_SCRIPT_CLASS = MAX_NAME_BYTES - len(".User.cs.meta")


def _class_name(
    r: Reader, m: YMap, name: str | None, kind: Direction | Role | None, *, action: bool = False
) -> str:
    entry = m.get("class")
    if entry is not None:
        value = r.text(m, "class", "a C# class name such as CmdVelPublisher", spec.CLASS_NAME)
        if value is not None and not is_csharp_identifier(value):
            r.invalid(entry, "a C# class name", hint=f"'{value}' is a C# keyword")
        elif value is not None and len(value) > _MAX_SCRIPT_CLASS:
            r.invalid(
                entry,
                f"a C# class name of at most {_MAX_SCRIPT_CLASS} characters",
                hint=_LONG_CLASS_HINT,
            )
        return value or ""
    if name is None or kind is None:
        return ""
    derived = default_class_name(name, kind, action=action)
    if len(derived) > _MAX_SCRIPT_CLASS:
        r.error(
            m.get("name").value.location,  # type: ignore[union-attr]
            f"the class derived from this name, '{derived[:24]}…', is {len(derived)} "
            f"characters long (at most {_MAX_SCRIPT_CLASS})",
            hint="give the entry a shorter 'class:'; " + _LONG_CLASS_HINT,
        )
    return derived


_LONG_CLASS_HINT = (
    f"the class names its files, and the longest, Name.User.cs.meta, must fit the "
    f"{MAX_NAME_BYTES} bytes a file name holds"
)


def read_topic(r: Reader, node: YNode, ctx: Context) -> Topic | None:
    m = r.mapping(node, spec.TOPIC)
    if m is None:
        return None
    name = _ros_name(r, m, ctx)
    type_ = r.text(
        m,
        "type",
        EXPECT_MSG_TYPE,
        spec.MSG_TYPE,
        hint=_type_hint(m, "msg"),
    )
    if type_ is not None and not _no_action_part(r, m, ctx, EXPECT_MSG_TYPE):
        type_ = None
    choice = r.choice(m, "direction", [d.value for d in Direction])
    direction = Direction(choice) if choice else None
    rates = read_rates(r, m, direction, ctx.runtime)
    topic = Topic(
        name=name or "",
        type=type_ or "",
        direction=direction or Direction.PUBLISH,
        gameobject=read_gameobject(r, m, ctx.connector_gameobject) or "",
        scene=read_scene(r, m, ctx, "topic") or "",
        create=_create(r, m, ctx),
        class_name=_class_name(r, m, name, direction),
        rate=rates.rate,
        throttle=rates.throttle,
        queue=rates.queue,
        locations=locations(m),
        latch=rates.latch,
    )
    return topic if name and type_ and direction else None


def _create(r: Reader, m: YMap, ctx: Context) -> bool:
    value = r.boolean(m, "create")
    return ctx.create if value is None else value


def read_service(r: Reader, node: YNode, ctx: Context) -> Service | None:
    return _read_role_entry(r, node, ctx, Service, spec.SERVICE, "srv", EXPECT_SRV_TYPE)


def read_action(r: Reader, node: YNode, ctx: Context) -> Action | None:
    return _read_role_entry(r, node, ctx, Action, spec.ACTION, "action", EXPECT_ACTION_TYPE)


_RoleEntry = TypeVar("_RoleEntry", Service, Action)


def _read_role_entry(
    r: Reader,
    node: YNode,
    ctx: Context,
    entry: type[_RoleEntry],
    section: spec.Section,
    kind: str,
    expected_type: str,
) -> _RoleEntry | None:
    """A service or an action: the same keys, read in the same order (so their errors come in
    the same order); they differ only in the kind of type they name."""
    m = r.mapping(node, section)
    if m is None:
        return None
    in_actions = kind == "action"
    pattern = spec.ACTION_TYPE if in_actions else spec.SRV_TYPE
    name = _ros_name(r, m, ctx)
    type_ = r.text(m, "type", expected_type, pattern, hint=_type_hint(m, kind))
    if type_ is not None and not _no_action_part(r, m, ctx, expected_type, in_actions=in_actions):
        type_ = None
    if type_ is not None and in_actions and not _action_carried(r, m, ctx):
        type_ = None
    choice = r.choice(m, "role", [x.value for x in Role])
    role = Role(choice) if choice else None
    read = entry(
        name=name or "",
        type=type_ or "",
        role=role or Role.CLIENT,
        gameobject=read_gameobject(r, m, ctx.connector_gameobject) or "",
        scene=read_scene(r, m, ctx, "action" if in_actions else "service") or "",
        create=_create(r, m, ctx),
        class_name=_class_name(r, m, name, role, action=in_actions),
        locations=locations(m),
    )
    return read if name and type_ and role else None


def _action_carried(r: Reader, m: YMap, ctx: Context) -> bool:
    """False (reported) for a ROS 2 action under ROS-TCP-Connector: its endpoint resolves
    message and service types only (``pkg.msg``, ``pkg.srv``), never ``pkg.action``."""
    if ctx.ros != 2 or ctx.runtime is not Runtime.TCP_CONNECTOR:
        return True
    r.error(
        m.get("type").value.location,  # type: ignore[union-attr]
        "ROS 2 actions cannot pass through ROS-TCP-Connector: its ROS 2 endpoint "
        "(ROS-TCP-Endpoint) resolves only message and service types, not pkg/action/ types",
        hint="use runtime: ros-sharp for this action (rosbridge carries ROS 2 actions), or "
        "call the action through a service of your own on the ROS side",
    )
    return False


def read_component(r: Reader, node: YNode, ctx: Context) -> Component | None:
    m = r.mapping(node, spec.COMPONENT)
    if m is None:
        return None
    script = _script(r, m, ctx) if m.get("script") is not None else None
    guid = r.text(m, "guid", "a GUID: 32 lowercase hex digits", spec.GUID)
    dll_class = r.text(m, "dll_class", "Namespace.Class of a script inside a DLL", spec.NAMESPACE)
    if m.get("script") is None and m.get("guid") is None:
        r.error(
            m.location,
            "component is missing required key 'script' (or 'guid')",
            hint="script: the class name (TwistSubscriber, Image) or the .cs path; "
            "guid: a package script's GUID",
        )
    if (entry := m.get("dll_class")) is not None and m.get("guid") is None:
        r.error(entry.key_location, "'dll_class' goes with 'guid' (the DLL's GUID)")
    gameobject = read_gameobject(r, m, None)
    label = script or (dll_class.rsplit(".", 1)[-1] if dll_class else guid)
    component = Component(
        script=label or "",
        gameobject=gameobject or "",
        scene=read_scene(r, m, ctx, "component") or "",
        create=_create(r, m, ctx),
        fields=read_fields(r, m),
        locations=locations(m),
        guid=guid,
        dll_class=dll_class,
        key=r.text(m, "id", "a short name of letters, digits, '_', '-' or '.'", spec.KEY),
    )
    return component if label and gameobject else None


def _script(r: Reader, m: YMap, ctx: Context) -> str | None:
    value = r.text(m, "script", EXPECT_SCRIPT)
    if value is None:
        return None
    entry = m.get("script")
    assert entry is not None
    if value.endswith(".cs"):
        return project_path(r, entry, value, ctx.project_root, expected=EXPECT_SCRIPT)
    if not re.fullmatch(spec.NAMESPACE.strip("^$"), value):
        r.invalid(
            entry,
            EXPECT_SCRIPT,
            hint="a class name may be qualified with its "
            "namespace (RosSharp.RosBridgeClient.TwistSubscriber)",
        )
        return None
    return value
