"""The JSON Schema an editor checks robot.yaml with and ``scaffold`` agree on hand-made variants.

Each variant is a valid manifest with one value changed, written out as YAML text and read by
both: the jsonschema library with the shipped schema, and ``load_manifest``. Both accept it or
both refuse it, under ROS 1 and ROS 2. The only exceptions are the rules listed in
``TOOL_ONLY``, which need the file system or path arithmetic that JSON Schema does not have.
"""

from __future__ import annotations

import copy
from pathlib import Path
from typing import Any

import pytest
import yaml
from helpers import require
from ruamel.yaml import YAML

from unityscaffold.errors import LocatedError
from unityscaffold.manifest import load_manifest
from unityscaffold.manifest.schema import load_schema

BASE: dict[str, Any] = {
    "version": 1,
    "ros": 1,
    "project": ".",
    "output": "Assets/RosGenerated",
    "namespace": "MyRobot.Ros",
    "interfaces": ["defs"],
    "scene": "Assets/Scenes/Main.unity",
    "connector": {"gameobject": "RosConnector", "url": "ws://localhost:9090", "timeout": 5},
    "topics": [
        {"name": "/cmd_vel", "type": "geometry_msgs/Twist", "direction": "publish", "rate": 10},
        {
            "name": "/odom",
            "type": "nav_msgs/msg/Odometry",
            "direction": "subscribe",
            "throttle": 10,
            "queue": 1,
        },
    ],
    "services": [{"name": "/reset", "type": "std_srvs/Trigger", "role": "client"}],
    "actions": [{"name": "/dock", "type": "diffbot_msgs/action/Dock", "role": "server"}],
    "components": [{"script": "TwistSubscriber", "gameobject": "Robot", "fields": {"Topic": "/x"}}],
    "objects": [
        {
            "path": "Robot/Camera",
            "position": [0, 1, 0],
            "rotation": [0, 90, 0],
            "layer": 3,
            "ui": {"size": [100, 20]},
            "components": [
                "Camera",
                {"type": "BoxCollider", "id": "a", "fields": {"m_Size": [1, 2, 3]}},
            ],
        }
    ],
}
INF, NAN = float("inf"), float("nan")
# (where, value): where is a dotted path into BASE, list positions as numbers.
VARIANTS: list[tuple[str, Any]] = [
    # whole numbers written as decimals are whole numbers to both
    ("version", 1.0),
    ("version", 10.0),
    ("version", 2),
    ("version", 1.5),
    ("version", "1"),
    ("ros", 2.0),
    ("ros", 3),
    ("ros", "2"),
    ("ros", True),
    ("connector.timeout", 10.0),
    ("connector.timeout", 1.5),
    ("connector.timeout", 0),
    ("topics.1.throttle", 100.0),
    ("topics.1.throttle", -1),
    ("topics.1.queue", 1.0),
    ("topics.1.queue", 0),
    # rates: positive and finite
    ("topics.0.rate", 0.5),
    ("topics.0.rate", 1e308),
    ("topics.0.rate", INF),
    ("topics.0.rate", -INF),
    ("topics.0.rate", NAN),
    ("topics.0.rate", 0),
    ("topics.0.rate", "10"),
    # paths: '/' separators, relative where they must be
    ("scene", "Assets\\Scenes\\Main.unity"),
    ("scene", "/abs/Main.unity"),
    ("scene", "C:/Main.unity"),
    ("scene", "Assets/Scenes/Main.prefab"),
    ("output", "Assets\\Gen"),
    ("output", "Assets/Gen\\Ros"),
    ("output", "./Assets/Gen"),
    ("output", "Gen"),
    ("project", "..\\unity"),
    ("project", "/abs"),
    ("project", "C:/unity"),
    ("project", "../unity"),
    ("project", ""),
    ("interfaces", ["a\\b"]),
    ("interfaces", ["/opt/ros/noetic/share"]),
    ("interfaces", [""]),
    ("connector.scene", "Assets\\M.unity"),
    ("topics.0.scene", "Assets\\M.unity"),
    ("services.0.scene", "/M.unity"),
    ("components.0.scene", "C:\\M.unity"),
    ("components.0.script", "Assets\\Scripts\\Foo.cs"),
    ("components.0.script", "/abs/Foo.cs"),
    ("components.0.script", "Assets/Scripts/Foo.cs"),
    ("components.0.script", "RosSharp.RosBridgeClient.TwistSubscriber"),
    ("components.0.script", "Foo Bar"),
    ("components.0.script", ""),
    # C# names
    ("topics.0.class", "int"),
    ("topics.0.class", "class"),
    ("services.0.class", "event"),
    ("topics.0.class", "var"),
    ("topics.0.class", "_Joints"),
    ("topics.0.class", "2D"),
    ("namespace", "My.class"),
    ("namespace", "int"),
    ("namespace", "Internal.Ros"),
    ("namespace", "My..Ros"),
    ("components.0.fields", {"class": 1}),
    ("components.0.fields", {"1a": 1}),
    ("components.0.fields", {"Offset": {"x": INF}}),
    # topic and service names: ROS 1 allows '_' to start a part and '__'; ROS 2 refuses '__'
    ("topics.0.name", "/_x"),
    ("topics.0.name", "/cmd__vel"),
    ("topics.0.name", "cmd_vel"),
    ("topics.0.name", "_x"),
    ("topics.0.name", "/a/_b"),
    ("topics.0.name", "/1x"),
    ("topics.0.name", "/x_"),
    ("topics.0.name", "~x"),
    ("topics.0.name", "/cmd//vel"),
    ("topics.0.name", "/scan/"),
    ("services.0.name", "/_reset"),
    ("services.0.name", "/re__set"),
    ("services.0.name", "/robot/reset"),
    # types, URLs, GameObjects
    ("topics.0.type", "geometry_msgs/srv/Twist"),
    ("services.0.type", "std_srvs/srv/Trigger"),
    # a ROS 2 action's parts are used only through its action (any ROS 1 name may end so)
    ("topics.0.type", "nav2_msgs/msg/NavigateToPose_FeedbackMessage"),
    ("topics.0.type", "my_msgs/Dock_Goal"),
    ("services.0.type", "nav2_msgs/srv/NavigateToPose_SendGoal"),
    ("services.0.type", "nav2_msgs/NavigateToPose_GetResult"),
    ("actions.0.type", "nav2_msgs/action/NavigateToPose_SendGoal"),
    ("actions.0.type", "nav2_msgs/action/NavigateToPose_Result"),
    ("actions.0.type", "nav2_msgs/msg/NavigateToPose"),
    ("actions.0.type", "nav2_msgs/NavigateToPose"),
    ("actions.0.role", "provider"),
    ("actions.0.name", "/nav__igate"),
    ("connector.url", "wss://robot:9090/bridge"),
    ("connector.url", "http://robot:9090"),
    ("topics.0.gameobject", "Robot/base_link"),
    ("topics.0.gameobject", "A//B"),
    ("topics.0.gameobject", "Robot\\arm"),
    ("topics.0.gameobject", "/Robot"),
    # declared objects and package scripts
    ("objects.0.position", [0, 1]),
    ("objects.0.position", [0, 1, "x"]),
    ("objects.0.position", [0, 1, INF]),
    ("objects.0.rotation", [0.5, 90.0, -45]),
    ("objects.0.rotation", 90),
    ("objects.0.scale", [1, 1, 1, 1]),
    ("objects.0.layer", 31),
    ("objects.0.layer", 32),
    ("objects.0.layer", -1),
    ("objects.0.layer", "UI"),
    ("objects.0.layer", "Ignore Raycast"),
    ("objects.0.layer", "ui"),
    ("objects.0.layer", True),
    ("objects.0.active", False),
    ("objects.0.active", "no"),
    ("objects.0.tag", "MainCamera"),
    ("objects.0.tag", ""),
    ("objects.0.ui", True),
    ("objects.0.ui", False),
    ("objects.0.ui", "yes"),
    ("objects.0.ui", {"anchor_min": [0, 1], "pivot": [0.5, 0.5]}),
    ("objects.0.ui", {"anchors": [0, 1]}),
    ("objects.0.ui", {"size": [1]}),
    ("objects.0.path", "A//B"),
    ("objects.0.path", "/Robot"),
    ("objects.0.components", ["Rigidbody", "Canvas", "CanvasRenderer"]),
    ("objects.0.components", ["Image"]),
    ("objects.0.components", [{"type": "Light", "id": "a b"}]),
    ("objects.0.components", [{"id": "x"}]),
    ("objects.0.components", [{"type": "Light", "colour": 1}]),
    ("components.0.id", "horizontal"),
    ("components.0.id", "a b"),
    ("components.0.guid", "0cd44c1031e13a943bb63640046fad76"),
    ("components.0.guid", "0CD44C1031E13A943BB63640046FAD76"),
    ("components.0.dll_class", "UnityEngine.UI.Image"),
    ("components.0.dll_class", "Not A.Class"),
]
# Refused by scaffold, accepted by the schema: "inside the project" is path arithmetic
# (normalising '..', following symbolic links) that JSON Schema cannot do.
TOOL_ONLY = {("scene", "../Main.unity"), ("output", "Assets/../Gen")}


def _variant(ros: int, where: str, value: Any) -> dict[str, Any]:
    data = copy.deepcopy(BASE)
    data["ros"] = ros
    *parents, last = where.split(".")
    node: Any = data
    for part in parents:
        node = node[int(part)] if part.isdigit() else node[part]
    node[int(last) if last.isdigit() else last] = value
    return data


def _verdicts(tmp_path: Path, data: dict[str, Any]) -> tuple[bool, bool, str]:
    """(schema accepts, scaffold accepts, the YAML text) for one manifest."""
    try:
        import jsonschema
    except ImportError:
        jsonschema = None
    require(jsonschema, "jsonschema (a test dependency)")
    text = yaml.safe_dump(data, sort_keys=False)
    path = tmp_path / "robot.yaml"
    path.write_text(text, encoding="utf-8")
    # What an editor's YAML language server sees: the YAML 1.2 data of the same text.
    document = YAML(typ="safe", pure=True).load(text)
    schema_ok = jsonschema.Draft202012Validator(load_schema()).is_valid(document)
    try:
        load_manifest(path)
        tool_ok = True
    except LocatedError:
        tool_ok = False
    return schema_ok, tool_ok, text


@pytest.mark.parametrize("ros", [1, 2])
@pytest.mark.parametrize(("where", "value"), VARIANTS, ids=[f"{w}={v!r}" for w, v in VARIANTS])
def test_schema_and_scaffold_agree(tmp_path: Path, ros: int, where: str, value: Any) -> None:
    schema_ok, tool_ok, text = _verdicts(tmp_path, _variant(ros, where, value))
    assert schema_ok == tool_ok, f"schema {schema_ok}, scaffold {tool_ok}:\n{text}"


@pytest.mark.parametrize("ros", [1, 2])
def test_the_base_manifest_is_valid_to_both(tmp_path: Path, ros: int) -> None:
    assert _verdicts(tmp_path, _variant(ros, "ros", ros))[:2] == (True, True)


@pytest.mark.parametrize(("where", "value"), sorted(TOOL_ONLY))
def test_rules_only_scaffold_checks_are_the_listed_ones(
    tmp_path: Path, where: str, value: Any
) -> None:
    schema_ok, tool_ok, _ = _verdicts(tmp_path, _variant(1, where, value))
    assert (schema_ok, tool_ok) == (True, False)


@pytest.mark.parametrize(
    ("ros", "name", "valid"),
    [(1, "/_x", True), (1, "/cmd__vel", True), (2, "/_x", True), (2, "/cmd__vel", False)],
)
def test_topic_names_follow_their_ros_version(
    tmp_path: Path, ros: int, name: str, valid: bool
) -> None:
    assert _verdicts(tmp_path, _variant(ros, "topics.0.name", name))[:2] == (valid, valid)


TCP_BASE: dict[str, Any] = {
    "version": 1,
    "ros": 1,
    "runtime": "ros-tcp-connector",
    "scene": "Assets/Scenes/Main.unity",
    "connector": {"gameobject": "ROSConnection", "host": "192.168.1.10", "port": 10000},
    "topics": [
        {"name": "/cmd_vel", "type": "geometry_msgs/Twist", "direction": "publish", "rate": 10},
        {"name": "/odom", "type": "nav_msgs/Odometry", "direction": "subscribe"},
    ],
    "services": [{"name": "/reset", "type": "std_srvs/Trigger", "role": "client"}],
}
# (ros, where, value): the keys each runtime has, its connector's values, and ROS 2 actions.
TCP_VARIANTS: list[tuple[int, str, Any]] = [
    (1, "runtime", "ros-sharp"),  # then host and port are ROS#'s connector's unknown keys
    (1, "runtime", "ros-tcp"),
    (1, "connector.host", "robot.local"),
    (1, "connector.host", "tcp://robot"),
    (1, "connector.host", "robot:10000"),
    (1, "connector.port", 65535),
    (1, "connector.port", 65536),
    (1, "connector.port", 0),
    (1, "connector.url", "ws://localhost:9090"),
    (1, "connector.timeout", 10),
    (1, "connector.keepalive", 0.5),
    (1, "connector.keepalive", 0),
    (1, "connector.sleep", INF),
    (1, "connector.network_timeout", "2"),
    (1, "connector.show_hud", False),
    (1, "connector.connect_on_start", "no"),
    (1, "connector.tf_topics", ["/tf", "/tf_static"]),
    (1, "connector.tf_topics", ["tf//x"]),
    (1, "connector.listen_for_tf", False),
    (1, "include_shipped", True),
    (1, "include_shipped", False),
    (1, "topics.0.queue", 1),
    (1, "topics.0.latch", True),
    (1, "topics.0.latch", 1),
    (1, "topics.0.throttle", 10),
    (1, "topics.1.queue", 5),
    (1, "topics.1.throttle", 5),
    (1, "topics.1.latch", True),
    (1, "actions", [{"name": "/dock", "type": "move_base_msgs/action/MoveBase", "role": "client"}]),
    (2, "actions", [{"name": "/dock", "type": "test_msgs/action/Fibonacci", "role": "client"}]),
    (2, "actions", []),
]


@pytest.mark.parametrize(
    ("ros", "where", "value"), TCP_VARIANTS, ids=[f"ros{r}:{w}={v!r}" for r, w, v in TCP_VARIANTS]
)
def test_schema_and_scaffold_agree_under_ros_tcp_connector(
    tmp_path: Path, ros: int, where: str, value: Any
) -> None:
    data = copy.deepcopy(TCP_BASE)
    data["ros"] = ros
    *parents, last = where.split(".")
    node: Any = data
    for part in parents:
        node = node[int(part)] if part.isdigit() else node[part]
    node[int(last) if last.isdigit() else last] = value
    schema_ok, tool_ok, text = _verdicts(tmp_path, data)
    assert schema_ok == tool_ok, f"schema {schema_ok}, scaffold {tool_ok}:\n{text}"


@pytest.mark.parametrize(
    ("where", "value", "valid"),
    [
        ("topics.0.latch", True, False),  # a ros-tcp-connector key
        ("topics.0.queue", 3, False),  # a ROS# publisher has no queue
        ("connector.host", "robot", False),
    ],
)
def test_connector_only_keys_are_refused_by_both_under_ros_sharp(
    tmp_path: Path, where: str, value: Any, valid: bool
) -> None:
    assert _verdicts(tmp_path, _variant(1, where, value))[:2] == (valid, valid)


def test_the_connector_base_manifest_is_valid_to_both(tmp_path: Path) -> None:
    assert _verdicts(tmp_path, copy.deepcopy(TCP_BASE))[:2] == (True, True)
