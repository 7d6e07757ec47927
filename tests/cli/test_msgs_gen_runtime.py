"""``scaffold msgs gen --runtime``: the same command generates either runtime's classes."""

from __future__ import annotations

from pathlib import Path

from helpers import run_cli

REPO = Path(__file__).resolve().parents[2]
SAMPLE = REPO / "sample_project" / "ros_ws" / "src"


def _gen(out: Path, *extra: str) -> tuple[int, str, str]:
    done = run_cli("msgs", "gen", "--ros", "1", "--path", str(SAMPLE), "diffbot_msgs",
                   "-o", str(out), *extra)  # fmt: skip
    return done.code, done.out, done.err


def test_the_connector_runtime_generates_the_connectors_classes_and_checks_clean(
    tmp_path: Path,
) -> None:
    out = tmp_path / "tcp"
    code, printed, _ = _gen(out, "--runtime", "ros-tcp-connector")
    assert code == 0
    status = (out / "Diffbot" / "msg" / "BaseStatusMsg.cs").read_text()
    assert "namespace RosMessageTypes.Diffbot" in status
    assert "ROS-TCP-Connector ships RosMessageTypes.Std.HeaderMsg" in printed
    assert _gen(out, "--runtime", "ros-tcp-connector", "--check")[0] == 0
    # the other runtime's classes for the same types are other files: --check says so
    assert _gen(out, "--check")[0] == 1


def test_ros_sharp_stays_the_default_runtime(tmp_path: Path) -> None:
    out = tmp_path / "sharp"
    assert _gen(out)[0] == 0
    status = (out / "Diffbot" / "msg" / "BaseStatus.cs").read_text()
    assert "RosSharp.RosBridgeClient" in status
    assert not (out / "Diffbot" / "msg" / "BaseStatusMsg.cs").exists()


def test_an_unknown_runtime_is_refused_and_nothing_is_written(tmp_path: Path) -> None:
    code, _, err = _gen(tmp_path / "x", "--runtime", "ros-tcp")
    assert code == 2 and "--runtime must be ros-sharp or ros-tcp-connector" in err
    assert not (tmp_path / "x").exists()
