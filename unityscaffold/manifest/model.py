"""The typed model of a loaded ``robot.yaml`` (manifest version 1).

Every default is already applied and every path is resolved, so later stages never look at the
YAML again. Each item keeps the positions of its keys' values (``Locations``) so that a problem
found later (an unknown type, a missing GameObject) is still reported at ``robot.yaml:LINE:COL``.
"""

from __future__ import annotations

import enum
import os
import re
from dataclasses import dataclass
from pathlib import Path

from unityscaffold.errors import SourceLocation
from unityscaffold.interfaces.model import Dialect
from unityscaffold.manifest.locations import Locations
from unityscaffold.manifest.robot_entry import RobotEntry
from unityscaffold.manifest.runtime import Runtime, TcpConnection

__all__ = [
    "CSHARP_IDENTIFIER",
    "CSHARP_KEYWORDS",
    "MANIFEST_VERSION",
    "Action",
    "BuiltinComponent",
    "Component",
    "ComponentField",
    "Connector",
    "Direction",
    "EmptyReference",
    "FieldValue",
    "Locations",
    "Manifest",
    "ObjectPath",
    "Protocol",
    "RectLayout",
    "Role",
    "SceneObject",
    "Serializer",
    "Service",
    "StructValue",
    "Topic",
    "default_class_name",
    "is_csharp_identifier",
    "value_text",
]

MANIFEST_VERSION = 1


class Direction(enum.Enum):
    """Which way a topic's messages flow, seen from Unity."""

    PUBLISH = "publish"
    SUBSCRIBE = "subscribe"


class Role(enum.Enum):
    """Which side of a service Unity takes."""

    CLIENT = "client"
    SERVER = "server"


class Serializer(enum.IntEnum):
    """ROS#'s ``RosSocket.SerializerEnum``; the value is what the scene stores."""

    MICROSOFT = 0
    NEWTONSOFT = 1

    @property
    def key(self) -> str:
        """The spelling used in the manifest."""
        return self.name.lower()


class Protocol(enum.IntEnum):
    """ROS#'s ``Protocols.Protocol``; the value is what the scene stores."""

    WEBSOCKET_SHARP = 0
    WEBSOCKET_NET = 1

    @property
    def key(self) -> str:
        """The spelling used in the manifest (``websocket-sharp``, ``websocket-net``)."""
        return self.name.lower().replace("_", "-")


@dataclass(frozen=True, slots=True)
class ObjectPath:
    """A reference from a component field to a GameObject (or a component on it) in its scene.

    Written ``@Robot/base_link`` or ``@RosConnector:RosConnector`` in the manifest; kept
    unresolved here because only the scene knows the fileIDs.
    """

    path: str
    component: str | None = None

    @property
    def segments(self) -> tuple[str, ...]:
        return tuple(self.path.split("/"))

    def __str__(self) -> str:
        suffix = f":{self.component}" if self.component else ""
        return f"@{self.path}{suffix}"


@dataclass(frozen=True, slots=True)
class StructValue:
    """A YAML mapping given as a field value (a serialized struct such as a Vector3)."""

    items: tuple[tuple[str, FieldValue], ...]

    def as_dict(self) -> dict[str, FieldValue]:
        return dict(self.items)


@dataclass(frozen=True, slots=True)
class EmptyReference:
    """``null`` as a field value: a reference to nothing (None in the Inspector,
    ``{fileID: 0}`` in the scene), for a field or list item that holds an object."""

    def __str__(self) -> str:
        return "null"


FieldValue = (
    bool | int | float | str | ObjectPath | EmptyReference | StructValue | tuple["FieldValue", ...]
)


def value_text(value: FieldValue) -> str:
    """A field value as the manifest writes it (YAML flow style), for messages."""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, StructValue):
        return "{" + ", ".join(f"{k}: {value_text(v)}" for k, v in value.items) + "}"
    if isinstance(value, tuple):
        return "[" + ", ".join(value_text(v) for v in value) + "]"
    if isinstance(value, str):
        return f"'{value}'" if value.isprintable() else repr(value)
    return str(value)


@dataclass(frozen=True, slots=True)
class ComponentField:
    """One serialized field value of a component, with where its value was written."""

    name: str
    value: FieldValue
    location: SourceLocation


@dataclass(frozen=True, slots=True)
class Connector:
    """The runtime's connection component: where it lives and its serialized settings.

    ``url`` … ``protocol`` are ROS#'s RosConnector's (at their defaults under the other
    runtime); ``tcp`` is ROS-TCP-Connector's ROSConnection's, None under ``ros-sharp``.
    """

    scene: str
    gameobject: str
    url: str
    timeout: int
    serializer: Serializer
    protocol: Protocol
    locations: Locations
    tcp: TcpConnection | None = None


@dataclass(frozen=True, slots=True)
class Topic:
    """A topic Unity publishes or subscribes to.

    ``scene`` is relative to the project root and already defaulted; ``create`` is the effective
    choice (the entry's ``create`` or the manifest's ``create_gameobjects``). ``rate`` is in Hz
    (None: publish on demand); ``throttle`` in milliseconds and ``queue`` are None when unset.
    ``queue`` is rosbridge's queue of a subscriber under ROS#, the ROS publisher's queue size
    under ROS-TCP-Connector, which also has ``latch`` (None when unset).
    """

    name: str
    type: str
    direction: Direction
    gameobject: str
    scene: str
    create: bool
    class_name: str
    rate: float | None
    throttle: int | None
    queue: int | None
    locations: Locations
    latch: bool | None = None


@dataclass(frozen=True, slots=True)
class Service:
    """A service Unity calls (client) or provides (server)."""

    name: str
    type: str
    role: Role
    gameobject: str
    scene: str
    create: bool
    class_name: str
    locations: Locations


@dataclass(frozen=True, slots=True)
class Action:
    """An action Unity sends goals to (client) or carries out (server).

    ``type`` is the action as written (``pkg/action/Name``); the script talks to ROS#'s ROS 2
    action API, or for ROS 1 to actionlib's topics under ``name`` (``name/goal``, …).
    """

    name: str
    type: str
    role: Role
    gameobject: str
    scene: str
    create: bool
    class_name: str
    locations: Locations


@dataclass(frozen=True, slots=True)
class Component:
    """An existing MonoBehaviour to put on a GameObject with the given field values.

    ``script`` is a class name (``TwistSubscriber``) or a project-relative ``.cs`` path; for a
    package script named by ``guid`` (and ``dll_class`` for one inside a DLL) it is the label
    shown in messages. ``key`` (the manifest's ``id``) tells apart several instances of one
    script on one GameObject.
    """

    script: str
    gameobject: str
    scene: str
    create: bool
    fields: tuple[ComponentField, ...]
    locations: Locations
    guid: str | None = None
    dll_class: str | None = None
    key: str | None = None

    @property
    def label(self) -> str:
        """How messages and the lock name the entry: ``JoyAxisReader`` or ``JoyAxisReader#x``."""
        return f"{self.script}#{self.key}" if self.key else self.script

    def field(self, name: str) -> ComponentField | None:
        return next((f for f in self.fields if f.name == name), None)


@dataclass(frozen=True, slots=True)
class BuiltinComponent:
    """A built-in Unity component (``Camera``, ``BoxCollider``, …) on a declared object.

    ``fields`` are Unity's serialized names (``m_Mass``); ``key`` tells apart several of one class.
    """

    type: str
    fields: tuple[ComponentField, ...]
    key: str | None
    location: SourceLocation


@dataclass(frozen=True, slots=True)
class RectLayout:
    """A UI object's RectTransform values; None keeps what the scene has (or Unity's default)."""

    anchor_min: tuple[float, float] | None = None
    anchor_max: tuple[float, float] | None = None
    position: tuple[float, float] | None = None  # m_AnchoredPosition
    size: tuple[float, float] | None = None  # m_SizeDelta
    pivot: tuple[float, float] | None = None


@dataclass(frozen=True, slots=True)
class SceneObject:
    """A GameObject the manifest declares, created if missing and kept as written.

    Only what is written is enforced: a value left out keeps what the scene has. ``rotation`` is
    Euler angles in degrees (Unity's Z, then X, then Y order); ``layer`` is 0–31; ``ui`` is None
    for a plain Transform, else the RectTransform's layout; ``sibling_index`` its place among its
    siblings (0 first), None to leave it where it is; ``primitive`` the shape whose components
    Unity's GameObject > 3D Object menu adds (``plane``), kept before ``components``.
    """

    path: str
    scene: str
    position: tuple[float, float, float] | None
    rotation: tuple[float, float, float] | None
    scale: tuple[float, float, float] | None
    active: bool | None
    tag: str | None
    layer: int | None
    ui: RectLayout | None
    components: tuple[BuiltinComponent, ...]
    locations: Locations
    sibling_index: int | None = None  # its place among its parent's children or the roots
    primitive: str | None = None  # "cube", "sphere", ...: what the 3D Object menu adds


@dataclass(frozen=True, slots=True)
class Manifest:
    """A validated manifest with every path absolute and every default applied.

    ``path`` is the manifest file, ``project_root`` the Unity project (its real path: links are
    followed once, when loading, so that paths below it compare as text), ``output_dir`` the
    folder for generated code (inside ``Assets/``); ``interfaces`` are real folders in the order
    written. ``namespace`` is None when the codegen default applies.
    """

    path: Path
    version: int
    ros: Dialect
    project_root: Path
    output_dir: Path
    namespace: str | None
    include_shipped: bool
    interfaces: tuple[Path, ...]
    scene: str | None
    create_gameobjects: bool
    connector: Connector
    topics: tuple[Topic, ...]
    services: tuple[Service, ...]
    components: tuple[Component, ...]
    locations: Locations
    objects: tuple[SceneObject, ...] = ()
    actions: tuple[Action, ...] = ()
    robots: tuple[RobotEntry, ...] = ()
    runtime: Runtime = Runtime.ROS_SHARP

    @property
    def output(self) -> str:
        """The output folder relative to the project root, POSIX style."""
        return self.asset_path(self.output_dir)

    def asset_path(self, path: Path) -> str:
        """A path inside the project as Unity names assets: relative to the root, POSIX style."""
        text, root = str(path), str(self.project_root)
        if text.startswith(root) and text[len(root) : len(root) + 1] == os.sep:
            return text[len(root) + 1 :].replace(os.sep, "/")  # the usual case, without pathlib
        return path.relative_to(self.project_root).as_posix()

    def scene_path(self, scene: str) -> Path:
        """The absolute path of a project-relative scene such as ``topic.scene``."""
        return self.project_root / scene

    @property
    def scenes(self) -> tuple[str, ...]:
        """Every scene the manifest touches, sorted."""
        named = {self.connector.scene}
        named.update(t.scene for t in self.topics)
        named.update(s.scene for s in self.services)
        named.update(a.scene for a in self.actions)
        named.update(c.scene for c in self.components)
        named.update(o.scene for o in self.objects)
        named.update(r.scene for r in self.robots)
        return tuple(sorted(named))


# The reserved C# keywords (codegen.naming keeps the same list plus the contextual ones, which
# are legal class names); a class named after one would not compile.
CSHARP_KEYWORDS = frozenset(
    (
        "abstract as base bool break byte case catch char checked class const continue decimal "
        "default delegate do double else enum event explicit extern false finally fixed float for "
        "foreach goto if implicit in int interface internal is lock long namespace new null object "
        "operator out override params private protected public readonly ref return sbyte sealed "
        "short sizeof stackalloc static string struct switch this throw true try typeof uint ulong "
        "unchecked unsafe ushort using virtual void volatile while"
    ).split(" ")
)
CSHARP_IDENTIFIER = r"[A-Za-z_][A-Za-z0-9_]*"
_IDENTIFIER_RE = re.compile(CSHARP_IDENTIFIER)
_SUFFIX: dict[Direction | Role, str] = {
    Direction.PUBLISH: "Publisher",
    Direction.SUBSCRIBE: "Subscriber",
    Role.CLIENT: "Client",
    Role.SERVER: "Server",
}


def is_csharp_identifier(name: str) -> bool:
    """True for a plain (ASCII, non-keyword) C# identifier usable as a class name."""
    return bool(_IDENTIFIER_RE.fullmatch(name)) and name not in CSHARP_KEYWORDS


def default_class_name(name: str, kind: Direction | Role, *, action: bool = False) -> str:
    """The generated script's class for a topic, service or action: ``/robot/odom`` →
    ``RobotOdom…``.

    Every ``/`` or ``_`` separated word is capitalised (the rest of the word is kept, so
    ``imuData`` stays ``ImuData``) and the suffix says what the class does: an action's
    says ``Action`` too (``/dock`` → ``DockActionClient``), apart from a service's class.
    """
    words = [w for w in re.split(r"[/_]+", name) if w]
    suffix = ("Action" if action else "") + _SUFFIX[kind]
    return "".join(w[0].upper() + w[1:] for w in words) + suffix
