"""Warnings about a runtime's shipped classes: a class that only starts with other values than
ROS's default (ROS-TCP-Connector's ROS 1 ``QuaternionMsg``: ``w = 1``) is named for an entry
that sends it, when that entry's script is written; a class that garbles messages, on every
apply."""

from __future__ import annotations

from pathlib import Path

from helpers import run_cli

QUATERNION = "RosMessageTypes.Geometry.QuaternionMsg does not match geometry_msgs/Quaternion"
EMPTY = "RosMessageTypes.Std.EmptyMsg does not match std_msgs/msg/Empty"
HEADER = "version: 1\nros: {ros}\nruntime: ros-tcp-connector\nscene: Assets/Scenes/Main.unity\n"


def _project(tmp_path: Path, ros: int, topics: str) -> Path:
    project = tmp_path / "project"
    done = run_cli("init", str(project), "--ros", str(ros), "--runtime", "ros-tcp-connector")
    assert done.code == 0, done.err
    (project / "robot.yaml").write_text(HEADER.format(ros=ros) + "topics:\n" + topics)
    return project


def _output(project: Path, *options: str, code: int = 0) -> str:
    done = run_cli("apply", *options, str(project / "robot.yaml"))
    assert done.code == code, done.err
    return done.out + done.err


def test_a_default_only_difference_is_not_noted_for_a_type_unity_only_receives(
    tmp_path: Path,
) -> None:
    odom = "  - {name: /odom, type: nav_msgs/Odometry, direction: subscribe}\n"
    project = _project(tmp_path, 1, odom)
    assert QUATERNION not in _output(project, "--check", code=1)  # 1: the project drifted
    assert QUATERNION not in _output(project)
    assert QUATERNION not in _output(project)


def test_a_default_only_difference_is_noted_when_the_sending_script_is_written(
    tmp_path: Path,
) -> None:
    pose = "  - {name: /goal, type: geometry_msgs/PoseStamped, direction: publish, rate: 1}\n"
    project = _project(tmp_path, 1, pose)
    assert QUATERNION in _output(project, "--check", code=1)  # says what apply would
    assert QUATERNION in _output(project)
    assert QUATERNION not in _output(project)  # said once; nothing changed since
    assert QUATERNION not in _output(project, "--check")
    manifest = project / "robot.yaml"
    manifest.write_text(manifest.read_text().replace("rate: 1", "rate: 5"))
    assert QUATERNION in _output(project)  # the script changed: said again


def test_a_class_that_garbles_messages_is_noted_on_every_apply(tmp_path: Path) -> None:
    ping = "  - {name: /ping, type: std_msgs/msg/Empty, direction: publish}\n"
    project = _project(tmp_path, 2, ping)
    assert EMPTY in _output(project)
    assert EMPTY in _output(project)
    assert EMPTY in _output(project, "--check")
