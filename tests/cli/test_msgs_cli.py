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


def test_unknown_type_suggests_close_names():
    run = run_cli("msgs", "show", "geometry_msgs/Twst", "--ros", "2", "--no-env")
    assert run.code == 2
    assert "unknown ROS 2 type 'geometry_msgs/Twst'" in run.err
    assert "did you mean geometry_msgs/Twist" in run.err
    assert "built-in" in run.err


def test_ambiguous_name_asks_for_the_kind():
    run = run_cli("msgs", "show", "nav_msgs/GetMap", "--ros", "1", "--no-env")
    assert run.code == 2
    assert "nav_msgs/srv/GetMap or nav_msgs/action/GetMap" in run.err


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
