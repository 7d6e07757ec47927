"""The sample project's generated scripts, run: in the UnityEngine stand-in's frame loop
(csharp/UnityEngineRuntime.cs) with ROS#'s real RosConnector and client, against the real
rosbridge, with a rospy node on the other side (data/script_node.py); and the same scripts
generated for ROS 2 (the sample's topics, its ROS 2 diffbot_msgs) against the real rosbridge 2.x
with an rclpy node (data/ros2/script_node.py)."""

from __future__ import annotations

import json
import shutil
import signal
from collections.abc import Callable
from pathlib import Path

from helpers import SYSTEM_PYTHON, run_cli

from tests.runtime.bridge import DATA, Bridge, free_port, wait_for
from tests.runtime.client import CSHARP, mcs_compile
from tests.runtime.lines import Lines, start
from tests.runtime.ros2 import Rosbridge2
from tests.runtime.runtime_helpers import SAMPLE_ROS2_INTERFACES

REPO = Path(__file__).resolve().parents[2]
GENERATED = REPO / "sample_project" / "unity" / "Assets" / "RosGenerated"
TIMEOUT = 60  # seconds; a guard against a hang only
RATE_TOLERANCE = 0.3  # of the 10 Hz rate, over a 4 s window on a shared machine
# The sample's topics (sample_project/robot.yaml) for ROS 2.
ROS2_MANIFEST = """\
version: 1
ros: 2
scene: Assets/Scenes/Main.unity
interfaces: [ws]
connector: {gameobject: RosConnector, url: "ws://localhost:9090", serializer: newtonsoft}
topics:
  - {name: /cmd_vel, type: geometry_msgs/msg/Twist, direction: publish, rate: 10, gameobject: Robot}
  - {name: /odom, type: nav_msgs/msg/Odometry, direction: subscribe, gameobject: Robot}
  - {name: /scan, type: sensor_msgs/msg/LaserScan, direction: subscribe, throttle: 100, queue: 1,
     gameobject: Robot/Lidar}
  - {name: /base_status, type: diffbot_msgs/msg/BaseStatus, direction: subscribe,
     gameobject: Robot}
"""


def _build(mcs: str, client: Path, package: Path, generated: Path = GENERATED) -> Path:
    folder = client.parent
    engine = folder / "UnityEngine.dll"
    mcs_compile(mcs, [CSHARP / "UnityEngineRuntime.cs"], engine)
    connector = package / "Runtime" / "RosBridgeClient" / "RosCommunication" / "RosConnector.cs"
    plumbing = [p for p in sorted(generated.rglob("*.cs")) if not p.name.endswith(".User.cs")]
    exe = folder / "Scenario.exe"
    references = [engine, client, folder / "Newtonsoft.Json.dll", folder / "websocket-sharp.dll"]
    mcs_compile(
        mcs,
        [connector, *plumbing, CSHARP / "Scenario.cs"],
        exe,
        references=references,
        target="exe",
        defines=["ROS2"] if generated != GENERATED else [],
    )
    return exe


def _subscribed_by_rosbridge(bridge: Bridge, topic: str) -> bool:
    return "/rosbridge_websocket" in bridge.system_state()[1].get(topic, set())


def test_sample_scripts_run_in_a_frame_loop(
    bridge: Bridge,
    mcs: str,
    mono: str,
    rossharp_client: Path,
    rossharp_package: Path,
    tmp_path: Path,
) -> None:
    exe = _build(mcs, rossharp_client, rossharp_package)
    result = tmp_path / "node.json"
    node = start([str(SYSTEM_PYTHON), str(DATA / "script_node.py"), str(result)], env=bridge.env)
    assert node.wait_for(lambda line: line == "ready", TIMEOUT), node.finish()
    subscribed = lambda topic: _subscribed_by_rosbridge(bridge, topic)  # noqa: E731
    _run_and_check(mono, exe, bridge.url, node, result, subscribed, from_first=True)


def test_the_sample_scripts_for_ros2_run_in_a_frame_loop(
    rosbridge2: Rosbridge2,
    mcs: str,
    mono: str,
    rossharp_ros2_client: Path,
    rossharp_package: Path,
    tmp_path: Path,
) -> None:
    project = tmp_path / "ros2"
    assert run_cli("init", str(project), "--ros", "2").code == 0
    shutil.copytree(SAMPLE_ROS2_INTERFACES, project / "ws")
    (project / "robot.yaml").write_text(ROS2_MANIFEST, encoding="utf-8")
    done = run_cli("apply", str(project / "robot.yaml"))
    assert done.code == 0, done.err
    generated = project / "Assets" / "RosGenerated"
    exe = _build(mcs, rossharp_ros2_client, rossharp_package, generated)
    result = tmp_path / "node.json"
    node = start(
        [str(rosbridge2.ros2.python), str(DATA / "ros2" / "script_node.py"), str(result)],
        env=rosbridge2.ros2.env,
    )
    assert node.wait_for(lambda line: line == "ready", TIMEOUT), node.finish()

    def subscribed(topic: str) -> bool:
        answer = rosbridge2.call("/rosapi/subscribers", {"topic": topic})
        return "/rosbridge_websocket" in answer["values"]["subscribers"]

    wait_for("rosbridge to see the node", lambda: _published(rosbridge2), 30, rosbridge2.logs)
    # DDS matches rosbridge's new publisher with the node's subscription in its own time and
    # drops what was published before (volatile QoS): the node may miss the first messages.
    _run_and_check(mono, exe, rosbridge2.url, node, result, subscribed, from_first=False)


def _published(bridge: Rosbridge2) -> bool:
    topics = set(bridge.call("/rosapi/topics")["values"]["topics"])
    return {"/odom", "/scan", "/base_status"} <= topics


def _run_and_check(
    mono: str,
    exe: Path,
    url: str,
    node: Lines,
    result: Path,
    subscribed: Callable[[str], bool],
    *,
    from_first: bool,
) -> None:
    """The scenario against ``node``; ``from_first``: whether the node must have received the
    publisher's first message (else any unbroken run of them)."""
    unreachable = f"ws://127.0.0.1:{free_port()}"
    scenario = start([mono, str(exe), url, unreachable])
    try:
        if scenario.wait_for(lambda line: line.startswith("waiting "), TIMEOUT):
            # OnDestroy unsubscribed: rosbridge dropped its /odom subscriber, kept the others.
            wait_for("rosbridge to drop /odom", lambda: not subscribed("/odom"), 5, [])
            assert subscribed("/base_status")
            assert scenario.process.stdin
            scenario.process.stdin.write("\n")
            scenario.process.stdin.flush()
            scenario.wait_for(lambda line: line.startswith("done "), TIMEOUT)
    finally:
        # Every wait is bounded: a scenario or node that hangs is killed and its output reported.
        output = scenario.finish()
        node_output = node.finish()
    lines = output.splitlines()
    report: dict[str, str] = {}
    for line in lines:
        key, _, value = line.partition(" ")
        report.setdefault(key, value)
    # The scenario's last step is ROS#'s RosSocket.Close, which can hang on a socket rosbridge
    # has already broken (it is not ours): a scenario killed after reporting "done" passes.
    code = scenario.process.returncode
    ended = code == 0 or (code == -signal.SIGKILL and "done" in report)
    assert ended and result.exists(), f"{output}\n--- node:\n{node_output}"
    cmd_vel = json.loads(result.read_text())["cmd_vel"]

    # The scripts were started before the connection was up, waited, then worked.
    assert int(report["connected_frame"]) > 0, output
    # The publisher published at Rate (10 Hz), calling UpdateMessage before each publish.
    # (It goes on publishing while the scenario goes on; the rate is measured over the first 4 s.)
    values = [x for _, x in cmd_vel]
    lowest = 1 if from_first or not values else int(values[0])
    assert values and values == [float(i) for i in range(lowest, lowest + len(values))], values
    first = [t for t, x in cmd_vel if x <= int(report["updates"])]
    rate = (len(first) - 1) / (first[-1] - first[0])
    assert abs(rate - 10) <= 10 * RATE_TOLERANCE, (len(first), rate)
    # Subscribers: OnMessage on the frame loop's thread, in arrival order.
    assert report["off_main_thread"] == "0"
    order = [int(tick) for tick in report["base_status"].split(",")]
    assert len(order) > 10 and order == sorted(set(order))
    assert int(report["odom"]) > 10
    # /scan comes at 50 Hz; Throttle 100 ms lets rosbridge send at most 10 a second, and never
    # more than Queue (1) reached OnMessage in one frame.
    assert (report["throttle"], report["queue"]) == ("100", "1")
    assert 0 < int(report["scan"]) <= 4 * 10 + 2
    assert report["scan_most_in_one_frame"] == "1"
    # A connector that never connects: the documented warning, once, after SecondsTimeout.
    warning = (
        f"[warning] BaseStatusSubscriber: no connection to {unreachable} within 1 s; "
        "subscription to /base_status is not set up. "
        "Is rosbridge running at that address and port?"
    )
    assert lines.count(warning) == 1, output
    # Nothing was thrown on the frame loop's thread: it ran to the end (an exception from a
    # script would have ended the program). websocket-sharp logs its refused connection itself,
    # on the connector's thread.
    assert "done" in report and "Unhandled Exception" not in output
