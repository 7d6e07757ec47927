"""``apply`` notes, at the manifest entry's line, what rosbridge 2.x will not carry for a ROS 2
entry (tests/runtime/test_ros2_roundtrip.py shows it drops those messages): wstring, bounded
strings and byte arrays, nested ones included, naming the upstream report and a workaround; and
that an action client's cancel waits for its goal unless rosbridge sends goals in threads."""

from __future__ import annotations

from pathlib import Path

from helpers import run_cli

MANIFEST = """\
version: 1
ros: 2
scene: Assets/Scenes/Main.unity
interfaces: [{share}]
topics:
  - {{name: /wide, type: test_msgs/msg/WStrings, direction: subscribe, gameobject: A}}
  - {{name: /plain, type: std_msgs/msg/String, direction: publish, gameobject: A}}
  - {{name: /nested, type: test_msgs/msg/MultiNested, direction: subscribe, gameobject: A}}
  - {{name: /bounded, type: test_msgs/msg/Strings, direction: publish, gameobject: A}}
services:
  - {{name: /params, type: rcl_interfaces/srv/SetParameters, role: client, gameobject: A}}
actions:
  - {{name: /fib, type: test_msgs/action/Fibonacci, role: client, gameobject: A}}
  - {{name: /fib_server, type: test_msgs/action/Fibonacci, role: server, gameobject: A}}
"""


def _type_at(text: str, name: str) -> str:
    """``line:column`` of the type of the entry named ``name`` in the manifest ``text``."""
    for number, line in enumerate(text.splitlines(), 1):
        if f"name: {name}," in line:
            return f"{number}:{line.index('type: ') + len('type: ') + 1}"
    raise AssertionError(name)


def test_ros2_entries_rosbridge_cannot_carry_get_a_note_at_their_line(
    tmp_path: Path, ros2_share: Path
) -> None:
    project = tmp_path / "p"
    assert run_cli("init", str(project), "--ros", "2").code == 0
    manifest = project / "robot.yaml"
    text = MANIFEST.format(share=ros2_share)
    manifest.write_text(text, encoding="utf-8")
    done = run_cli("apply", str(manifest))
    assert done.code == 0, done.err
    rosbridge = [n for n in done.out.splitlines() if n.startswith("note: ") and "rosbridge 2" in n]
    assert [n.split(": ", 2)[1] for n in rosbridge] == [
        f"{manifest}:{_type_at(text, name)}"
        for name in ("/wide", "/nested", "/bounded", "/params", "/fib")
    ]
    wide, nested, bounded, params, cancel = rosbridge
    assert (
        "/wide (test_msgs/msg/WStrings): rosbridge 2.x cannot carry .wstring_value (wstring)"
        in (wide)
    )
    assert "rosbridge_suite/issues/1297" in wide
    # Found inside nested messages; three fields are listed, then how many more.
    assert "cannot carry .array_of_arrays[].byte_values[] (byte[3])," in nested
    assert "and 15 more" in nested
    assert "byte array: https://github.com/RobotWebTools/rosbridge_suite/pull/1315" in nested
    assert ".bounded_string_value (string<=22)" in bounded
    assert "bounded string: https://github.com/RobotWebTools/rosbridge_suite/pull/827" in bounded
    # rcl_interfaces/msg/ParameterValue.byte_array_value, in the request's parameters.
    assert ".parameters[].value.byte_array_value[] (byte[])" in params
    assert "/fib (test_msgs/action/Fibonacci): rosbridge 2.x runs a client's goals" in cancel
    assert "send_action_goals_in_new_thread:=true" in cancel
    assert "rosbridge_suite/issues/909" in cancel
    assert not any("/plain" in n or "/fib_server" in n for n in rosbridge)


def test_ros1_entries_get_no_rosbridge_2_note(tmp_path: Path) -> None:
    manifest = """\
version: 1
ros: 1
scene: Assets/Scenes/Main.unity
topics:
  - {name: /plain, type: std_msgs/String, direction: publish, gameobject: A}
"""
    project = tmp_path / "p"
    assert run_cli("init", str(project), "--ros", "1").code == 0
    (project / "robot.yaml").write_text(manifest, encoding="utf-8")
    done = run_cli("apply", str(project / "robot.yaml"))
    assert done.code == 0, done.err
    assert "rosbridge 2.x" not in done.out
