"""What gets generated: ROS#'s contract per ROS version, shipped types, and the class map."""

from __future__ import annotations

from pathlib import PurePath

import pytest
from codegen_helpers import generate_data

from unityscaffold.codegen import GeneratedCode
from unityscaffold.codegen._classes import source_name
from unityscaffold.codegen._views import doc_lines
from unityscaffold.interfaces.model import Dialect
from unityscaffold.interfaces.ros1 import parse_message


def _text(code: GeneratedCode, path: str) -> str:
    return next(f.text for f in code.files if f.path == path)


@pytest.fixture(scope="module")
def ros1() -> GeneratedCode:
    return generate_data(Dialect.ROS1, ["scaffold_test_msgs/Cook", "scaffold_test_msgs/Lookup"])


@pytest.fixture(scope="module")
def ros2() -> GeneratedCode:
    return generate_data(Dialect.ROS2, ["scaffold_test_msgs/Cook", "scaffold_test_msgs/Lookup"])


def test_service_halves_both_carry_the_service_name(
    ros1: GeneratedCode, ros2: GeneratedCode
) -> None:
    for half in ("Request", "Response"):
        assert 'RosMessageName = "scaffold_test_msgs/Lookup";' in _text(
            ros1, f"ScaffoldTest/srv/Lookup{half}.cs"
        )
        assert 'RosMessageName = "scaffold_test_msgs/srv/Lookup";' in _text(
            ros2, f"ScaffoldTest/srv/Lookup{half}.cs"
        )


def test_actions_get_rossharps_seven_classes(ros1: GeneratedCode, ros2: GeneratedCode) -> None:
    suffixes = (
        "Goal",
        "Result",
        "Feedback",
        "ActionGoal",
        "ActionResult",
        "ActionFeedback",
        "Action",
    )
    for code, prefix in ((ros1, "scaffold_test_msgs/"), (ros2, "scaffold_test_msgs/action/")):
        for suffix in suffixes:
            text = _text(code, f"ScaffoldTest/action/Cook{suffix}.cs")
            assert f'RosMessageName = "{prefix}Cook{suffix}";' in text


def test_ros1_and_ros2_action_wrappers_use_their_bases(
    ros1: GeneratedCode, ros2: GeneratedCode
) -> None:
    assert (
        "CookActionGoal(Header header, GoalID goal_id, CookGoal goal) : base(header, goal_id)"
        in _text(ros1, "ScaffoldTest/action/CookActionGoal.cs")
    )
    assert (
        "(Header header, string action, string id, CookFeedback values)"
        " : base(header, action, id)" in _text(ros2, "ScaffoldTest/action/CookActionFeedback.cs")
    )


def test_files_are_guarded_by_the_ros_version(ros1: GeneratedCode, ros2: GeneratedCode) -> None:
    assert all("\n#if !ROS2\n" in f.text and f.text.endswith("}\n#endif\n") for f in ros1.files)
    assert all("\n#if ROS2\n" in f.text for f in ros2.files)


def test_shipped_types_are_skipped_and_mapped_to_rossharps_classes(ros1: GeneratedCode) -> None:
    skipped = {s.ros_type: s for s in ros1.skipped}
    assert "ROS# ships" in skipped["std_msgs/Header"].reason
    assert "Std/msg/Header.cs" not in {f.path for f in ros1.files}
    header = ros1.message_class("std_msgs/Header")
    assert header.full_name == "RosSharp.RosBridgeClient.MessageTypes.Std.Header"


def test_class_map_names_every_role(ros1: GeneratedCode, ros2: GeneratedCode) -> None:
    roles = ros1.classes["scaffold_test_msgs/action/Cook"]
    assert roles["action_goal"].name == "CookActionGoal"
    assert ros2.classes["scaffold_test_msgs/srv/Lookup"]["response"].full_name == (
        "RosSharp.RosBridgeClient.MessageTypes.ScaffoldTest.LookupResponse"
    )
    assert ros2.message_class("scaffold_test_msgs/msg/Kitchen").name == "Kitchen"


def test_ros2_byte_is_unsigned_and_ros1_byte_signed() -> None:
    ros1 = generate_data(Dialect.ROS1, ["scaffold_test_msgs/Kitchen"])
    ros2 = generate_data(Dialect.ROS2, ["scaffold_test_msgs/Kitchen"])
    assert "public sbyte[] signed_bytes" in _text(ros1, "ScaffoldTest/msg/Kitchen.cs")
    ros2_text = _text(ros2, "ScaffoldTest/msg/Kitchen.cs")
    assert "public byte raw_byte { get; set; }" in ros2_text
    assert "public const byte RAW = 255;" in ros2_text


def test_ros2_defaults_are_properties_initialised_in_the_constructor() -> None:
    text = _text(
        generate_data(Dialect.ROS2, ["scaffold_test_msgs/Kitchen"]), "ScaffoldTest/msg/Kitchen.cs"
    )
    assert "public float scale { get; set; }" in text
    assert "this.scale = 1.5f;" in text
    assert "this.offsets = new long[] { -1L, 0L, 9223372036854775807L };" in text
    assert 'this.wide = "na\\u00EFve";' in text
    assert "if (value != null && value.Length > 4)" in text


def test_include_shipped_generates_shipped_types_but_never_ros1_time() -> None:
    code = generate_data(Dialect.ROS1, ["std_msgs/Time", "std_msgs/Header"], include_shipped=True)
    assert [f.path for f in code.files] == ["Std/msg/Header.cs"]
    assert "hand-writes" in code.skipped[0].reason


def test_doc_comments_escape_xml_and_drop_blank_ends() -> None:
    assert doc_lines(("", "a < b & c > d", "", "x", "")) == (
        "/// <summary>",
        "/// a &lt; b &amp; c &gt; d",
        "///",
        "/// x",
        "/// </summary>",
    )
    assert doc_lines(()) == ()


@pytest.mark.parametrize(
    "source",
    [
        "/opt/ws/src/pkg/msg/Pose.msg",
        "pkg/msg/Pose.msg",
        "Pose.msg",
        "/Pose.msg",
        "<string>",
        "a//msg/Pose.msg",
        "a/./msg/Pose.msg",
        "a/msg/./Pose.msg",
        "a/../msg/Pose.msg",
        "a/msg/Pose.msg/",
        "//net/msg/Pose.msg",
    ],
)
def test_the_header_names_the_source_as_pathlib_reads_its_folder_and_file(source: str) -> None:
    spec = parse_message("int32 a\n", "pkg", "Pose", source)
    path = PurePath(source)
    assert source_name(spec) == f"pkg/{path.parent.name}/{path.name}"
