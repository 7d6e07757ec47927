"""The real ROS 2 the runtime tests run on (scripts/ros2_stack.py, tests/runtime/ros2.py): an
rclpy node's topic and service reach a plain JSON websocket client through rosbridge 2.x, and
rosapi lists them with their ROS 2 types."""

from __future__ import annotations

import contextlib
import json
import time
from collections.abc import Callable
from pathlib import Path
from typing import Any

from processes import wait_for
from websockets.sync.client import ClientConnection, connect

from tests.runtime.ros2 import Ros2, Rosbridge2

DATA = Path(__file__).parent / "data" / "ros2"
TIMEOUT = 60  # a guard against a hang only


def _listed(bridge: Rosbridge2) -> bool:
    services = bridge.call("/rosapi/services")["values"]["services"]
    topics = bridge.call("/rosapi/topics")["values"]["topics"]
    # rosapi is a node of its own: rosbridge's may not have discovered the service yet.
    listed = "/stack/set" in services and "/stack/chatter" in topics
    return listed and bridge.knows_services(["/stack/set"])


def _receive(
    socket: ClientConnection, wanted: Callable[[dict[str, Any]], bool]
) -> dict[str, Any] | None:
    """The first message from rosbridge for which ``wanted`` holds, or None when TIMEOUT passed
    first (the talker publishes on and on: a bound on each receive alone would never end)."""
    deadline = time.monotonic() + TIMEOUT
    with contextlib.suppress(TimeoutError):
        while (left := deadline - time.monotonic()) > 0:
            message: dict[str, Any] = json.loads(socket.recv(timeout=left))
            if wanted(message):
                return message
    return None


def test_an_rclpy_topic_and_service_reach_a_websocket_client_through_rosbridge_2(
    ros2: Ros2, rosbridge2: Rosbridge2
) -> None:
    node = ros2.run_node(DATA / "talker_node.py", "/stack/chatter", "/stack/set")
    try:
        assert node.wait_for(lambda line: line == "ready", TIMEOUT), node.finish()
        # The node exists; rosbridge's own node may not have discovered it yet.
        wait_for("the talker in rosapi", lambda: _listed(rosbridge2), TIMEOUT, rosbridge2.logs)
        with connect(rosbridge2.url, open_timeout=10) as socket:
            socket.send(
                json.dumps(
                    {"op": "subscribe", "topic": "/stack/chatter", "type": "std_msgs/msg/String"}
                )
            )
            message = _receive(socket, lambda _: True)
            socket.send(
                json.dumps(
                    {
                        "op": "call_service",
                        "service": "/stack/set",
                        "args": {"data": True},
                        "id": "c1",
                    }
                )
            )
            answer = _receive(socket, lambda m: m["op"] != "publish")
        topics = rosbridge2.call("/rosapi/topics")["values"]
        service_type = rosbridge2.call("/rosapi/service_type", {"service": "/stack/set"})
    finally:
        output = node.finish()
    assert message, f"nothing from rosbridge within {TIMEOUT} s\n{output}"
    assert message["op"] == "publish" and message["topic"] == "/stack/chatter", message
    assert message["msg"]["data"].startswith("hello "), message
    assert answer == {
        "op": "service_response",
        "service": "/stack/set",
        "values": {"success": True, "message": "set True"},
        "result": True,
        "id": "c1",
    }, output
    types = dict(zip(topics["topics"], topics["types"], strict=True))
    assert types["/stack/chatter"] == "std_msgs/msg/String"
    assert service_type["values"] == {"type": "std_srvs/srv/SetBool"}
