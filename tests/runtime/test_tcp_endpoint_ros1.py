"""Generated ROS-TCP-Connector scripts, run under Mono with the connector's real ROSConnection
(its socket thread, registrations, main-thread callbacks) in the UnityEngine stand-in's frame
loop, against the real ROS-TCP-Endpoint v0.7.0 (ROS 1) on Debian's rospy and a real rosmaster,
on loopback: a publisher whose messages a rospy node echoes to a subscriber, a call of a rospy
service, a rospy call of the service a Unity script provides, and a ROS 1 action each way with
rospy's actionlib (nav_msgs/GetMap, whose wrappers the connector ships unregistered)."""

from __future__ import annotations

import os
from pathlib import Path

import pytest
from connector_csharp import RUNNABLE, compile_connector
from helpers import SYSTEM_PYTHON, require, run_cli
from processes import free_port, run, start, stop, wait_for

from tests.runtime.bridge import vendor_folder
from tests.runtime.client import mcs_compile

HERE = Path(__file__).resolve().parent
MANIFEST = """\
version: 1
ros: 1
runtime: ros-tcp-connector
scene: Assets/Scenes/Main.unity
topics:
  - {name: /chatter, type: std_msgs/String, direction: publish, rate: 5}
  - {name: /echo, type: std_msgs/String, direction: subscribe, gameobject: Robot}
services:
  - {name: /trigger, type: std_srvs/Trigger, role: client, gameobject: Robot}
  - {name: /set, type: std_srvs/SetBool, role: server, gameobject: Robot}
actions:
  - {name: /map, type: nav_msgs/action/GetMap, role: client, gameobject: Robot}
  - {name: /sim/map, type: nav_msgs/action/GetMap, role: server, gameobject: Robot}
"""


def _endpoint_sources() -> Path:
    folder = vendor_folder("UNITYSCAFFOLD_TCP_ENDPOINT", "ros-tcp-endpoint/ros1-v0.7.0")
    require(folder, "ROS-TCP-Endpoint v0.7.0 for ROS 1 (UNITYSCAFFOLD_TCP_ENDPOINT)")
    assert folder is not None
    return folder / "src"


def _scenario(mcs: str, tmp_path: Path) -> Path:
    """The applied project's generated plumbing (its user halves replaced by the scenario's)
    compiled with the connector into TcpScenario.exe."""
    project = tmp_path / "project"
    assert run_cli("init", str(project), "--ros", "1", "--runtime", "ros-tcp-connector").code == 0
    (project / "robot.yaml").write_text(MANIFEST, encoding="utf-8")
    done = run_cli("apply", str(project / "robot.yaml"))
    assert done.code == 0, done.err
    build = tmp_path / "build"
    engine, package = compile_connector(mcs, build, ros2=False, engine=RUNNABLE)
    generated = [
        p
        for p in sorted((project / "Assets" / "RosGenerated").rglob("*.cs"))
        if not p.name.endswith(".User.cs")
    ]
    exe = build / "TcpScenario.exe"
    mcs_compile(
        mcs,
        [HERE / "csharp" / "TcpScenario.cs", *generated],
        exe,
        references=[engine, package],
        target="exe",
    )
    return exe


@pytest.fixture
def ros(tmp_path: Path):  # type: ignore[no-untyped-def]
    """rosmaster, ROS-TCP-Endpoint and the rospy robot node on free loopback ports."""
    require(Path("/usr/bin/rosmaster").exists(), "Debian's python3-rosmaster")
    sources = _endpoint_sources()
    master_port, endpoint_port = free_port(), free_port()
    home = tmp_path / "ros"
    home.mkdir()
    env = {
        **os.environ,
        "ROS_MASTER_URI": f"http://127.0.0.1:{master_port}",
        "ROS_HOSTNAME": "127.0.0.1",
        "ROS_LOG_DIR": str(home / "log"),
        "ROS_HOME": str(home),
        "PYTHONPATH": str(sources),
    }
    env.pop("PYTHONHOME", None)
    logs = [home / "master.log", home / "endpoint.log", home / "robot.log"]
    processes = []
    try:
        processes.append(
            start(
                [str(SYSTEM_PYTHON), "/usr/bin/rosmaster", "--core", "-p", str(master_port)],
                env,
                logs[0],
            )
        )
        processes.append(
            start(
                [str(SYSTEM_PYTHON), str(HERE / "data" / "tcp_endpoint.py"), str(endpoint_port)],
                env,
                logs[1],
            )
        )
        processes.append(
            start([str(SYSTEM_PYTHON), "-u", str(HERE / "data" / "tcp_robot.py")], env, logs[2])
        )
        wait_for("ROS-TCP-Endpoint", lambda: "Starting server on" in logs[1].read_text(), 30, logs)
        yield endpoint_port, logs
    finally:
        for process in reversed(processes):
            stop(process)


@pytest.mark.usefixtures("actionlib_python")
def test_generated_scripts_talk_to_ros_through_the_real_endpoint(
    mcs: str, mono: str, tmp_path: Path, ros: tuple[int, list[Path]]
) -> None:
    exe = _scenario(mcs, tmp_path)
    port, logs = ros
    done = run([mono, str(exe), "127.0.0.1", str(port)], timeout=120)
    robot = logs[2].read_text(errors="replace")
    report = dict(
        line.split(" ", 1) for line in done.stdout.splitlines() if line and not line.startswith("[")
    )
    context = (
        f"{done.stdout}\n{done.stderr}\n--- robot:\n{robot}\n--- endpoint:\n"
        + (logs[1].read_text(errors="replace")[-3000:])
    )
    assert done.returncode == 0, context
    assert report.get("echo", "").startswith("echo: hello "), context
    assert report.get("trigger") == "True triggered", context
    assert int(report.get("set_calls", "0")) >= 1, context
    assert "set True set to True" in robot, context
    assert report.get("map_result") == "3 map-from-ros 3", context  # SUCCEEDED
    assert int(report.get("map_goals", "0")) == 1, context
    assert "map_result 3 map-from-unity" in robot, context
    assert report.get("off_main") == "0", context
