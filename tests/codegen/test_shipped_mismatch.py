"""A type ROS# ships is skipped by name; when the target's definition has other fields than
ROS#'s class (Jazzy's ``sensor_msgs/msg/Range`` has ``variance``, ROS# 2.2.1's class does not),
the user is warned, with the definition's hash and the way to generate our class instead."""

from __future__ import annotations

from pathlib import Path

from helpers import run_cli

from unityscaffold.codegen._shipped import shipped_fields
from unityscaffold.interfaces.model import Dialect


def test_rossharp_fields_are_known_per_class() -> None:
    assert shipped_fields(Dialect.ROS2)[("Std", "Header")] == ("stamp", "frame_id")
    assert shipped_fields(Dialect.ROS1)[("Std", "Header")] == ("seq", "stamp", "frame_id")
    assert "variance" not in shipped_fields(Dialect.ROS2)[("Sensor", "Range")]


def test_msgs_gen_warns_when_the_shipped_class_lacks_a_field(tmp_path: Path) -> None:
    run = run_cli("msgs", "gen", "sensor_msgs/msg/Range", "--ros", "2", "-o", str(tmp_path))
    assert run.code == 0, run.err
    warnings = [line for line in run.err.splitlines() if line.startswith("warning: ")]
    assert len(warnings) == 1, run.err  # Header matches ROS#'s class: no warning for it
    assert warnings[0].startswith(
        "warning: ROS#'s RosSharp.RosBridgeClient.MessageTypes.Sensor.Range does not match "
        "sensor_msgs/msg/Range as defined here (ROS 2 type hash of sensor_msgs/msg/Range: RIHS01_"
    )
    assert warnings[0].endswith(
        "it lacks variance; to generate ours instead, set a `namespace:` of your own in the "
        "manifest (msgs gen --namespace)"
    )


def test_a_custom_namespace_generates_ours_and_silences_the_warning(tmp_path: Path) -> None:
    run = run_cli(
        "msgs", "gen", "sensor_msgs/msg/Range", "--ros", "2", "-o", str(tmp_path),
        "--namespace", "MyRobot.Ros",
    )  # fmt: skip
    assert run.code == 0, run.err
    assert "warning:" not in run.err
    assert "variance" in (tmp_path / "Sensor" / "msg" / "Range.cs").read_text()
