"""The action both ROS 2 action tests use: the sample's diffbot_msgs/action/Dock as the rosbridge
double sees it, and what the double's Dock server does (as data/action_node.py's for ROS 1)."""

from __future__ import annotations

import threading
from typing import Any

from tests.runtime.rosbridge2_double import (
    STATUS_CANCELED,
    STATUS_SUCCEEDED,
    ActionType,
    Refused,
)

TIMEOUT = 60  # seconds; a guard against a hang only
DOCK = ActionType(
    "diffbot_msgs/action/Dock",
    goal={"dock_id": "string"},
    result={"docked": "bool", "battery": "float32"},
    feedback={"distance_remaining": "float32"},
)


def dock(args: dict[str, Any], feedback: Any, cancelled: threading.Event) -> Any:
    """The double's Dock server: "reject-me" is refused; "cancel-me" sends one feedback (9.5 m)
    and runs until cancelled (docked false, battery -1); any other goal sends two feedbacks
    (2.5 m, 1.25 m) and succeeds (docked, battery 87.5)."""
    if args.get("dock_id") == "reject-me":
        raise Refused("Goal was rejected")
    if args.get("dock_id") == "cancel-me":
        feedback({"distance_remaining": 9.5})
        cancelled.wait(TIMEOUT)
        return STATUS_CANCELED, {"docked": False, "battery": -1.0}
    feedback({"distance_remaining": 2.5})
    feedback({"distance_remaining": 1.25})
    return STATUS_SUCCEEDED, {"docked": True, "battery": 87.5}
