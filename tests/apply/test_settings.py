"""The ROS2 scripting define in ProjectSettings.asset follows the manifest's ROS version."""

from __future__ import annotations

import pytest

from unityscaffold.apply._settings import GROUPS, with_ros_define

EMPTY = "PlayerSettings:\n  productName: x\n  scriptingDefineSymbols: {}\n  other: 1\n"
GROUPS_TEXT = (
    "PlayerSettings:\n  scriptingDefineSymbols:\n    Standalone: FOO;ROS2\n    Android: BAR\n"
    "  other: 1\n"
)


ALL_GROUPS = "".join(f"    {group}: ROS2\n" for group in GROUPS)


def test_ros2_adds_the_define_for_every_build_target_group_and_ros1_restores_it():
    with_define = with_ros_define(EMPTY, True)
    assert f"  scriptingDefineSymbols:\n{ALL_GROUPS}  other: 1\n" in with_define
    for group in ("Standalone", "Android", "iPhone", "WebGL", "Windows Store Apps"):
        assert f"    {group}: ROS2\n" in with_define
    assert with_ros_define(with_define, False) == EMPTY


def test_every_build_target_group_gets_the_define_and_others_are_kept():
    edited = with_ros_define(GROUPS_TEXT, True)
    assert "    Standalone: FOO;ROS2\n" in edited
    assert "    Android: BAR;ROS2\n" in edited
    assert "    iPhone: ROS2\n" in edited
    assert edited.endswith("  other: 1\n")
    assert with_ros_define(GROUPS_TEXT, False) == (
        "PlayerSettings:\n  scriptingDefineSymbols:\n    Standalone: FOO\n    Android: BAR\n"
        "  other: 1\n"
    )


@pytest.mark.parametrize("text", [EMPTY, GROUPS_TEXT])
@pytest.mark.parametrize("ros2", [True, False])
def test_the_edit_is_idempotent(text, ros2):
    once = with_ros_define(text, ros2)
    assert with_ros_define(once, ros2) == once


def test_a_missing_block_is_added_for_ros2_only():
    text = "PlayerSettings:\n  productName: x\n"
    assert with_ros_define(text, False) == text
    assert f"scriptingDefineSymbols:\n{ALL_GROUPS}" in with_ros_define(text, True)


@pytest.mark.parametrize("ros2", [True, False])
def test_crlf_line_endings_are_kept(ros2):
    for text in (EMPTY, GROUPS_TEXT):
        crlf = text.replace("\n", "\r\n")
        edited = with_ros_define(crlf, ros2)
        assert "\n" not in edited.replace("\r\n", "")
        assert edited.replace("\r\n", "\n") == with_ros_define(text, ros2)
