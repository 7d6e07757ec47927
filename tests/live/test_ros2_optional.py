"""``rclpy`` comes with the optional ``ros2`` extra: only ``discover --ros2`` imports it, and
without it that command says what to install instead of failing with a traceback."""

from __future__ import annotations

import json
import sys
from pathlib import Path

import processes

REPO = Path(__file__).resolve().parents[2]

# The CLI in a fresh interpreter where ``import rclpy`` fails as if it were not installed.
_PROGRAM = """
import json, sys
sys.modules["rclpy"] = None
from unityscaffold.cli import main
code = main(sys.argv[1:])
print(json.dumps({"code": code, "rclpy_imported": sys.modules.get("rclpy") is not None}))
"""


def _without_rclpy(cwd: Path, *args: str) -> tuple[dict[str, object], str]:
    env = {"PYTHONPATH": str(REPO), "PATH": "/usr/bin:/bin"}
    run = processes.run([sys.executable, "-c", _PROGRAM, *args], timeout=120, cwd=cwd, env=env)
    return json.loads(run.stdout.strip().splitlines()[-1]), run.stderr


def test_discover_ros2_without_rclpy_says_which_extra_to_install(tmp_path: Path) -> None:
    (tmp_path / "robot.yaml").write_text("ros: 2\n")
    result, err = _without_rclpy(tmp_path, "discover", "--ros2")
    assert result["code"] == 2, err
    assert "error: reading the ROS 2 graph needs rclpy, which is not installed" in err
    assert "unityscaffold[ros2]" in err and "--rosbridge" in err
    assert "Traceback" not in err
    assert (tmp_path / "robot.yaml").read_text() == "ros: 2\n"
    assert not (tmp_path / "ros_definitions").exists()


def test_ros2_is_one_source_among_the_others(tmp_path: Path) -> None:
    result, err = _without_rclpy(
        tmp_path, "discover", "--print", "--ros2", "--rosbridge", "ws://127.0.0.1:9"
    )
    assert result["code"] == 2, err
    assert "give exactly one source: --master URL, --rosbridge URL, --ros2 or --bag FILE" in err
    assert result["rclpy_imported"] is False


def test_other_sources_do_not_need_rclpy(tmp_path: Path) -> None:
    result, err = _without_rclpy(
        tmp_path, "discover", "--print", "--rosbridge", "ws://127.0.0.1:9", "--timeout", "0.5"
    )
    assert result["code"] == 2, err
    assert "no rosbridge at ws://127.0.0.1:9" in err and "rclpy" not in err
    assert result["rclpy_imported"] is False
