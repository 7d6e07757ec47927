"""The one description of the manifest's keys, read by the validator, the JSON Schema and docs.

Each mapping of the manifest is a ``Section`` listing its keys, with a description, a JSON
Schema fragment for the value, and its default. The validator takes the allowed and required
keys from here, and ``schema.build_schema`` turns the same table into ``robot.schema.json``, so
the two cannot drift apart. Patterns are written in the subset of regex syntax that Python and
JSON Schema (ECMA 262) read alike.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

from unityscaffold.manifest.model import (
    CSHARP_IDENTIFIER,
    CSHARP_KEYWORDS,
    MANIFEST_VERSION,
    Direction,
    Protocol,
    Role,
    Serializer,
)

__all__ = ["SECTIONS", "Key", "Section", "patterns"]

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
    "Rigidbody",
    "SphereCollider",
)
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
        "not_portable": NOT_PORTABLE,
        "not_relative": NOT_RELATIVE,
        "keyword_part": KEYWORD_PART,
        "ros2_action_part": ROS2_ACTION_PART,
        "guid": GUID,
        "key": KEY,
    }


def _ref(name: str) -> dict[str, Any]:
    return {"$ref": f"#/$defs/{name}"}


def _list_of(item: Mapping[str, Any]) -> dict[str, Any]:
    # null is accepted so that a key whose entries are all commented out is still valid
    return {"type": ["array", "null"], "items": dict(item)}


_STR = {"type": "string", "minLength": 1}
_BOOL = {"type": "boolean"}
_SCENE = {"type": "string", "pattern": SCENE, "not": {"pattern": NOT_RELATIVE}}
_GAMEOBJECT = {"type": "string", "pattern": GAMEOBJECT}
_CREATE = Key(
    "create",
    "Create the GameObject (and missing parents) if the scene lacks it. "
    "Overrides the top-level `create_gameobjects`.",
    _BOOL,
)
_CLASS = Key(
    "class",
    "Name of the generated C# class, overriding the one derived from the "
    "name (e.g. `/cmd_vel` publish gives `CmdVelPublisher`).",
    {"type": "string", "pattern": CLASS_NAME, "not": {"enum": sorted(CSHARP_KEYWORDS)}},
)


def _scene_key(what: str) -> Key:
    return Key(
        "scene",
        f"Scene that holds the {what}, relative to the project "
        "(e.g. `Assets/Scenes/Main.unity`). Default: the top-level `scene`.",
        _SCENE,
    )


def _item_gameobject(what: str) -> Key:
    return Key(
        "gameobject",
        f"Hierarchy path (`Parent/Child`) of the GameObject that gets the "
        f"{what}. Default: the connector's GameObject, which ROS#'s components require.",
        _GAMEOBJECT,
    )


TOP = Section(
    "manifest",
    "manifest",
    "A robot.yaml manifest for unityscaffold.",
    (
        Key(
            "version",
            "Manifest format version.",
            {"type": "integer", "enum": [MANIFEST_VERSION]},
            required=True,
        ),
        Key(
            "ros",
            "ROS version of the robot: 1 or 2.",
            {"type": "integer", "enum": [1, 2]},
            required=True,
        ),
        Key(
            "project",
            "Unity project root (the folder holding `Assets/`), relative to this file.",
            {**_STR, "not": {"pattern": NOT_RELATIVE}},
            default=".",
        ),
        Key(
            "output",
            "Folder for generated code, relative to the project; must be inside `Assets/`.",
            {"type": "string", "pattern": "^(\\./)?Assets/.", "not": {"pattern": NOT_PORTABLE}},
            default="Assets/RosGenerated",
        ),
        Key(
            "namespace",
            "C# root namespace for generated code, overriding the default.",
            {"type": "string", "pattern": NAMESPACE, "not": {"pattern": KEYWORD_PART}},
        ),
        Key(
            "include_shipped",
            "Also generate classes for message packages that ROS# already "
            "ships (std_msgs, geometry_msgs, …); normally their ROS# classes are used.",
            _BOOL,
            default=False,
        ),
        Key(
            "interfaces",
            "Extra folders searched for `.msg`/`.srv`/`.action` files (workspaces, "
            "a definitions cache), relative to this file.",
            _list_of({**_STR, "not": {"pattern": NOT_PORTABLE}}),
        ),
        Key(
            "scene",
            "Default scene for the connector, topics, services, actions and components, relative "
            "to the project. Required unless every entry names its own.",
            _SCENE,
        ),
        Key(
            "create_gameobjects",
            "Create GameObjects named by entries when the scene lacks them.",
            _BOOL,
            default=True,
        ),
        Key(
            "connector",
            "ROS#'s RosConnector: where it lives and its settings.",
            {"anyOf": [_ref("connector"), {"type": "null"}]},
        ),
        Key("topics", "Topics Unity publishes or subscribes to.", _list_of(_ref("topic"))),
        Key("services", "Services Unity calls or provides.", _list_of(_ref("service"))),
        Key(
            "actions",
            "Actions Unity sends goals to (client) or carries out (server).",
            _list_of(_ref("action")),
        ),
        Key(
            "components",
            "Existing MonoBehaviours (yours, ROS#'s or a package's) to add with field values.",
            _list_of(_ref("component")),
        ),
        Key(
            "objects",
            "GameObjects to create and keep as declared: transform, active flag, tag, layer, "
            "UI layout and built-in components (Camera, Light, colliders, Canvas, …).",
            _list_of(_ref("object")),
        ),
    ),
    rules=(
        {
            "if": {"properties": {"ros": {"const": 2}}, "required": ["ros"]},
            "then": {
                "properties": {
                    key: {
                        "items": {
                            "properties": {
                                "name": {"not": {"pattern": ROS2_NAME_NOT}},
                                "type": {"not": {"pattern": ROS2_ACTION_PART}},
                            }
                        }
                    }
                    for key in ("topics", "services", "actions")
                }
            },
        },
    ),
)

CONNECTOR = Section(
    "connector",
    "connector",
    "ROS#'s RosConnector component.",
    (
        Key(
            "scene",
            "Scene of the RosConnector, relative to the project. Default: the top-level `scene`.",
            _SCENE,
        ),
        Key(
            "gameobject",
            "Hierarchy path of the GameObject holding the RosConnector; created if missing.",
            _GAMEOBJECT,
            default="RosConnector",
        ),
        Key(
            "url",
            "rosbridge WebSocket URL (`RosBridgeServerUrl`).",
            {"type": "string", "pattern": URL},
            default="ws://localhost:9090",
        ),
        Key(
            "timeout",
            "Connection timeout in seconds (`SecondsTimeout`).",
            {"type": "integer", "minimum": 1, "maximum": INT32_MAX},
            default=DEFAULT_TIMEOUT,
        ),
        Key(
            "serializer",
            "JSON serializer (`Serializer`): `microsoft` is System.Text.Json.",
            {"enum": [s.key for s in Serializer]},
            default=Serializer.MICROSOFT.key,
        ),
        Key(
            "protocol",
            "WebSocket implementation (`protocol`).",
            {"enum": [p.key for p in Protocol]},
            default=Protocol.WEBSOCKET_SHARP.key,
        ),
    ),
)

TOPIC = Section(
    "topic",
    "topic",
    "A topic Unity publishes or subscribes to.",
    (
        Key(
            "name",
            "ROS topic name, e.g. `/cmd_vel`.",
            {"type": "string", "pattern": ROS_NAME},
            required=True,
        ),
        Key(
            "type",
            "Message type, `pkg/Name` or `pkg/msg/Name`.",
            {"type": "string", "pattern": MSG_TYPE},
            required=True,
        ),
        Key(
            "direction",
            "`publish` (Unity sends) or `subscribe` (Unity receives).",
            {"enum": [d.value for d in Direction]},
            required=True,
        ),
        _item_gameobject("generated script"),
        _scene_key("GameObject"),
        _CREATE,
        Key(
            "rate",
            "Publish only: messages per second (Hz). Absent: publish on demand.",
            # NaN passes every comparison, so "not above the largest float" is what refuses it
            # in a JSON Schema validator (as "maximum" refuses .inf)
            {
                "type": "number",
                "minimum": FLOAT32_TINY,
                "maximum": FLOAT32_MAX,
                "not": {"exclusiveMinimum": FLOAT32_MAX},
            },
        ),
        Key(
            "throttle",
            "Subscribe only: minimum milliseconds between messages (rosbridge `throttle_rate`).",
            {"type": "integer", "minimum": 0, "maximum": INT32_MAX},
        ),
        Key(
            "queue",
            "Subscribe only: rosbridge `queue_length`.",
            {"type": "integer", "minimum": 1, "maximum": INT32_MAX},
        ),
        _CLASS,
    ),
    rules=(
        {
            "if": {"properties": {"direction": {"const": "publish"}}, "required": ["direction"]},
            "then": {"properties": {"throttle": False, "queue": False}},
        },
        {
            "if": {"properties": {"direction": {"const": "subscribe"}}, "required": ["direction"]},
            "then": {"properties": {"rate": False}},
        },
    ),
)

SERVICE = Section(
    "service",
    "service",
    "A service Unity calls or provides.",
    (
        Key(
            "name",
            "ROS service name, e.g. `/reset`.",
            {"type": "string", "pattern": ROS_NAME},
            required=True,
        ),
        Key(
            "type",
            "Service type, `pkg/Name` or `pkg/srv/Name`.",
            {"type": "string", "pattern": SRV_TYPE},
            required=True,
        ),
        Key(
            "role",
            "`client` (Unity calls it) or `server` (Unity provides it).",
            {"enum": [r.value for r in Role]},
            required=True,
        ),
        _item_gameobject("generated script"),
        _scene_key("GameObject"),
        _CREATE,
        _CLASS,
    ),
)

ACTION = Section(
    "action",
    "action",
    "An action Unity sends goals to or carries out.",
    (
        Key(
            "name",
            "ROS action name, e.g. `/dock` (ROS 1: the namespace of its goal, cancel, status, "
            "feedback and result topics).",
            {"type": "string", "pattern": ROS_NAME},
            required=True,
        ),
        Key(
            "type",
            "Action type, `pkg/action/Name` or `pkg/Name` (ROS 1: the `.action` file's "
            "name, not its `pkg/NameAction` message).",
            {"type": "string", "pattern": ACTION_TYPE},
            required=True,
        ),
        Key(
            "role",
            "`client` (Unity sends goals) or `server` (Unity carries them out).",
            {"enum": [r.value for r in Role]},
            required=True,
        ),
        _item_gameobject("generated script"),
        _scene_key("GameObject"),
        _CREATE,
        _CLASS,
    ),
)

COMPONENT = Section(
    "component",
    "component",
    "An existing MonoBehaviour with field values.",
    (
        Key(
            "script",
            "Class name of the MonoBehaviour (e.g. `TwistSubscriber`, or uGUI's `Image`) or the "
            "path of its `.cs` file, relative to the project. Required unless `guid` is given.",
            {
                "type": "string",
                "anyOf": [
                    {"pattern": "[.]cs$", "not": {"pattern": NOT_RELATIVE}},
                    {"pattern": NAMESPACE},
                ],
            },
        ),
        Key(
            "guid",
            "GUID of a package's script (from its `.meta`), or of the DLL holding it with "
            "`dll_class`; `script` then only names it in messages.",
            {"type": "string", "pattern": GUID},
        ),
        Key(
            "dll_class",
            "`Namespace.Class` of the script inside the DLL whose GUID is `guid`.",
            {"type": "string", "pattern": NAMESPACE},
        ),
        Key(
            "id",
            "Tells apart several instances of one script on one GameObject (e.g. two "
            "`JoyAxisReader`s): any short name, kept stable across runs.",
            {"type": "string", "pattern": KEY},
        ),
        Key(
            "gameobject",
            "Hierarchy path of the GameObject that gets the component.",
            _GAMEOBJECT,
            required=True,
        ),
        _scene_key("GameObject"),
        _CREATE,
        Key(
            "fields",
            "Serialized field values by field name. A text starting with `@` refers to "
            "a GameObject (`@Robot/base_link`) or a component on one "
            "(`@RosConnector:RosConnector`) in the same scene; write `@@` for a literal `@`.",
            {
                "type": ["object", "null"],
                "propertyNames": {"pattern": CLASS_NAME},
                "additionalProperties": _ref("fieldValue"),
            },
        ),
    ),
    rules=(
        {"anyOf": [{"required": ["script"]}, {"required": ["guid"]}]},
        {"dependentRequired": {"dll_class": ["guid"]}},
    ),
)

_FLOAT = {"type": "number", "minimum": -FLOAT32_MAX, "maximum": FLOAT32_MAX}
_VEC3 = {"type": "array", "items": _FLOAT, "minItems": 3, "maxItems": 3}
_VEC2 = {"type": "array", "items": _FLOAT, "minItems": 2, "maxItems": 2}

UI = Section(
    "ui",
    "ui",
    "A UI object's RectTransform; keys left out keep the scene's values (new: Unity's defaults).",
    (
        Key("anchor_min", "`m_AnchorMin`, e.g. `[0, 0]`.", _VEC2),
        Key("anchor_max", "`m_AnchorMax`, e.g. `[1, 1]`.", _VEC2),
        Key("position", "`m_AnchoredPosition` in pixels, e.g. `[150, 150]`.", _VEC2),
        Key("size", "`m_SizeDelta` in pixels, e.g. `[100, 100]`.", _VEC2),
        Key("pivot", "`m_Pivot`, e.g. `[0.5, 0.5]`.", _VEC2),
    ),
)

BUILTIN = Section(
    "built-in component",
    "builtinComponent",
    "A built-in Unity component of a declared object.",
    (
        Key(
            "type",
            "Class of the component: " + ", ".join(f"`{name}`" for name in BUILTIN_TYPES) + ".",
            {"enum": list(BUILTIN_TYPES)},
            required=True,
        ),
        Key(
            "id",
            "Tells apart several components of one class on the object.",
            {"type": "string", "pattern": KEY},
        ),
        Key(
            "fields",
            "Values by Unity's serialized name (`m_Mass`, `m_IsTrigger`, `m_Size`); the rest "
            "keep Unity's defaults.",
            {"type": ["object", "null"], "additionalProperties": _ref("fieldValue")},
        ),
    ),
)

OBJECT = Section(
    "object",
    "object",
    "A GameObject created if missing and kept as declared; keys left out keep the scene's values.",
    (
        Key(
            "path",
            "Hierarchy path (`Parent/Child`); missing parents are created as empty objects.",
            _GAMEOBJECT,
            required=True,
        ),
        _scene_key("object"),
        Key("position", "Local position `[x, y, z]`.", _VEC3),
        Key(
            "rotation",
            "Local rotation as Euler angles in degrees `[x, y, z]`, as the Inspector shows it.",
            _VEC3,
        ),
        Key("scale", "Local scale `[x, y, z]`.", _VEC3),
        Key("active", "Whether the GameObject is active.", _BOOL),
        Key(
            "tag",
            "Tag: a built-in one (`MainCamera`, `Player`, …) or one in "
            "ProjectSettings/TagManager.asset.",
            _STR,
        ),
        Key(
            "layer",
            "Layer number 0–31, or a built-in layer's name (" + ", ".join(BUILTIN_LAYERS) + ").",
            {"anyOf": [{"type": "integer", "minimum": 0, "maximum": 31}, {"enum": BUILTIN_LAYERS}]},
        ),
        Key(
            "ui",
            "`true` (or a mapping of its layout) for a UI object with a RectTransform.",
            {"anyOf": [{"type": "boolean"}, _ref("ui")]},
        ),
        Key(
            "components",
            "Built-in components: a class name (`Camera`) or `{type, id, fields}`.",
            _list_of({"anyOf": [{"enum": list(BUILTIN_TYPES)}, _ref("builtinComponent")]}),
        ),
    ),
)

SECTIONS: tuple[Section, ...] = (
    TOP,
    CONNECTOR,
    TOPIC,
    SERVICE,
    ACTION,
    COMPONENT,
    OBJECT,
    UI,
    BUILTIN,
)
