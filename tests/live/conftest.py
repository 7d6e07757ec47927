"""Fixtures for the discovery tests: genmsg's truth, a real ROS 1 master with a rospy node, and
a hard time limit per test so that a hung network step fails the test instead of the run."""

from __future__ import annotations

import json
import os
import shutil
import signal
import socket
import subprocess
import xmlrpc.client
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest
from helpers import SYSTEM_PYTHON, require
from processes import free_port, start, stop, wait_for

from tests.live.helpers_live import Ros1System
from unityscaffold.interfaces.live._actions import ACTION_TOPICS

DATA = Path(__file__).parent / "data"
TEST_PACKAGE = DATA / "scaffold_test_msgs"
TEST_TIME_LIMIT = 60  # seconds; every network step in these tests has its own, shorter timeout
# Types the rospy node and the fake rosbridge use; ".srv" marks services.
TYPES = [
    "std_msgs/String",
    "sensor_msgs/Imu",
    "scaffold_test_msgs/Reading",
    "rosgraph_msgs/Log",
    "geometry_msgs/Twist",
    "std_msgs/Int32",
    "move_base_msgs/MoveBaseActionGoal",  # an action's topics, recorded in a bag
    "move_base_msgs/MoveBaseActionFeedback",
    "move_base_msgs/MoveBaseActionResult",
    "actionlib_msgs/GoalID",
    "actionlib_msgs/GoalStatusArray",
    "std_srvs/Trigger.srv",
    "scaffold_test_msgs/Calibrate.srv",
]


@pytest.fixture(autouse=True)
def _time_limit() -> Iterator[None]:
    def expire(signum: int, frame: Any) -> None:
        pytest.fail(f"test took longer than {TEST_TIME_LIMIT} s")

    previous = signal.signal(signal.SIGALRM, expire)
    signal.alarm(TEST_TIME_LIMIT)
    yield
    signal.alarm(0)
    signal.signal(signal.SIGALRM, previous)


@pytest.fixture(scope="session")
def genmsg_truth(genmsg_python: Path, ros1_share: Path) -> dict[str, Any]:
    """genmsg's md5sum and full text of TYPES (services: of both halves too)."""
    output = subprocess.run(
        [str(genmsg_python), str(DATA / "genmsg_dump.py"), "--root", str(DATA), *TYPES],
        capture_output=True,
        text=True,
        timeout=60,
        check=True,
    )
    return dict(json.loads(output.stdout))


@pytest.fixture(scope="session")
def ros1_system(
    genmsg_truth: dict[str, Any], tmp_path_factory: pytest.TempPathFactory
) -> Iterator[Ros1System]:
    """rosmaster on a free loopback port, the rospy test node, and a registered publisher
    (/ghost) whose node accepts connections but never answers."""
    require(Path("/usr/bin/rosmaster").exists(), "Debian's python3-rosmaster")
    require(
        subprocess.run(
            [str(SYSTEM_PYTHON), "-c", "import rospy, genpy.dynamic, actionlib"],
            capture_output=True,
            timeout=30,
        ).returncode
        == 0,
        "Debian's python3-rospy, python3-genpy and python3-actionlib",
    )
    home = tmp_path_factory.mktemp("ros_home")
    port = free_port()
    url = f"http://127.0.0.1:{port}"
    env = {
        **os.environ,
        "ROS_MASTER_URI": url,
        "ROS_HOSTNAME": "127.0.0.1",
        "ROS_LOG_DIR": str(home / "log"),
        "ROS_HOME": str(home),
    }
    definitions = home / "definitions.json"
    definitions.write_text(json.dumps(genmsg_truth))
    processes: list[subprocess.Popen[bytes]] = []
    silent = socket.socket()  # listens, never accepts: a node that hangs
    try:
        processes.append(
            start(
                [str(SYSTEM_PYTHON), "/usr/bin/rosmaster", "--core", "-p", str(port)],
                env,
                home / "master.log",
            )
        )
        master = xmlrpc.client.ServerProxy(url)
        wait_for("rosmaster", lambda: master.getPid("/test")[0] == 1, 20, [home / "master.log"])
        processes.append(
            start(
                [str(SYSTEM_PYTHON), str(DATA / "ros1_node.py"), str(definitions)],
                env,
                home / "node.log",
            )
        )
        wait_for(
            "the rospy node",
            lambda: _node_ready(master),
            30,
            [home / "node.log", home / "master.log"],
        )
        silent.bind(("127.0.0.1", 0))
        silent.listen(8)
        ghost_api = f"http://127.0.0.1:{silent.getsockname()[1]}/"
        master.registerPublisher("/ghost_node", "/ghost", "std_msgs/Int32", ghost_api)
        yield Ros1System(url, env, genmsg_truth, "/ghost")
    finally:
        for process in reversed(processes):
            stop(process)
        silent.close()
        shutil.rmtree(home, ignore_errors=True)


def _node_ready(master: xmlrpc.client.ServerProxy) -> bool:
    publishers, subscribers, services = master.getSystemState("/test")[2]
    topics = {name for name, _ in publishers} | {name for name, _ in subscribers}
    actions = {f"/{a}/{t}" for a in ("two_ints", "served_by_unity") for t in ACTION_TOPICS}
    return {"/reading", "/imu", "/chatter", "/cmd_vel", *actions} <= topics and {
        "/trigger",
        "/calibrate",
    } <= {name for name, _ in services}
