"""The ROS-TCP-Connector generator: names, what it references, what it refuses, its warnings."""

from __future__ import annotations

from pathlib import Path

import pytest
from codegen_helpers import DATA
from helpers import build_tree

from unityscaffold.codegen import ClassRole, GeneratedCode, Options
from unityscaffold.codegen.naming import CsClass
from unityscaffold.codegen.rostcp import generate
from unityscaffold.errors import LocatedError, UserError
from unityscaffold.interfaces.model import Dialect
from unityscaffold.interfaces.registry import Registry

HERE = Path(__file__).resolve().parent


def _generate(
    dialect: Dialect, names: list[str], folder: Path | None = None, *, include_shipped: bool = False
) -> GeneratedCode:
    roots = [folder] if folder else []
    registry = Registry.load(dialect, roots)
    return generate(registry, [registry.get(n) for n in names], Options(dialect, include_shipped))


def test_a_message_becomes_a_msg_class_named_as_the_connector_names_it(ros1_share: Path) -> None:
    code = _generate(Dialect.ROS1, ["scaffold_test_msgs/Kitchen"], DATA / "ros1")
    kitchen = code.message_class("scaffold_test_msgs/Kitchen")
    assert kitchen == CsClass("RosMessageTypes.ScaffoldTest", "KitchenMsg")
    text = next(f.text for f in code.files if f.path == "ScaffoldTest/msg/KitchenMsg.cs")
    assert 'public const string k_RosMessageName = "scaffold_test_msgs/Kitchen";' in text
    assert "public static KitchenMsg Deserialize(" in text
    assert "public override void SerializeTo(" in text
    assert "public static void Register()" in text


def test_shipped_classes_are_referenced_and_not_generated(ros1_share: Path) -> None:
    code = _generate(Dialect.ROS1, ["scaffold_test_msgs/Kitchen"], DATA / "ros1")
    paths = {f.path for f in code.files}
    assert "Std/msg/HeaderMsg.cs" not in paths
    assert code.message_class("std_msgs/Header") == CsClass("RosMessageTypes.Std", "HeaderMsg")
    header = next(s for s in code.skipped if s.ros_type == "std_msgs/Header")
    assert header.reason == "ROS-TCP-Connector ships RosMessageTypes.Std.HeaderMsg"
    kitchen = next(f.text for f in code.files if f.path == "ScaffoldTest/msg/KitchenMsg.cs")
    assert "public global::RosMessageTypes.Std.HeaderMsg header;" in kitchen


def test_fixed_arrays_of_strings_and_messages_start_filled(ros1_share: Path) -> None:
    code = _generate(Dialect.ROS1, ["scaffold_test_msgs/Kitchen"], DATA / "ros1")
    text = next(f.text for f in code.files if f.path == "ScaffoldTest/msg/KitchenMsg.cs")
    point = "global::RosMessageTypes.Geometry.PointMsg"
    assert f"this.corners = new {point}[] {{ new {point}(), new {point}() }};" in text
    assert 'this.names = new string[] { "", "", "" };' in text
    assert 'GREETING = "Hello \\"Unity\\" & <ROS>";' in text


def test_ros1_time_types_become_the_connectors_time_classes(
    ros1_share: Path, tmp_path: Path
) -> None:
    text = "time a\nduration b\nstd_msgs/Time c\nstd_msgs/Duration d\n"
    folder = build_tree(tmp_path, {"tcp_msgs/msg/Stamps.msg": text})
    code = _generate(Dialect.ROS1, ["tcp_msgs/Stamps"], folder)
    stamps = next(f.text for f in code.files if f.path == "Tcp/msg/StampsMsg.cs")
    time, duration = (
        f"global::RosMessageTypes.BuiltinInterfaces.{n}Msg" for n in ("Time", "Duration")
    )
    assert f"public {time} a;" in stamps
    assert f"public {duration} b;" in stamps
    assert f"public {time} c;" in stamps  # the connector's generator writes Std.TimeMsg (#297)
    assert "public global::RosMessageTypes.Std.DurationMsg d;" in stamps
    own = next(f.text for f in code.files if f.path == "Std/msg/DurationMsg.cs")
    assert 'k_RosMessageName = "std_msgs/Duration";' in own
    assert f"public {duration} data;" in own


def test_a_service_gives_request_and_response_registered_under_the_service_name(
    ros1_share: Path,
) -> None:
    code = _generate(Dialect.ROS1, ["scaffold_test_msgs/Lookup"], DATA / "ros1")
    roles = code.classes["scaffold_test_msgs/srv/Lookup"]
    assert roles[ClassRole.REQUEST].name == "LookupRequest"
    response = next(f.text for f in code.files if f.path == "ScaffoldTest/srv/LookupResponse.cs")
    assert 'k_RosMessageName = "scaffold_test_msgs/Lookup";' in response
    assert "MessageSubtopic.Response);" in response


def test_a_ros1_action_gives_parts_and_registered_wrappers(ros1_share: Path) -> None:
    code = _generate(Dialect.ROS1, ["scaffold_test_msgs/Cook"], DATA / "ros1")
    names = {f.path.rsplit("/", 1)[-1] for f in code.files if "/action/" in f.path}
    assert names == {
        f"Cook{s}.cs"
        for s in (
            "Goal",
            "Result",
            "Feedback",
            "ActionGoal",
            "ActionResult",
            "ActionFeedback",
            "Action",
        )
    }
    wrapper = next(f.text for f in code.files if f.path.endswith("/CookActionGoal.cs"))
    assert "MessageGeneration.ActionGoal<global::RosMessageTypes.ScaffoldTest.CookGoal>" in wrapper
    assert "MessageRegistry.Register(k_RosMessageName, Deserialize);" in wrapper
    goal = next(f.text for f in code.files if f.path.endswith("/CookGoal.cs"))
    assert 'k_RosMessageName = "scaffold_test_msgs/CookGoal";' in goal


def test_ros2_actions_are_refused(ros2_share: Path) -> None:
    with pytest.raises(UserError) as raised:
        _generate(Dialect.ROS2, ["test_msgs/action/Fibonacci"])
    assert "ROS 2 action" in raised.value.message
    assert "pkg.msg and pkg.srv" in (raised.value.hint or "")


def test_generating_the_shipped_classes_again_is_refused(ros1_share: Path) -> None:
    with pytest.raises(UserError, match="cannot be generated again"):
        _generate(Dialect.ROS1, ["std_msgs/String"], include_shipped=True)


def test_a_message_and_a_service_registering_one_name_are_refused(ros2_share: Path) -> None:
    with pytest.raises(UserError) as raised:
        _generate(Dialect.ROS2, ["test_msgs/msg/Arrays", "test_msgs/srv/Arrays"])
    assert "would both register as test_msgs/Arrays" in raised.value.message


def test_a_field_named_like_a_connector_member_is_refused_at_its_line(
    ros1_share: Path, tmp_path: Path
) -> None:
    folder = build_tree(tmp_path, {"tcp_msgs/msg/Odd.msg": "int32 fine\nint32 Register\n"})
    with pytest.raises(LocatedError) as raised:
        _generate(Dialect.ROS1, ["tcp_msgs/Odd"], folder)
    assert raised.value.location.line == 2
    assert "Register" in raised.value.message


def test_a_wstring_field_is_refused_at_its_line(ros2_share: Path, tmp_path: Path) -> None:
    folder = build_tree(tmp_path, {"tcp_msgs/msg/Wide.msg": "string a\nwstring b\n"})
    with pytest.raises(LocatedError) as raised:
        _generate(Dialect.ROS2, ["tcp_msgs/msg/Wide"], folder)
    assert raised.value.location.line == 2
    assert "wstring" in raised.value.message


def test_jazzy_definitions_the_shipped_classes_predate_are_warned_about(ros2_share: Path) -> None:
    names = [
        "sensor_msgs/msg/Range",
        "shape_msgs/msg/SolidPrimitive",
        "visualization_msgs/msg/InteractiveMarkerUpdate",
        "visualization_msgs/msg/MarkerArray",
    ]
    code = _generate(Dialect.ROS2, names)
    warnings = {s.ros_type: s.warning for s in code.skipped if s.warning}
    assert "lacks variance" in warnings["sensor_msgs/msg/Range"]
    assert "lacks polygon" in warnings["shape_msgs/msg/SolidPrimitive"]
    assert (
        "lacks texture_resource, texture, uv_coordinates, mesh_file"
        in warnings["visualization_msgs/msg/Marker"]
    )
    for holder in ("MarkerArray", "InteractiveMarker", "InteractiveMarkerControl"):
        holds = warnings[f"visualization_msgs/msg/{holder}"]
        assert "holds visualization_msgs/msg/Marker" in holds
    assert "local copy of the package" in warnings["sensor_msgs/msg/Range"]


def test_empty_shipped_classes_are_warned_about_under_ros2_only(
    ros1_share: Path, ros2_share: Path
) -> None:
    ros2 = _generate(Dialect.ROS2, ["std_msgs/msg/Empty", "std_srvs/srv/Trigger"])
    warned = {s.cs_class.name for s in ros2.skipped if s.warning and "no byte" in s.warning}
    assert warned == {"EmptyMsg", "TriggerRequest"}
    ros1 = _generate(Dialect.ROS1, ["std_msgs/Empty", "std_srvs/Trigger"])
    assert not [s for s in ros1.skipped if s.warning]


def test_debian_ros1_definitions_match_the_shipped_classes_but_quaternions_default(
    ros1_share: Path,
) -> None:
    registry = Registry.load(Dialect.ROS1)
    interfaces, problems = registry.parse_all()
    assert not problems
    code = generate(registry, interfaces, Options(Dialect.ROS1))
    warnings = {s.ros_type: s.warning or "" for s in code.skipped if s.warning}
    differing = [name for name, text in warnings.items() if "never registers" not in text]
    assert differing == ["geometry_msgs/Quaternion"]
    assert "starts with w = 1" in warnings["geometry_msgs/Quaternion"]


def test_shipped_action_wrappers_that_never_register_are_warned_about(ros1_share: Path) -> None:
    code = _generate(Dialect.ROS1, ["nav_msgs/action/GetMap"])
    assert not [f for f in code.files if "/action/" in f.path]
    warned = {s.cs_class.name: s.warning for s in code.skipped if s.warning}
    for name in ("GetMapActionGoal", "GetMapActionResult", "GetMapActionFeedback", "GetMapAction"):
        assert "never registers itself" in warned[name]
    assert "GetMapGoal" not in warned  # the parts register (under the action's name)


def test_a_root_namespace_of_ones_own_holds_the_generated_classes_only(ros1_share: Path) -> None:
    registry = Registry.load(Dialect.ROS1, [DATA / "ros1"])
    roots = [registry.get("scaffold_test_msgs/Kitchen")]
    code = generate(registry, roots, Options(Dialect.ROS1, namespace="MyRobot.Msgs"))
    kitchen = code.message_class("scaffold_test_msgs/Kitchen")
    assert kitchen == CsClass("MyRobot.Msgs.ScaffoldTest", "KitchenMsg")
    assert code.message_class("std_msgs/Header") == CsClass("RosMessageTypes.Std", "HeaderMsg")
    text = next(f.text for f in code.files if f.path == "ScaffoldTest/msg/KitchenMsg.cs")
    assert "namespace MyRobot.Msgs.ScaffoldTest" in text
    assert "public global::RosMessageTypes.Std.HeaderMsg header;" in text
