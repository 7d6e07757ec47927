"""``scaffold msgs list`` and ``msgs show`` through the CLI entry point."""

from __future__ import annotations

import json
import os
import subprocess
import sys

import pytest
from helpers import build_tree, run_cli

CUSTOM = {
    "ws/src/my_robot_msgs/package.xml": "<package><name>my_robot_msgs</name></package>",
    "ws/src/my_robot_msgs/msg/Status.msg": (
        "# Robot status.\nuint8 OK=0\nHeader header\nfloat32 battery  # volts\n"
    ),
    "ws/src/my_robot_msgs/srv/Reset.srv": "bool hard\n---\nbool success\n",
}


def test_show_json_has_exactly_the_documented_keys(tmp_path):
    build_tree(tmp_path, CUSTOM)
    run = run_cli(
        "msgs",
        "show",
        "my_robot_msgs/Status",
        "my_robot_msgs/Reset",
        "--ros",
        "1",
        "--path",
        str(tmp_path / "ws"),
        "--json",
    )
    assert run.code == 0, run.err
    message, service = json.loads(run.out)
    keys = {"type", "kind", "md5sum", "definition", "fields", "constants", "source"}
    assert set(message) == keys
    assert set(service) == keys | {"request", "response"}
    assert message["type"] == "my_robot_msgs/Status"
    assert message["definition"].split("\n")[0] == "# Robot status."
    assert "MSG: std_msgs/Header" in message["definition"]
    assert [f["name"] for f in message["fields"]] == ["header", "battery"]
    assert message["fields"][1]["comment"] == "volts"
    assert message["constants"][0]["value"] == 0
    assert service["request"]["type"] == "my_robot_msgs/ResetRequest"
    assert service["response"]["md5sum"] and len(service["md5sum"]) == 32
    assert service["source"].endswith("srv/Reset.srv")


def test_service_halves_are_accepted_as_types(tmp_path):
    build_tree(tmp_path, CUSTOM)
    run = run_cli(
        "msgs",
        "show",
        "my_robot_msgs/ResetResponse",
        "--ros",
        "1",
        "--path",
        str(tmp_path / "ws"),
        "--json",
    )
    assert json.loads(run.out)[0]["fields"][0]["name"] == "success"


def test_package_name_comes_from_package_xml_not_the_folder(tmp_path):
    build_tree(
        tmp_path,
        {
            "ws/folder_name/package.xml": "<package>\n  <name>real_name</name>\n</package>",
            "ws/folder_name/msg/A.msg": "int32 x\n",
        },
    )
    run = run_cli(
        "msgs",
        "list",
        "--ros",
        "1",
        "--path",
        str(tmp_path / "ws"),
        "--package",
        "real_name",
        "--json",
    )
    assert run.code == 0, run.err
    assert json.loads(run.out)[0]["types"] == [{"type": "real_name/A", "kind": "msg"}]


def test_the_first_definition_wins_and_show_names_the_other(tmp_path):
    build_tree(tmp_path, {"ws/std_msgs/msg/String.msg": "string data\nint32 extra\n"})
    run = run_cli("msgs", "show", "std_msgs/String", "--ros", "1", "--path", str(tmp_path / "ws"))
    assert run.code == 0
    assert f"source:     {tmp_path / 'ws/std_msgs/msg/String.msg'} (given path)" in run.out
    assert "not used:" in run.out and "DIFFERENT text" in run.out


def test_a_malformed_file_is_located_and_does_not_hide_the_good_ones(tmp_path):
    build_tree(
        tmp_path,
        {"ws/pkg/msg/Good.msg": "int32 x\n", "ws/pkg/msg/Bad.msg": "int32 x\nfloat64\ty\n"},
    )
    run = run_cli("msgs", "list", "--ros", "1", "--path", str(tmp_path / "ws"), "--package", "pkg")
    assert run.code == 2
    assert "pkg/Good" in run.out
    assert f"{tmp_path / 'ws/pkg/msg/Bad.msg'}:2:1: error: invalid field declaration" in run.err
    assert "Traceback" not in run.err


def test_showing_a_malformed_type_exits_2_with_its_position(tmp_path):
    build_tree(tmp_path, {"ws/pkg/msg/Bad.msg": "int32 x\nstring S\nint32 1x\n"})
    run = run_cli("msgs", "show", "pkg/Bad", "--ros", "1", "--path", str(tmp_path / "ws"))
    assert run.code == 2
    assert "Bad.msg:3:7: error: '1x' is not a legal field name" in run.err
    assert "    int32 1x\n          ^" in run.err


@pytest.mark.parametrize("ros", ["1", "2"])
def test_showing_a_type_that_contains_itself_is_refused_at_the_field_that_closes_the_cycle(
    ros, tmp_path
):
    """Its ROS 1 md5 would need its own md5: this recursed until Python gave up (exit 3)."""
    build_tree(tmp_path, {"ws/loop_msgs/msg/A.msg": "B b\n", "ws/loop_msgs/msg/B.msg": "A a\n"})
    run = run_cli(
        "msgs", "show", "loop_msgs/A", "--ros", ros, "--no-env", "--path", str(tmp_path / "ws")
    )
    assert run.code == 2 and "Traceback" not in run.err
    b = tmp_path / "ws/loop_msgs/msg/B.msg"
    mid = "/msg/" if ros == "2" else "/"
    assert run.err.startswith(
        f"{b}:1:1: error: types refer to each other in a cycle: loop_msgs{mid}A -> "
        f"loop_msgs{mid}B -> loop_msgs{mid}A\n"
    )


@pytest.mark.parametrize("ros", ["1", "2"])
def test_showing_a_type_with_an_unknown_field_type_names_that_field(ros, tmp_path):
    build_tree(tmp_path, {"ws/uses_msgs/msg/U.msg": "int32 a\nnowhere_msgs/Missing m\n"})
    run = run_cli(
        "msgs", "show", "uses_msgs/U", "--ros", ros, "--no-env", "--path", str(tmp_path / "ws")
    )
    assert run.code == 2
    assert run.err.startswith(
        f"{tmp_path / 'ws/uses_msgs/msg/U.msg'}:2:1: error: unknown ROS {ros}"
    )


@pytest.mark.parametrize(("ros1_type", "ros2_type"), [("time", "Time"), ("duration", "Duration")])
@pytest.mark.parametrize("command", ["show", "gen"])
def test_a_ros2_field_of_ros1_time_is_refused_at_its_line_with_a_hint_that_works(
    ros1_type, ros2_type, command, tmp_path
):
    """rosidl's parser takes ``time`` for compatibility, but it has no ROS 2 type id: the
    type hash raised KeyError (exit 3)."""
    build_tree(
        tmp_path, {"ws/p/msg/A.msg": f"int32 a\n{ros1_type} t\n", "ws/p/msg/Uses.msg": "A a\n"}
    )
    args = ["--ros", "2", "--no-env", "--path", str(tmp_path / "ws")]
    out = ["-o", str(tmp_path / "out")] if command == "gen" else []
    run = run_cli("msgs", command, "p/msg/Uses", *args, *out)
    assert run.code == 2 and "Traceback" not in run.err
    assert run.err == (
        f"{tmp_path / 'ws/p/msg/A.msg'}:2:1: error: '{ros1_type}' is a ROS 1 type; ROS 2 has no "
        f"type hash or code for it\n  hint: write builtin_interfaces/{ros2_type} instead\n"
    )
    assert not (tmp_path / "out").exists()
    (tmp_path / "ws/p/msg/A.msg").write_text(f"int32 a\nbuiltin_interfaces/{ros2_type} t\n")
    assert run_cli("msgs", command, "p/msg/Uses", *args, *out).code == 0


def test_unknown_type_suggests_close_names():
    run = run_cli("msgs", "show", "geometry_msgs/Twst", "--ros", "2", "--no-env")
    assert run.code == 2
    assert "unknown ROS 2 type 'geometry_msgs/Twst'" in run.err
    assert "did you mean geometry_msgs/msg/Twist" in run.err
    assert "built-in" in run.err


def test_ros1_pkg_name_is_the_msg_or_srv_as_rossrv_reads_it_and_pkg_action_name_the_action():
    # nav_msgs has GetMap.srv and GetMap.action; in ROS 1 only the srv is a type named GetMap.
    for name, kind in (
        ("nav_msgs/GetMap", "srv"),
        ("nav_msgs/srv/GetMap", "srv"),
        ("nav_msgs/action/GetMap", "action"),
        ("nav_msgs/GetMapGoal", "msg"),
    ):
        run = run_cli("msgs", "show", name, "--ros", "1", "--no-env", "--json")
        assert run.code == 0, run.err
        assert json.loads(run.out)[0]["kind"] == kind


def _hinted(err: str) -> list[str]:
    """The type names a hint proposes ('write A or B', 'did you mean A or B?')."""
    hint = err.split("hint:", 1)[1].split("looked")[0]
    words = hint.replace("?", " ").replace(",", " ").replace(";", " ").split()
    return [w for w in words if w.count("/") in (1, 2) and not w.startswith("/")]


def _show(tree, *names, ros):
    return run_cli("msgs", "show", *names, "--ros", ros, "--no-env", "--path", str(tree))


AMBIGUOUS = {
    "ws/pkg_msgs/msg/Thing.msg": "int32 a\n",
    "ws/pkg_msgs/srv/Thing.srv": "int32 a\n---\nint32 b\n",
    "ws/pkg_msgs/action/Patrol.action": "int32 a\n---\nint32 b\n---\nint32 c\n",
    "ws/pkg_msgs/msg/RobotState.msg": "int32 a\n",
}


@pytest.mark.parametrize("ros", ["1", "2"])
def test_a_name_of_two_kinds_gets_a_hint_that_works_when_followed(ros, tmp_path):
    build_tree(tmp_path, AMBIGUOUS)
    run = _show(tmp_path / "ws", "pkg_msgs/Thing", ros=ros)
    assert run.code == 2
    assert "'pkg_msgs/Thing' names both a msg and a srv" in run.err
    hinted = _hinted(run.err)
    assert hinted == ["pkg_msgs/msg/Thing", "pkg_msgs/srv/Thing"]
    for name in hinted:
        assert _show(tmp_path / "ws", name, ros=ros).code == 0


def test_a_ros1_action_is_named_pkg_action_name_or_pkg_name_when_nothing_else_is(tmp_path):
    build_tree(tmp_path, AMBIGUOUS)
    for name in ("pkg_msgs/action/Patrol", "pkg_msgs/Patrol", "pkg_msgs/PatrolGoal"):
        assert _show(tmp_path / "ws", name, ros="1").code == 0, name


@pytest.mark.parametrize("name", ["pkg_msgs/action/Patrol_SendGoal", "pkg_msgs/Patrol_GetResult"])
def test_a_ros2_actions_derived_service_is_refused_with_hints_that_work(name, tmp_path):
    build_tree(tmp_path, AMBIGUOUS)
    run = _show(tmp_path / "ws", name, ros="2")
    assert run.code == 2 and "Traceback" not in run.err
    assert f"'{name}' is a service rosidl derives from the action pkg_msgs/action/Patrol" in (
        run.err
    )
    hinted = _hinted(run.err)
    service = "pkg_msgs/action/Patrol_" + name.rsplit("_", 1)[1]
    assert hinted == ["pkg_msgs/action/Patrol", f"{service}_Request", f"{service}_Response"]
    for hint in hinted:
        assert _show(tmp_path / "ws", hint, ros="2").code == 0, hint


def test_a_ros2_actions_derived_message_says_where_it_comes_from(tmp_path):
    build_tree(tmp_path, AMBIGUOUS)
    for name in (
        "pkg_msgs/action/Patrol_FeedbackMessage",
        "pkg_msgs/action/Patrol_SendGoal_Request",
    ):
        run = _show(tmp_path / "ws", name, ros="2")
        assert run.code == 0, run.err
        assert "derived:    by rosidl from pkg_msgs/action/Patrol, with no text of its own" in (
            run.out
        )
    written = _show(tmp_path / "ws", "pkg_msgs/action/Patrol_Goal", ros="2")
    assert written.code == 0 and "derived:" not in written.out  # the file's own text


@pytest.mark.parametrize("ros", ["1", "2"])
def test_suggestions_come_from_the_same_package_first_and_work_when_followed(ros, tmp_path):
    build_tree(tmp_path, AMBIGUOUS)
    for typo in ("pkg_msgs/RobotStat", "pkg_msgs/Patro", "pkg_msgs/Thin"):
        run = _show(tmp_path / "ws", typo, ros=ros)
        assert run.code == 2, typo
        hinted = _hinted(run.err)
        assert hinted and hinted[0].startswith("pkg_msgs/"), run.err
        for name in hinted:
            assert _show(tmp_path / "ws", name, ros=ros).code == 0, (typo, name, run.err)


def test_unknown_types_are_reported_all_at_once_and_a_missing_package_is_named():
    run = run_cli(
        "msgs",
        "show",
        "nope_msgs/msg/A",
        "geometry_msgs/msg/Pointt",
        "other_msgs/msg/B",
        "std_msgs/msg/String",
        "--ros",
        "2",
        "--no-env",
    )
    assert run.code == 2
    assert "3 types are unknown:" in run.err
    assert "unknown ROS 2 type 'nope_msgs/msg/A': no package 'nope_msgs' was found" in run.err
    assert "unknown ROS 2 type 'other_msgs/msg/B': no package 'other_msgs' was found" in run.err
    assert "did you mean geometry_msgs/msg/Point or" in run.err
    assert "hint: looked in: " in run.err and "(built-in)" in run.err


def test_a_single_missing_package_says_where_packages_are_looked_for():
    run = run_cli("msgs", "show", "nope_msgs/msg/A", "--ros", "2", "--no-env")
    assert run.code == 2
    assert "no package 'nope_msgs' was found" in run.err
    assert "hint: packages are looked for in: " in run.err


def test_msgs_gen_reports_every_unknown_type_too(tmp_path):
    run = run_cli(
        "msgs",
        "gen",
        "nope_msgs/A",
        "nope_msgs/B",
        "--ros",
        "1",
        "--no-env",
        "--out",
        str(tmp_path / "out"),
    )
    assert run.code == 2
    assert "2 types are unknown:" in run.err
    assert not (tmp_path / "out").exists()


def test_tf2_msgs_tfmessage_is_built_in_for_ros2_with_jazzys_type_hash():
    run = run_cli("msgs", "show", "tf2_msgs/msg/TFMessage", "--ros", "2", "--no-env")
    assert run.code == 0, run.err
    # The hash a Jazzy system reports for /tf (ros2 topic info -v, rosbag2 metadata).
    expected = "RIHS01_e369d0f05a23ae52508854b66f6aa0437f3449d652e8cbf22d5abe85d020f087"
    assert f"type hash:  {expected}" in run.out
    assert "(built-in)" in run.out


@pytest.mark.parametrize("ros", ["1", "2"])
def test_builtin_fallback_works_with_no_ros_paths_at_all(ros, tmp_path):
    """A separate process with an empty environment and --no-env: only the built-in definitions."""
    env = {"PATH": os.environ["PATH"], "HOME": str(tmp_path)}
    done = subprocess.run(
        [
            sys.executable,
            "-m",
            "unityscaffold",
            "msgs",
            "show",
            "sensor_msgs/Imu",
            "--ros",
            ros,
            "--no-env",
            "--json",
        ],
        capture_output=True,
        text=True,
        env=env,
        timeout=60,
    )
    assert done.returncode == 0, done.stderr
    (shown,) = json.loads(done.stdout)
    assert "/builtin/ros" in shown["source"]
    if ros == "1":
        assert shown["md5sum"] == "6a62c6daae103f4ff57a132d6f95cec2"
    else:
        assert shown["type"] == "sensor_msgs/msg/Imu" and shown["md5sum"] is None


def test_bad_ros_version_is_a_user_error():
    run = run_cli("msgs", "list", "--ros", "3")
    assert run.code == 2 and "--ros must be 1 or 2" in run.err


def test_missing_path_is_a_user_error(tmp_path):
    run = run_cli("msgs", "list", "--path", str(tmp_path / "nope"))
    assert run.code == 2 and "interface folder not found" in run.err


@pytest.mark.parametrize(
    "args", [("msgs", "show"), ("apply", "--no-such-option"), ("msgs", "frob"), ("init",)]
)
def test_usage_errors_exit_2_without_a_traceback(args):
    run = run_cli(*args)
    assert run.code == 2
    assert "Traceback" not in run.err and "internal error" not in run.err
    assert "Usage:" in run.err or "Error" in run.err
