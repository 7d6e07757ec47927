"""Fixtures for the runtime tests: one real rosbridge (ROS 1) per session, ROS#'s real client
compiled once per session, and the sample's interface package as Python modules for rospy."""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path

import pytest
from helpers import SYSTEM_PYTHON, require
from processes import run

from tests.runtime.bridge import Bridge, start_bridge, vendor_folder
from tests.runtime.client import build_client, build_ros2_client
from tests.runtime.ros2 import Ros2, Rosbridge2, open_ros2, start_rosbridge2
from tests.runtime.runtime_helpers import (
    SAMPLE_INTERFACES,
    TIME_PRIMITIVES,
    build_ours_only_client,
    message_types,
    python_package_of,
    ros1_registry,
    service_types,
)


@pytest.fixture(scope="session")
def rosbridge_sources() -> Path:
    folder = vendor_folder("UNITYSCAFFOLD_ROSBRIDGE", "rosbridge_suite-ros1")
    require(folder, "rosbridge_suite's ROS 1 sources (UNITYSCAFFOLD_ROSBRIDGE)")
    assert folder
    return folder


@pytest.fixture(scope="session")
def rossharp_package() -> Path:
    folder = vendor_folder("UNITYSCAFFOLD_ROSSHARP", "ros-sharp/2.2.1/com.siemens.ros-sharp")
    require(folder, "ROS# 2.2.1's com.siemens.ros-sharp folder (UNITYSCAFFOLD_ROSSHARP)")
    assert folder
    return folder


@pytest.fixture(scope="session")
def actionlib_python() -> None:
    """rospy's actionlib under the system Python, for the ROS 1 action tests' rospy side."""
    works = run([str(SYSTEM_PYTHON), "-c", "import actionlib"], timeout=60)
    require(works.returncode == 0, "rospy's actionlib (Debian package python3-actionlib)")


@pytest.fixture(scope="session")
def sample_python(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """The sample's diffbot_msgs as genpy modules (messages, action messages, service)."""
    require(Path("/usr/lib/genpy/genmsg_py.py").exists(), "Debian's python3-genpy")
    out = tmp_path_factory.mktemp("sample_python")
    python_package_of(SAMPLE_INTERFACES, "diffbot_msgs", out)
    return out


@pytest.fixture(scope="session")
def bridge(
    rosbridge_sources: Path, sample_python: Path, tmp_path_factory: pytest.TempPathFactory
) -> Iterator[Bridge]:
    """rosmaster, rosbridge_websocket and rosapi_node on free loopback ports for the session."""
    require(Path("/usr/bin/rosmaster").exists(), "Debian's python3-rosmaster")
    modules = "import rospy, tornado, twisted, autobahn, bson, PIL, rosnode, rosparam, rosservice"
    require(
        run([str(SYSTEM_PYTHON), "-c", modules], timeout=60).returncode == 0,
        "rosbridge's Debian dependencies (see .ci/run)",
    )
    home = tmp_path_factory.mktemp("rosbridge")
    running = start_bridge(
        rosbridge_sources, home, extra_python_path=[sample_python], packages=[SAMPLE_INTERFACES]
    )
    try:
        yield running
    finally:
        running.close()


@pytest.fixture(scope="session")
def rossharp_client(
    mcs: str, mono: str, rossharp_package: Path, tmp_path_factory: pytest.TempPathFactory
) -> Path:
    """ROS#'s RosBridgeClient.dll with its shipped ROS 1 message classes, Plugins beside it."""
    return build_client(mcs, rossharp_package, tmp_path_factory.mktemp("rossharp_client"))


@pytest.fixture(scope="session")
def rossharp_ros2_client(
    mcs: str, mono: str, rossharp_package: Path, tmp_path_factory: pytest.TempPathFactory
) -> Path:
    """ROS#'s RosBridgeClient.dll built for ROS 2 (``-define:ROS2``), Plugins beside it."""
    return build_ros2_client(mcs, rossharp_package, tmp_path_factory.mktemp("rossharp_ros2"))


@pytest.fixture(scope="session")
def ours_only_client(
    mcs: str, mono: str, rossharp_package: Path, tmp_path_factory: pytest.TempPathFactory
) -> Path:
    """ROS#'s client without its message classes, ours (--include-shipped) for every ROS 1
    message type and both halves of every service instead (std_msgs/Time and Duration aside:
    ROS# maps them to its primitives)."""
    registry = ros1_registry()
    roots = [s for s in message_types(registry) if s.full_name not in TIME_PRIMITIVES]
    out = tmp_path_factory.mktemp("ours_only_client")
    return build_ours_only_client(
        mcs, rossharp_package, registry, [*roots, *service_types(registry)], out
    )


@pytest.fixture(scope="session")
def ros2(tmp_path_factory: pytest.TempPathFactory) -> Iterator[Ros2]:
    """ROS 2 Jazzy (scripts/ros2_stack.py, built if this machine has none) in a ROS domain of
    this session's own, on loopback."""
    stack = open_ros2(tmp_path_factory.mktemp("ros2"))
    try:
        yield stack
    finally:
        stack.close()


@pytest.fixture()
def rosbridge2(ros2: Ros2) -> Iterator[Rosbridge2]:
    """rosbridge 2.x's websocket server and rosapi in the session's domain, with their defaults,
    for one test: a bridge shared by the session was seen to stop accepting clients after a test's
    client left with a subscription open (its log then says "Tried to write to a closed
    websocket" every second; rosbridge_suite#744, #947), failing every later test on it."""
    running = start_rosbridge2(ros2)
    try:
        yield running
    finally:
        running.close()
