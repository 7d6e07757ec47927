"""The ROS2 scripting define in ProjectSettings.asset follows the manifest's ROS version."""

from __future__ import annotations

import pytest

from unityscaffold.apply._settings import with_ros_define

EMPTY = "PlayerSettings:\n  productName: x\n  scriptingDefineSymbols: {}\n  other: 1\n"
GROUPS = (
    "PlayerSettings:\n  scriptingDefineSymbols:\n    Standalone: FOO;ROS2\n    Android: BAR\n"
    "  other: 1\n"
)


def test_ros2_adds_the_define_to_an_empty_block_and_ros1_restores_it():
    with_define = with_ros_define(EMPTY, True)
    assert "  scriptingDefineSymbols:\n    Standalone: ROS2\n  other: 1\n" in with_define
    assert with_ros_define(with_define, False) == EMPTY


def test_every_build_target_group_gets_the_define_and_others_are_kept():
    assert with_ros_define(GROUPS, True) == (
        "PlayerSettings:\n  scriptingDefineSymbols:\n    Standalone: FOO;ROS2\n"
        "    Android: BAR;ROS2\n  other: 1\n"
    )
    assert with_ros_define(GROUPS, False) == (
        "PlayerSettings:\n  scriptingDefineSymbols:\n    Standalone: FOO\n    Android: BAR\n"
        "  other: 1\n"
    )


@pytest.mark.parametrize("text", [EMPTY, GROUPS])
@pytest.mark.parametrize("ros2", [True, False])
def test_the_edit_is_idempotent(text, ros2):
    once = with_ros_define(text, ros2)
    assert with_ros_define(once, ros2) == once


def test_a_missing_block_is_added_for_ros2_only():
    text = "PlayerSettings:\n  productName: x\n"
    assert with_ros_define(text, False) == text
    assert "scriptingDefineSymbols:\n    Standalone: ROS2\n" in with_ros_define(text, True)
