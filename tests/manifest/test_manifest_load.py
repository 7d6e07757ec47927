"""Loading good manifests: defaults, resolved paths, values, and the locations kept for later."""

from __future__ import annotations

import re
import textwrap
from pathlib import Path

import pytest

from unityscaffold.errors import LocatedError, UserError
from unityscaffold.interfaces.model import Dialect
from unityscaffold.manifest import (
    Manifest,
    ObjectPath,
    load_manifest,
    parse_manifest,
    starter_manifest,
)
from unityscaffold.manifest.model import (
    Direction,
    Protocol,
    Role,
    Serializer,
    StructValue,
)

VALID = Path(__file__).parent / "valid"


def parse(text: str, where: Path = Path("/robots/r1")) -> Manifest:
    return parse_manifest(textwrap.dedent(text), where / "robot.yaml")


def test_ros1_sample_loads_every_key_with_its_value() -> None:
    m = load_manifest(VALID / "ros1.yaml")
    assert m.ros is Dialect.ROS1
    assert m.project_root == (VALID / "unity").absolute()
    assert m.output_dir == m.project_root / "Assets/RosGenerated/Robot"
    assert m.output == "Assets/RosGenerated/Robot"
    assert m.namespace == "MyRobot.Ros"
    assert m.interfaces == (
        (VALID.parent / "catkin_ws/src").absolute(),
        (VALID / "defs").absolute(),
    )
    c = m.connector
    assert (c.gameobject, c.url, c.timeout) == ("Ros/Connector", "ws://192.168.1.10:9090", 5)
    assert (c.serializer, c.protocol) == (Serializer.NEWTONSOFT, Protocol.WEBSOCKET_NET)
    cmd, odom, joints = m.topics
    assert (cmd.direction, cmd.rate, cmd.class_name) == (Direction.PUBLISH, 20.0, "CmdVelPublisher")
    assert cmd.gameobject == "Ros/Connector"  # defaults to the connector's GameObject
    assert (odom.throttle, odom.queue, odom.create) == (100, 2, False)
    assert (odom.gameobject, odom.scene) == ("Robot/base_link", "Assets/Scenes/Other.unity")
    assert joints.class_name == "Joints"
    assert [s.class_name for s in m.services] == ["ResetClient", "SetModeServer"]
    assert m.services[1].role is Role.SERVER and m.services[1].create is False
    move_base, dock = m.actions
    assert (move_base.type, move_base.role) == ("move_base_msgs/action/MoveBase", Role.CLIENT)
    assert (move_base.class_name, move_base.gameobject) == ("MoveBaseActionClient", "Robot")
    assert (dock.role, dock.class_name, dock.create) == (Role.SERVER, "DockingStation", False)
    assert (dock.gameobject, dock.scene) == ("Ros/Connector", "Assets/Scenes/Other.unity")
    assert m.scenes == ("Assets/Scenes/Main.unity", "Assets/Scenes/Other.unity")


def test_component_fields_keep_scalars_structs_lists_and_references() -> None:
    twist, lidar = load_manifest(VALID / "ros1.yaml").components
    assert [(f.name, f.value) for f in twist.fields] == [
        ("Topic", "/cmd_vel_unity"),
        ("TimeStep", 0.1),
        ("EnsureThreadSafety", True),
        ("SubscribedTransform", ObjectPath("Robot/base_link")),
    ]
    assert lidar.script == "Assets/Scripts/Lidar.cs"
    fields = {f.name: f.value for f in lidar.fields}
    assert fields["Connector"] == ObjectPath("Ros/Connector", "RosConnector")
    offset = fields["Offset"]
    assert isinstance(offset, StructValue) and offset.as_dict() == {"x": 0, "y": 0.25, "z": -1.5}
    assert fields["Names"] == ("a", "b", "@literal")
    assert lidar.field("Names") is not None and lidar.field("Missing") is None


def test_ros2_sample_gets_every_default() -> None:
    m = load_manifest(VALID / "ros2.yaml")
    assert m.ros is Dialect.ROS2
    assert m.project_root == VALID.absolute()
    assert m.output == "Assets/RosGenerated"
    assert (m.namespace, m.include_shipped, m.interfaces, m.create_gameobjects) == (
        None,
        False,
        (),
        True,
    )
    c = m.connector
    assert (c.scene, c.gameobject, c.url, c.timeout) == (
        "Assets/Scenes/Main.unity",
        "RosConnector",
        "ws://localhost:9090",
        10,
    )
    assert (c.serializer, c.protocol) == (Serializer.MICROSOFT, Protocol.WEBSOCKET_SHARP)
    assert [(t.rate, t.throttle, t.queue) for t in m.topics] == [(None,) * 3, (None,) * 3]
    assert m.services[0].class_name == "AddTwoIntsClient"
    assert m.components == ()


def test_locations_point_at_each_value_for_later_stages() -> None:
    m = load_manifest(VALID / "ros1.yaml")
    odom = m.topics[1]
    where = odom.locations.of("type")
    assert (where.line, where.col) == (26, 11)
    assert where.source_line == "    type: nav_msgs/Odometry"
    assert odom.locations.of("gameobject").line == 30
    # a key left to its default falls back to the entry itself
    assert m.topics[0].locations.of("gameobject") == m.topics[0].locations.item
    assert m.components[0].fields[0].location.line == 43


def test_location_path_is_the_path_as_given() -> None:
    with pytest.raises(LocatedError) as caught:
        parse_manifest("version: 1\nros: 7\nscene: Assets/S.unity\n", Path("robot.yaml"))
    assert caught.value.render().startswith("robot.yaml:2:6: error:")


def test_entries_use_create_gameobjects_unless_they_say_otherwise() -> None:
    m = parse("""\
        version: 1
        ros: 2
        scene: Assets/S.unity
        create_gameobjects: false
        topics:
          - {name: a, type: p/A, direction: publish}
          - {name: b, type: p/B, direction: publish, create: true}
        """)
    assert [t.create for t in m.topics] == [False, True]


def test_scene_may_be_left_out_when_every_entry_names_one() -> None:
    m = parse("""\
        version: 1
        ros: 1
        connector: {scene: Assets/A.unity}
        topics: [{name: a, type: p/A, direction: publish, scene: Assets/B.unity}]
        """)
    assert m.scene is None
    assert m.topics[0].scene == "Assets/B.unity"


def test_paths_are_normalised_inside_the_project() -> None:
    m = parse("""\
        version: 1
        ros: 1
        project: ./unity/
        output: ./Assets/../Assets/Gen/
        scene: Assets/Scenes/./Main.unity
        """)
    assert m.project_root == Path("/robots/r1/unity")
    assert m.output == "Assets/Gen"
    assert m.scene == "Assets/Scenes/Main.unity"


def test_yaml_anchors_and_merge_keys_are_expanded() -> None:
    m = parse("""\
        version: 1
        ros: 2
        scene: Assets/S.unity
        topics:
          - &sub {name: /a, type: p/A, direction: subscribe, throttle: 50}
          - {<<: *sub, name: /b}
        """)
    assert [(t.name, t.throttle) for t in m.topics] == [("/a", 50), ("/b", 50)]


def test_empty_lists_and_connector_are_accepted() -> None:
    m = parse("""\
        version: 1
        ros: 2
        scene: Assets/S.unity
        connector:
        topics:
        services: []
        """)
    assert m.topics == () and m.connector.gameobject == "RosConnector"


def test_yes_and_dates_stay_text_in_yaml_1_2() -> None:
    m = parse("""\
        version: 1
        ros: 2
        scene: Assets/S.unity
        components:
          - script: Thing
            gameobject: A
            fields: {Mode: yes, Day: 2024-01-01, Hex: 0x10}
        """)
    assert [f.value for f in m.components[0].fields] == ["yes", "2024-01-01", 16]


@pytest.mark.parametrize("ros", [1, 2])
def test_starter_manifest_is_valid(ros: int) -> None:
    text = starter_manifest(ros, "Assets/Scenes/Main.unity", schema="robot.schema.json")
    assert text.startswith("# yaml-language-server: $schema=robot.schema.json\n")
    m = parse_manifest(text, Path("/p/robot.yaml"))
    assert int(m.ros) == ros and m.scene == "Assets/Scenes/Main.unity"


@pytest.mark.parametrize("ros", [1, 2])
def test_starter_manifest_examples_are_valid_once_uncommented(ros: int) -> None:
    text = starter_manifest(ros, "Assets/Scenes/Main.unity")
    uncommented = re.sub(r"(?m)^#(  - |    \w)", r"\1", text)
    m = parse_manifest(uncommented, Path("/p/robot.yaml"))
    assert [t.class_name for t in m.topics] == ["CmdVelPublisher", "OdomSubscriber"]
    assert len(m.services) == 1 and len(m.components) == 1
    # ROS 2's standard interfaces define no action: its example is the built-in Fibonacci
    expected = "MoveBaseActionClient" if ros == 1 else "FibonacciActionClient"
    assert [a.class_name for a in m.actions] == [expected]
    assert [r.urdf for r in m.robots] == [Path("/p/ros/my_robot.urdf")]


def test_starter_manifest_rejects_bad_arguments() -> None:
    with pytest.raises(UserError):
        starter_manifest(3, "Assets/Scenes/Main.unity")
    with pytest.raises(UserError):
        starter_manifest(1, "Assets/Scenes/Main")


def test_output_through_a_symlink_out_of_the_project_is_rejected(tmp_path: Path) -> None:
    (tmp_path / "outside").mkdir()
    (tmp_path / "project/Assets").mkdir(parents=True)
    (tmp_path / "project/Assets/Gen").symlink_to(tmp_path / "outside")
    manifest = tmp_path / "robot.yaml"
    manifest.write_text(
        "version: 1\nros: 1\nproject: project\noutput: Assets/Gen/Code\nscene: Assets/S.unity\n"
    )
    with pytest.raises(LocatedError) as caught:
        load_manifest(manifest)
    (diagnostic,) = caught.value.diagnostics
    assert (diagnostic.location.line, diagnostic.location.col) == (4, 9)
    assert "symbolic link" in (diagnostic.hint or "")
    assert list((tmp_path / "outside").iterdir()) == []


def test_symlink_that_stays_inside_the_project_is_fine(tmp_path: Path) -> None:
    (tmp_path / "Assets/Real").mkdir(parents=True)
    (tmp_path / "Assets/Gen").symlink_to(tmp_path / "Assets/Real")
    manifest = tmp_path / "robot.yaml"
    manifest.write_text("version: 1\nros: 1\noutput: Assets/Gen\nscene: Assets/S.unity\n")
    assert load_manifest(manifest).output == "Assets/Gen"


def test_scene_through_a_symlink_out_of_the_project_is_rejected(tmp_path: Path) -> None:
    (tmp_path / "elsewhere").mkdir()
    (tmp_path / "p/Assets").mkdir(parents=True)
    (tmp_path / "p/Assets/Scenes").symlink_to(tmp_path / "elsewhere")
    manifest = tmp_path / "robot.yaml"
    manifest.write_text("version: 1\nros: 1\nproject: p\nscene: Assets/Scenes/Main.unity\n")
    with pytest.raises(LocatedError) as caught:
        load_manifest(manifest)
    assert caught.value.location.line == 4


@pytest.mark.parametrize(
    ("content", "message"),
    [
        (None, "does not exist"),
        ("dir", "is a folder"),
        (b"version: 1\nros: \xff\n", "not UTF-8"),
    ],
)
def test_unreadable_manifest_files_are_user_errors(
    tmp_path: Path, content: object, message: str
) -> None:
    path = tmp_path / "robot.yaml"
    if content == "dir":
        path.mkdir()
    elif isinstance(content, bytes):
        path.write_bytes(content)
    with pytest.raises(UserError, match=message):
        load_manifest(path)


def test_a_byte_order_mark_is_ignored(tmp_path: Path) -> None:
    path = tmp_path / "robot.yaml"
    path.write_bytes(b"\xef\xbb\xbfversion: 1\nros: 2\nscene: Assets/S.unity\n")
    assert load_manifest(path).ros is Dialect.ROS2
