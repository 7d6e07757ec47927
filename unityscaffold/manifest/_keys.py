"""The parts of the manifest's key table: ``Key`` and ``Section``, the patterns of names and
paths, and the schema fragments several sections share (see ``_spec``, which lists them)."""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

from unityscaffold.manifest.model import CSHARP_IDENTIFIER, CSHARP_KEYWORDS

_WORD = "[A-Za-z][A-Za-z0-9_]*"
# ROS 1's rule (a part may start with '_' after a '/'); ROS 2 also forbids '__' (ROS2_NAME_NOT).
ROS_NAME = "^(/[A-Za-z_]|[A-Za-z])[A-Za-z0-9_]*(/[A-Za-z_][A-Za-z0-9_]*)*$"
ROS2_NAME_NOT = "__"
# What rosidl appends to an action's name for the messages and services it derives; ROS 2
# interface names have no '_', so a type ending so is a part of an action, used only whole.
ROS2_ACTION_PART = "_(Goal|Result|Feedback|FeedbackMessage|SendGoal|GetResult)$"
MSG_TYPE = f"^{_WORD}/(msg/)?{_WORD}$"
SRV_TYPE = f"^{_WORD}/(srv/)?{_WORD}$"
ACTION_TYPE = f"^{_WORD}/(action/)?{_WORD}$"
CLASS_NAME = f"^{CSHARP_IDENTIFIER}$"
NAMESPACE = f"^{CSHARP_IDENTIFIER}([.]{CSHARP_IDENTIFIER})*$"
GAMEOBJECT = "^[^/]+(/[^/]+)*$"
SCENE = "[.]unity$"
URL = "^wss?://[^\\s/]+(/\\S*)?$"
# An IPv4 address or a host name (ROSConnection's m_RosIPAddress; it resolves either).
_LABEL = "[A-Za-z0-9]([A-Za-z0-9-]*[A-Za-z0-9])?"
HOST = f"^{_LABEL}([.]{_LABEL})*$"
GUID = "^[0-9a-f]{32}$"
KEY = "^[A-Za-z0-9_.-]+$"
#: The largest C# ``int``: timeout, throttle and queue become int fields in C#.
INT32_MAX = 2**31 - 1
#: The positive range of a C# ``float`` (rate): its smallest normal value and its largest.
FLOAT32_TINY, FLOAT32_MAX = 1.1754943508222875e-38, 3.4028234663852886e38
# What a path in the manifest must not contain: a '\' separator (the manifest is shared across
# systems), and for paths inside the project a leading '/' or drive letter.
NOT_PORTABLE = "\\\\"
NOT_RELATIVE = "\\\\|^/|^[A-Za-z]:"
# A C# keyword as one part of a dotted name; such a class or namespace would not compile.
KEYWORD_PART = f"(^|[.])({'|'.join(sorted(CSHARP_KEYWORDS))})([.]|$)"

#: The built-in component classes an object may declare and the built-in layers by number.
#: ``unity/builtins.py`` holds their layouts; a test keeps the two lists equal (importing the
#: unity stage here would load the whole scene patcher for every command that reads a manifest).
BUILTIN_TYPES = (
    "AudioListener",
    "BoxCollider",
    "Camera",
    "Canvas",
    "CanvasRenderer",
    "CapsuleCollider",
    "Light",
    "MeshCollider",
    "MeshFilter",
    "MeshRenderer",
    "Rigidbody",
    "SphereCollider",
)
#: The shapes an object may be made as, the six of Unity's GameObject > 3D Object menu
#: (``unity/builtins.py``'s PRIMITIVES, kept equal by a test).
PRIMITIVE_NAMES = ("capsule", "cube", "cylinder", "plane", "quad", "sphere")
LAYER_NUMBERS = {"Default": 0, "TransparentFX": 1, "Ignore Raycast": 2, "Water": 4, "UI": 5}
BUILTIN_LAYERS = list(LAYER_NUMBERS)

NO_DEFAULT = object()
DEFAULT_TIMEOUT = 10


@dataclass(frozen=True, slots=True)
class Key:
    name: str
    doc: str
    schema: Mapping[str, Any]
    required: bool = False
    default: object = NO_DEFAULT


@dataclass(frozen=True, slots=True)
class Section:
    """A mapping in the manifest. ``label`` names it in messages, ``ref`` in the schema."""

    label: str
    ref: str
    doc: str
    keys: tuple[Key, ...]
    rules: tuple[Mapping[str, Any], ...] = ()
    #: Keys of a sibling section that this one refuses, each with the hint that says why
    #: (the other runtime's ``connector:`` keys).
    foreign: tuple[tuple[str, str], ...] = ()

    @property
    def names(self) -> tuple[str, ...]:
        return tuple(k.name for k in self.keys)

    @property
    def required(self) -> tuple[str, ...]:
        return tuple(k.name for k in self.keys if k.required)

    def key(self, name: str) -> Key:
        return next(k for k in self.keys if k.name == name)


def patterns() -> dict[str, str]:
    """Every pattern by name, for tests that check Python and the schema agree on them."""
    return {
        "ros_name": ROS_NAME,
        "msg_type": MSG_TYPE,
        "srv_type": SRV_TYPE,
        "action_type": ACTION_TYPE,
        "class": CLASS_NAME,
        "namespace": NAMESPACE,
        "gameobject": GAMEOBJECT,
        "scene": SCENE,
        "url": URL,
        "host": HOST,
        "not_portable": NOT_PORTABLE,
        "not_relative": NOT_RELATIVE,
        "keyword_part": KEYWORD_PART,
        "ros2_action_part": ROS2_ACTION_PART,
        "guid": GUID,
        "key": KEY,
    }


def ref(name: str) -> dict[str, Any]:
    return {"$ref": f"#/$defs/{name}"}


def list_of(item: Mapping[str, Any]) -> dict[str, Any]:
    # null is accepted so that a key whose entries are all commented out is still valid
    return {"type": ["array", "null"], "items": dict(item)}


STR = {"type": "string", "minLength": 1}
BOOL = {"type": "boolean"}
SCENE_VALUE = {"type": "string", "pattern": SCENE, "not": {"pattern": NOT_RELATIVE}}
GAMEOBJECT_VALUE = {"type": "string", "pattern": GAMEOBJECT}
CREATE = Key(
    "create",
    "Create the GameObject (and missing parents) if the scene lacks it. "
    "Overrides the top-level `create_gameobjects`.",
    BOOL,
)
CLASS = Key(
    "class",
    "Name of the generated C# class, overriding the one derived from the "
    "name (e.g. `/cmd_vel` publish gives `CmdVelPublisher`).",
    {"type": "string", "pattern": CLASS_NAME, "not": {"enum": sorted(CSHARP_KEYWORDS)}},
)


def scene_key(what: str) -> Key:
    return Key(
        "scene",
        f"Scene that holds the {what}, relative to the project "
        "(e.g. `Assets/Scenes/Main.unity`). Default: the top-level `scene`.",
        SCENE_VALUE,
    )


def item_gameobject(what: str) -> Key:
    return Key(
        "gameobject",
        f"Hierarchy path (`Parent/Child`) of the GameObject that gets the "
        f"{what}. Default: the connector's GameObject, which ROS#'s components require.",
        GAMEOBJECT_VALUE,
    )
