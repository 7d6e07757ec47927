"""The one description of the manifest's keys, read by the validator, the JSON Schema and docs.

Each mapping of the manifest is a ``Section`` listing its keys, with a description, a JSON
Schema fragment for the value, and its default. The validator takes the allowed and required
keys from here, and ``schema.build_schema`` turns the same table into ``robot.schema.json``, so
the two cannot drift apart. Patterns are written in the subset of regex syntax that Python and
JSON Schema (ECMA 262) read alike.

The sections of the robot's interfaces are here, the declared objects' in ``_spec_objects``;
``Key``, ``Section``, the patterns and the fragments both share are in ``_keys``.
"""

from __future__ import annotations

from unityscaffold.manifest._keys import (
    ACTION_TYPE,
    BOOL,
    BUILTIN_LAYERS,
    BUILTIN_TYPES,
    CLASS,
    CLASS_NAME,
    CREATE,
    DEFAULT_TIMEOUT,
    FLOAT32_MAX,
    FLOAT32_TINY,
    GAMEOBJECT,
    GAMEOBJECT_VALUE,
    GUID,
    HOST,
    INT32_MAX,
    KEY,
    KEYWORD_PART,
    LAYER_NUMBERS,
    MSG_TYPE,
    NAMESPACE,
    NO_DEFAULT,
    NOT_PORTABLE,
    NOT_RELATIVE,
    ROS2_ACTION_PART,
    ROS2_NAME_NOT,
    ROS_NAME,
    SCENE,
    SCENE_VALUE,
    SRV_TYPE,
    STR,
    URL,
    Key,
    Section,
    item_gameobject,
    list_of,
    patterns,
    ref,
    scene_key,
)
from unityscaffold.manifest._spec_connector import (
    CONNECTOR,
    RUNTIME,
    RUNTIME_RULES,
    TCP_CONNECTOR,
)
from unityscaffold.manifest._spec_objects import BUILTIN, OBJECT, UI
from unityscaffold.manifest._spec_robots import ROBOT
from unityscaffold.manifest.model import MANIFEST_VERSION, Direction, Role

__all__ = [
    "ACTION",
    "ACTION_TYPE",
    "BUILTIN",
    "BUILTIN_LAYERS",
    "BUILTIN_TYPES",
    "CLASS_NAME",
    "COMPONENT",
    "CONNECTOR",
    "DEFAULT_TIMEOUT",
    "FLOAT32_MAX",
    "FLOAT32_TINY",
    "GAMEOBJECT",
    "GUID",
    "HOST",
    "INT32_MAX",
    "KEY",
    "KEYWORD_PART",
    "LAYER_NUMBERS",
    "MSG_TYPE",
    "NAMESPACE",
    "NOT_PORTABLE",
    "NOT_RELATIVE",
    "NO_DEFAULT",
    "OBJECT",
    "ROBOT",
    "ROS2_ACTION_PART",
    "ROS2_NAME_NOT",
    "ROS_NAME",
    "SCENE",
    "SECTIONS",
    "SERVICE",
    "SRV_TYPE",
    "TCP_CONNECTOR",
    "TOP",
    "TOPIC",
    "UI",
    "URL",
    "Key",
    "Section",
    "patterns",
]


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
        RUNTIME,
        Key(
            "project",
            "Unity project root (the folder holding `Assets/`), relative to this file.",
            {**STR, "not": {"pattern": NOT_RELATIVE}},
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
            BOOL,
            default=False,
        ),
        Key(
            "interfaces",
            "Extra folders searched for `.msg`/`.srv`/`.action` files (workspaces, "
            "a definitions cache), relative to this file.",
            list_of({**STR, "not": {"pattern": NOT_PORTABLE}}),
        ),
        Key(
            "scene",
            "Default scene for the connector, topics, services, actions and components, relative "
            "to the project. Required unless every entry names its own.",
            SCENE_VALUE,
        ),
        Key(
            "create_gameobjects",
            "Create GameObjects named by entries when the scene lacks them.",
            BOOL,
            default=True,
        ),
        Key(
            "connector",
            "The runtime's connection component (ROS#'s RosConnector, ROS-TCP-Connector's "
            "ROSConnection): where it lives and its settings.",
            {"anyOf": [ref(CONNECTOR.ref), ref(TCP_CONNECTOR.ref), {"type": "null"}]},
        ),
        Key("topics", "Topics Unity publishes or subscribes to.", list_of(ref("topic"))),
        Key("services", "Services Unity calls or provides.", list_of(ref("service"))),
        Key(
            "actions",
            "Actions Unity sends goals to (client) or carries out (server).",
            list_of(ref("action")),
        ),
        Key(
            "components",
            "Existing MonoBehaviours (yours, ROS#'s or a package's) to add with field values.",
            list_of(ref("component")),
        ),
        Key(
            "objects",
            "GameObjects to create and keep as declared: transform, active flag, tag, layer, "
            "UI layout and built-in components (Camera, Light, colliders, Canvas, …).",
            list_of(ref("object")),
        ),
        Key(
            "robots",
            "Robots imported from their URDF into a scene, as ROS#'s importer does it.",
            list_of(ref("robot")),
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
        *RUNTIME_RULES,
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
        item_gameobject("generated script"),
        scene_key("GameObject"),
        CREATE,
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
            "ros-sharp, subscribe only: minimum milliseconds between messages (rosbridge "
            "`throttle_rate`).",
            {"type": "integer", "minimum": 0, "maximum": INT32_MAX},
        ),
        Key(
            "queue",
            "ros-sharp, subscribe only: rosbridge `queue_length`; ros-tcp-connector, publish "
            "only: the ROS publisher's `queue_size`.",
            {"type": "integer", "minimum": 1, "maximum": INT32_MAX},
        ),
        Key(
            "latch",
            "ros-tcp-connector, publish only: latch the ROS publisher (the last message goes "
            "to every later subscriber).",
            BOOL,
        ),
        CLASS,
    ),
    rules=(
        {
            "if": {"properties": {"direction": {"const": "publish"}}, "required": ["direction"]},
            "then": {"properties": {"throttle": False}},
        },
        {
            "if": {"properties": {"direction": {"const": "subscribe"}}, "required": ["direction"]},
            "then": {"properties": {"rate": False, "latch": False}},
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
        item_gameobject("generated script"),
        scene_key("GameObject"),
        CREATE,
        CLASS,
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
        item_gameobject("generated script"),
        scene_key("GameObject"),
        CREATE,
        CLASS,
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
            GAMEOBJECT_VALUE,
            required=True,
        ),
        scene_key("GameObject"),
        CREATE,
        Key(
            "fields",
            "Serialized field values by field name. A text starting with `@` refers to "
            "a GameObject (`@Robot/base_link`) or a component on one "
            "(`@RosConnector:RosConnector`) in the same scene; write `@@` for a literal `@`.",
            {
                "type": ["object", "null"],
                "propertyNames": {"pattern": CLASS_NAME},
                "additionalProperties": ref("fieldValue"),
            },
        ),
    ),
    rules=(
        {"anyOf": [{"required": ["script"]}, {"required": ["guid"]}]},
        {"dependentRequired": {"dll_class": ["guid"]}},
    ),
)

SECTIONS: tuple[Section, ...] = (
    TOP,
    CONNECTOR,
    TCP_CONNECTOR,
    TOPIC,
    SERVICE,
    ACTION,
    COMPONENT,
    OBJECT,
    UI,
    BUILTIN,
    ROBOT,
)
