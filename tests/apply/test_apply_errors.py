"""Bad manifests and projects: a located error, exit status 2, no traceback, nothing written."""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest
from helpers import run_cli, snapshot

REPO = Path(__file__).resolve().parents[2]


@pytest.fixture
def sample(tmp_path: Path) -> Path:
    copy = tmp_path / "sample_project"
    shutil.copytree(REPO / "sample_project", copy)
    return copy


def _apply_fails(sample: Path, *fragments: str) -> str:
    before = snapshot(sample)
    run = run_cli("apply", str(sample / "robot.yaml"))
    assert run.code == 2, run.out + run.err
    assert "Traceback" not in run.err
    for fragment in fragments:
        assert fragment in run.err, run.err
    assert snapshot(sample) == before
    return run.err


def _edit(sample: Path, old: str, new: str) -> None:
    manifest = sample / "robot.yaml"
    text = manifest.read_text()
    assert old in text
    manifest.write_text(text.replace(old, new, 1))


def test_unknown_type_points_at_the_manifest_and_suggests(sample):
    _edit(sample, "type: nav_msgs/Odometry", "type: nav_msgs/Odometri")
    _apply_fails(
        sample,
        "robot.yaml:19:",
        "unknown ROS 1 type 'nav_msgs/Odometri'",
        "did you mean nav_msgs/Odometry",
    )


def test_a_service_type_on_a_topic_is_refused(sample):
    _edit(sample, "type: nav_msgs/Odometry", "type: std_srvs/Trigger")
    _apply_fails(sample, "robot.yaml:19:", "'std_srvs/Trigger' is a service, not a message")


@pytest.mark.parametrize(
    ("written", "fragments"),
    [
        # the action's own message: the hint names the action
        (
            "diffbot_msgs/DockAction",
            (
                "'diffbot_msgs/DockAction' is a message, not an action",
                "is a message of the action diffbot_msgs/action/Dock; name the action itself: "
                "type: diffbot_msgs/action/Dock",
            ),
        ),
        (
            "diffbot_msgs/DockActionGoal",
            ("name the action itself: type: diffbot_msgs/action/Dock",),
        ),
        # a misspelled action: the suggestions are actions
        ("diffbot_msgs/action/Dok", ("unknown ROS 1 type", "did you mean diffbot_msgs/Dock?")),
        ("diffbot_msgs/SetSpeedLimit", ("is a service, not an action", "list it under 'services'")),
    ],
)
def test_an_action_entry_names_an_action(sample, written, fragments):
    _edit(sample, "type: diffbot_msgs/action/Dock", f"type: {written}")
    _apply_fails(sample, "robot.yaml:33:", *fragments)


def test_ros1_pkg_name_is_the_service_when_an_action_has_the_name_too(sample):
    # nav_msgs has GetMap.srv and GetMap.action: pkg/Name means the service, as rossrv reads it
    _edit(sample, "type: diffbot_msgs/action/Dock", "type: nav_msgs/GetMap")
    err = _apply_fails(sample, "'nav_msgs/GetMap' is a service, not an action")
    assert "in ROS 1, pkg/Name means the service; write nav_msgs/action/GetMap" in err
    _edit(sample, "type: nav_msgs/GetMap", "type: nav_msgs/action/GetMap")
    assert run_cli("apply", str(sample / "robot.yaml")).code == 0  # the hint works when followed


def test_every_unknown_type_of_the_manifest_is_reported_at_once(sample):
    _edit(sample, "type: nav_msgs/Odometry", "type: nav_msgs/Odometri")
    _edit(sample, "type: diffbot_msgs/action/Dock", "type: diffbot_msgs/action/Dok")
    _apply_fails(sample, "robot.yaml:19:", "robot.yaml:33:", "'nav_msgs/Odometri'", "Dok'")


def test_unknown_key_is_refused_with_the_nearest_key(sample):
    _edit(sample, "direction: publish, rate: 10", "direction: publish, rat: 10")
    _apply_fails(sample, "robot.yaml:18:", "did you mean 'rate'")


def test_duplicate_topic_is_refused(sample):
    _edit(sample, "name: /odom,", "name: /cmd_vel,")
    _apply_fails(sample, "robot.yaml:19:", "/cmd_vel")


def test_a_missing_gameobject_with_creation_off_lists_what_exists(sample):
    _edit(sample, "gameobject: Robot/Lidar}", "gameobject: Robot/Lidar2, create: false}")
    err = _apply_fails(sample, "robot.yaml:21:18: error: ")
    # The whole first line: the missing name, where it was looked for, and the one name there.
    first_line = err.splitlines()[0]
    assert first_line.endswith(
        "Main.unity: no GameObject named 'Lidar2' under 'Robot'; names there: 'Lidar'"
    ), first_line


def test_an_output_folder_leaving_the_project_is_refused(sample):
    _edit(sample, "output: Assets/RosGenerated", "output: Assets/../../outside")
    _apply_fails(sample, "robot.yaml:7:")


def test_an_output_folder_leaving_through_a_symlink_is_refused(sample, tmp_path):
    outside = tmp_path / "elsewhere"
    outside.mkdir()
    (sample / "unity" / "Assets" / "Linked").symlink_to(outside)
    _edit(sample, "output: Assets/RosGenerated", "output: Assets/Linked/Gen")
    _apply_fails(sample, "robot.yaml:7:", "symbolic link")
    assert not any(outside.iterdir())


def test_a_binary_scene_is_refused(sample):
    scene = sample / "unity" / "Assets" / "Scenes" / "Main.unity"
    scene.write_bytes(b"\x00\x01UnityFS binary scene \xff\xfe")
    _apply_fails(sample, "robot.yaml:8:", "Main.unity")


def test_a_scene_document_new_objects_would_copy_is_refused_where_it_is_not_yaml(sample):
    # A tab hides the first Transform's m_Children from a line-based reader: the new Robot/Sonar
    # would copy a Transform without it.
    scene = sample / "unity" / "Assets" / "Scenes" / "Main.unity"
    lines = scene.read_text().splitlines(keepends=True)
    assert lines[216] == "  m_Children: []\n"
    lines[216] = "\tm_Children: []\n"
    scene.write_text("".join(lines))
    _edit(sample, "gameobject: Robot/Lidar}", "gameobject: Robot/Sonar}")
    _apply_fails(
        sample,
        "Main.unity:217:1: error: --- !u!4 &705507995: is not valid YAML (found a tab character",
        "new Transforms copy its layout",
    )


def test_a_missing_scene_is_refused(sample):
    _edit(sample, "scene: Assets/Scenes/Main.unity", "scene: Assets/Scenes/Nope.unity")
    _apply_fails(sample, "robot.yaml:8:", "scene Assets/Scenes/Nope.unity not found")


def test_a_missing_interfaces_folder_is_refused(sample):
    shutil.rmtree(sample / "ros_ws")
    _apply_fails(sample, "robot.yaml:", "interface folder", "does not exist")


def test_a_project_without_ros_sharp_says_what_to_install(sample):
    (sample / "unity" / "Packages" / "manifest.json").write_text('{"dependencies": {}}')
    _apply_fails(sample, "ROS# is not installed", "com.siemens.ros-sharp")


def test_a_malformed_interface_file_is_located(sample):
    msg = sample / "ros_ws" / "src" / "diffbot_msgs" / "msg" / "WheelState.msg"
    msg.write_text(msg.read_text() + "float64\tbroken\n")
    _apply_fails(sample, "WheelState.msg:6:1: error: invalid field declaration")


def test_a_corrupt_lock_file_is_refused(sample):
    (sample / "robot.lock.json").write_text("{not json")
    _apply_fails(sample, "robot.lock.json is not a valid unityscaffold lock file")


def test_a_symlinked_folder_inside_the_output_cannot_lead_writes_outside(sample, tmp_path):
    outside = tmp_path / "outside_scripts"
    outside.mkdir()
    scripts = sample / "unity" / "Assets" / "RosGenerated" / "Scripts"
    shutil.rmtree(scripts)
    scripts.symlink_to(outside)
    _apply_fails(sample, "outside the Unity project", "symbolic link")
    assert not any(outside.iterdir())


def test_a_tampered_lock_cannot_delete_files_outside_the_project(sample, tmp_path):
    victim = tmp_path / "victim.txt"
    victim.write_text("precious\n")
    lock = sample / "robot.lock.json"
    text = lock.read_text()
    digest = __import__("hashlib").sha256(b"precious\n").hexdigest()
    lock.write_text(
        text.replace('"files": {', f'"files": {{\n    "../../victim.txt": "{digest}",', 1)
    )
    _apply_fails(sample, "robot.lock.json is not a valid unityscaffold lock file", "Assets/")
    assert victim.read_text() == "precious\n"


def test_binary_project_settings_are_refused(sample):
    settings = sample / "unity" / "ProjectSettings" / "ProjectSettings.asset"
    settings.write_bytes(b"\x00\x01binary settings\xff")
    _apply_fails(sample, "ProjectSettings.asset is not a text (YAML) settings file", "Force Text")


def test_a_project_folder_without_assets_points_at_the_project_key(sample):
    _edit(sample, "project: unity ", "project: ros_ws")
    manifest = sample / "robot.yaml"
    line = next(n for n in manifest.read_text().split("\n") if n.startswith("project:"))
    assert _apply_fails(sample) == (
        f"{manifest}:6:10: error: {sample / 'ros_ws'} is not a Unity project (no Assets/ folder)\n"
        f"    {line}\n"
        f"             ^\n"
        "  hint: set `project:` in the manifest, or create one with scaffold init\n"
    )


@pytest.mark.parametrize("name", ["std_msgs/Time", "std_msgs/Duration"])
def test_std_msgs_time_types_are_refused_with_rossharp_classes(sample, name):
    # ROS#'s Std.Time/Std.Duration are the bare primitives; tests/runtime/test_wire_defects.py
    # shows rosbridge refusing what they send as these types.
    _edit(sample, "type: nav_msgs/Odometry", f"type: {name}")
    _apply_fails(
        sample,
        "robot.yaml:19:",
        f"error: {name} cannot be sent or received with ROS#'s class for it",
        "holds it in a field 'data'",
        "the manifest key `namespace:`",
    )


def test_std_msgs_time_types_apply_with_a_namespace(sample):
    _edit(sample, "type: nav_msgs/Odometry", "type: std_msgs/Time")
    _edit(sample, "connector:", "namespace: Robot.Messages\nconnector:")
    run = run_cli("apply", str(sample / "robot.yaml"))
    assert run.code == 0, run.out + run.err
    generated = sample / "unity/Assets/RosGenerated/Messages/Std/msg/Time.cs"
    assert "public global::RosSharp.RosBridgeClient.MessageTypes.Std.Time data" in (
        generated.read_text()
    )
