"""The service scripts ``scaffold apply`` generates for ROS 2, run: a client of the sample's
diffbot_msgs/srv/SetSpeedLimit and a server of std_srvs/srv/Trigger in the UnityEngine
stand-in's frame loop with ROS#'s real RosConnector and client (csharp/ServiceScenario.cs writes
their user halves), through the real rosbridge 2.x against an rclpy server and client
(data/ros2/service_script_node.py): both calls the client makes are answered, in order, on the
frame loop's thread; both calls rclpy makes are served."""

from __future__ import annotations

import json
import shutil
from functools import partial
from pathlib import Path

from helpers import run_cli
from processes import wait_for

from tests.runtime.client import CSHARP, mcs_compile
from tests.runtime.lines import start
from tests.runtime.ros2 import Rosbridge2
from tests.runtime.runtime_helpers import SAMPLE_ROS2_INTERFACES

DATA = Path(__file__).parent / "data" / "ros2"
TIMEOUT = 60  # seconds; a guard against a hang only
MANIFEST = """\
version: 1
ros: 2
scene: Assets/Scenes/Main.unity
interfaces: [ws]
connector: {gameobject: RosConnector, url: "ws://localhost:9090", serializer: newtonsoft}
services:
  - {name: /set_speed_limit, type: diffbot_msgs/srv/SetSpeedLimit, role: client, gameobject: Robot}
  - {name: /reset_cs, type: std_srvs/srv/Trigger, role: server, gameobject: Robot}
"""


def _build(mcs: str, client: Path, package: Path, tmp_path: Path) -> Path:
    project = tmp_path / "ros2"
    assert run_cli("init", str(project), "--ros", "2").code == 0
    shutil.copytree(SAMPLE_ROS2_INTERFACES, project / "ws")
    (project / "robot.yaml").write_text(MANIFEST, encoding="utf-8")
    done = run_cli("apply", str(project / "robot.yaml"))
    assert done.code == 0, done.err
    generated = project / "Assets" / "RosGenerated"
    out = tmp_path / "bin"
    out.mkdir()
    for dll in client.parent.glob("*.dll"):
        if dll.name != "UnityEngine.dll":
            shutil.copy2(dll, out / dll.name)
    engine = out / "UnityEngine.dll"
    mcs_compile(mcs, [CSHARP / "UnityEngineRuntime.cs"], engine)
    connector = package / "Runtime" / "RosBridgeClient" / "RosCommunication" / "RosConnector.cs"
    plumbing = [p for p in sorted(generated.rglob("*.cs")) if not p.name.endswith(".User.cs")]
    exe = out / "ServiceScenario.exe"
    mcs_compile(
        mcs,
        [connector, *plumbing, CSHARP / "ServiceScenario.cs"],
        exe,
        references=[engine, *(out / n for n in ("RosBridgeClient.dll", "Newtonsoft.Json.dll"))],
        target="exe",
        defines=["ROS2"],
    )
    return exe


def _values(lines: list[str], key: str) -> list[str]:
    return [line.split(" ", 1)[1] for line in lines if line.startswith(key + " ")]


def test_ros2_service_scripts_against_rclpy(
    rosbridge2: Rosbridge2,
    mcs: str,
    mono: str,
    rossharp_ros2_client: Path,
    rossharp_package: Path,
    tmp_path: Path,
) -> None:
    exe = _build(mcs, rossharp_ros2_client, rossharp_package, tmp_path)
    result = tmp_path / "node.json"
    node = rosbridge2.ros2.run_node(DATA / "service_script_node.py", str(result), str(TIMEOUT))
    scenario = None
    try:
        assert node.wait_for(lambda line: line == "ready", TIMEOUT), node.finish()
        # The node exists; rosbridge's own node may not have discovered its service yet.
        known = partial(rosbridge2.knows_services, ["/set_speed_limit"])
        wait_for("rosbridge to discover /set_speed_limit", known, TIMEOUT, rosbridge2.logs)
        scenario = start([mono, str(exe), rosbridge2.url])
        node.wait_for(lambda line: line == "done", TIMEOUT + 30)
        scenario.wait_for(lambda line: line.startswith("client_response False"), TIMEOUT)
    finally:
        node_output = node.finish()
        output = scenario.finish() if scenario else ""
    assert result.exists(), node_output
    seen = json.loads(result.read_text())
    lines = output.splitlines()
    report = f"{node_output}\n--- C#:\n{output}"

    # The generated client -> rclpy's server: both requests arrived, both answers reached
    # OnResponse on the frame loop's thread, in order.
    assert seen["requests"] == [1.25, 9.5], report
    assert _values(lines, "client_response") == ["True limit 1.25", "False above 1.5"], report
    # rclpy's client -> the generated server.
    assert seen["responses"] == [[True, "reset 1"], [True, "reset 2"]], report
    assert _values(lines, "server_request") == ["1", "2"], report
    assert _values(lines, "off_main_thread") == ["0"], report
    assert "destroyed" in output and "Unhandled Exception" not in output, report
