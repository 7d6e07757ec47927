"""C# naming rules: ROS#'s package rule, class names, keyword escaping, identifiers."""

from __future__ import annotations

import pytest

from unityscaffold.codegen.naming import (
    class_name,
    escape_identifier,
    namespace_segment,
    validate_namespace,
)
from unityscaffold.errors import UserError


@pytest.mark.parametrize(
    ("package", "segment"),
    [
        ("geometry_msgs", "Geometry"),
        ("std_srvs", "Std"),
        ("tf2_msgs", "Tf2"),
        ("unique_identifier_msgs", "UniqueIdentifier"),
        ("foo_msgs_ext", "FooMsgs"),
        ("builtin_interfaces", "BuiltinInterfaces"),
        ("rosapi", "Rosapi"),
        ("my_robot_actions", "MyRobot"),
        ("test_msgs", "Test"),
        ("action_msgs", "Action"),
    ],
)
def test_package_names_become_rossharp_namespaces(package: str, segment: str) -> None:
    assert namespace_segment(package) == segment


def test_package_that_leaves_no_name_is_refused() -> None:
    with pytest.raises(UserError, match="cannot become a C# namespace"):
        namespace_segment("_msgs")


def test_class_names_capitalise_only_the_first_letter() -> None:
    assert class_name("poseStamped") == "PoseStamped"
    assert class_name("TF2Error") == "TF2Error"


@pytest.mark.parametrize(
    ("name", "escaped"),
    [
        ("object", "@object"),
        ("params", "@params"),
        ("default", "@default"),
        ("value", "@value"),
        ("range", "range"),
        ("x", "x"),
        ("frame_id", "frame_id"),
    ],
)
def test_keywords_are_escaped_with_at(name: str, escaped: str) -> None:
    assert escape_identifier(name) == escaped


@pytest.mark.parametrize("name", ["9lives", "has-dash", "", "naïve"])
def test_names_that_cannot_be_identifiers_are_refused(name: str) -> None:
    with pytest.raises(UserError, match="cannot become a C# identifier"):
        escape_identifier(name)


def test_root_namespace_must_be_dotted_identifiers() -> None:
    assert validate_namespace("MyRobot.Messages") == "MyRobot.Messages"
    for bad in ("My.class", "My..Ns", "1Robot", "My Robot"):
        with pytest.raises(UserError):
            validate_namespace(bad)
