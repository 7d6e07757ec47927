"""Class names derived from topic and service names, and C# identifier checks."""

from __future__ import annotations

import pytest

from unityscaffold.manifest import default_class_name
from unityscaffold.manifest._fields import parse_reference
from unityscaffold.manifest.model import Direction, ObjectPath, Role, is_csharp_identifier


@pytest.mark.parametrize(
    ("name", "kind", "expected"),
    [
        ("/cmd_vel", Direction.PUBLISH, "CmdVelPublisher"),
        ("/robot/odom", Direction.SUBSCRIBE, "RobotOdomSubscriber"),
        ("/reset", Role.CLIENT, "ResetClient"),
        ("/reset", Role.SERVER, "ResetServer"),
        ("joint_states", Direction.SUBSCRIBE, "JointStatesSubscriber"),
        ("/robot/imuData", Direction.SUBSCRIBE, "RobotImuDataSubscriber"),
        ("/a/__private_x", Direction.PUBLISH, "APrivateXPublisher"),
        ("/camera/image_raw2", Direction.SUBSCRIBE, "CameraImageRaw2Subscriber"),
    ],
)
def test_default_class_name_capitalises_each_word_and_adds_the_role(
    name: str, kind: Direction | Role, expected: str
) -> None:
    assert default_class_name(name, kind) == expected
    assert is_csharp_identifier(expected)


@pytest.mark.parametrize(
    ("name", "ok"),
    [
        ("CmdVelPublisher", True),
        ("_x", True),
        ("A1", True),
        ("class", False),
        ("1A", False),
        ("A-B", False),
        ("Ä", False),
        ("", False),
        ("A.B", False),
    ],
)
def test_is_csharp_identifier(name: str, ok: bool) -> None:
    assert is_csharp_identifier(name) is ok


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("@Robot/base_link", ObjectPath("Robot/base_link")),
        ("@RosConnector:RosConnector", ObjectPath("RosConnector", "RosConnector")),
        ("@Main Camera", ObjectPath("Main Camera")),
        (
            "@A/B:RosSharp.RosBridgeClient.RosConnector",
            ObjectPath("A/B", "RosSharp.RosBridgeClient.RosConnector"),
        ),
        ("@", None),
        ("@/A", None),
        ("@A/", None),
        ("@A:", None),
        ("@A:1x", None),
        ("@:C", None),
    ],
)
def test_object_references_split_path_and_component(text: str, expected: ObjectPath | None) -> None:
    assert parse_reference(text) == expected


def test_object_path_prints_as_written() -> None:
    assert str(ObjectPath("A/B", "C")) == "@A/B:C"
    assert ObjectPath("A/B").segments == ("A", "B")
