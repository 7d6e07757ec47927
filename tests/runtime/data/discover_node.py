"""The rospy side of discovery through the real rosbridge; runs under Debian's /usr/bin/python3.

Publishes /chatter (std_msgs/String), /odom (nav_msgs/Odometry), /base_status (the
sample's diffbot_msgs/BaseStatus: constants, a fixed array of a custom type) and
/undock/feedback (the sample's action message diffbot_msgs/DockActionFeedback, alone: a topic,
not an action); subscribes to /cmd_vel (geometry_msgs/Twist); serves /trigger (std_srvs/Trigger)
and /set_speed_limit (the sample's diffbot_msgs/SetSpeedLimit). With actionlib (Debian's
python3-actionlib), serves the sample's diffbot_msgs/Dock action on /dock and is a client, with
no server, of the same action on /charger/dock.
Once the master lists all of them, prints one JSON line: genpy's md5sum and full text of each
message type (the truth discovery must reproduce); then runs until its stdin closes.
Usage: discover_node.py
"""

import json
import sys
import time

import actionlib
import rosgraph
import rospy
from actionlib_msgs.msg import GoalID, GoalStatusArray
from diffbot_msgs.msg import (
    BaseStatus,
    DockAction,
    DockActionFeedback,
    DockActionGoal,
    DockActionResult,
    DockResult,
)
from diffbot_msgs.srv import SetSpeedLimit, SetSpeedLimitResponse
from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry
from std_msgs.msg import String
from std_srvs.srv import Trigger, TriggerResponse

PUBLISHED = {
    "/chatter": String,
    "/odom": Odometry,
    "/base_status": BaseStatus,
    "/undock/feedback": DockActionFeedback,
}
ACTIONS = {"/dock": "server", "/charger/dock": "client"}  # the node's side of each
ACTION_MESSAGES = [DockActionGoal, GoalID, GoalStatusArray, DockActionFeedback, DockActionResult]
SUBSCRIBED = {"/cmd_vel": Twist}
SERVED = {"/trigger": Trigger, "/set_speed_limit": SetSpeedLimit}


def main():
    rospy.init_node("discover_test", disable_signals=True)
    keep = [rospy.Publisher(name, cls, queue_size=1) for name, cls in PUBLISHED.items()]
    keep += [rospy.Subscriber(name, cls, lambda _: None) for name, cls in SUBSCRIBED.items()]
    keep.append(rospy.Service("/trigger", Trigger, lambda _: TriggerResponse(True, "ok")))
    keep.append(rospy.Service("/set_speed_limit", SetSpeedLimit, lambda _: SetSpeedLimitResponse()))
    server = actionlib.SimpleActionServer(
        "/dock", DockAction, lambda _: server.set_succeeded(DockResult(True, 100.0)), False
    )
    server.start()
    keep.append(actionlib.SimpleActionClient("/charger/dock", DockAction))
    parts = ("goal", "cancel", "status", "feedback", "result")
    action_topics = {f"{a}/{t}" for a in ACTIONS for t in parts}
    master = rosgraph.Master(rospy.get_name())
    me = rospy.get_name()
    deadline = time.monotonic() + 30
    while time.monotonic() < deadline:  # rospy registers from a background thread
        state = master.getSystemState()
        mine = [{name for name, nodes in part if me in nodes} for part in state]
        registered = (
            set(PUBLISHED) <= mine[0]
            and set(SUBSCRIBED) <= mine[1]
            and set(SERVED) <= mine[2]
            and action_topics <= mine[0] | mine[1]
        )
        if registered:
            break
        time.sleep(0.05)
    truth = {
        cls._type: {"md5sum": cls._md5sum, "definition": cls._full_text}
        for cls in [*PUBLISHED.values(), *SUBSCRIBED.values(), *ACTION_MESSAGES]
    }
    truth.update({cls._type: {"md5sum": cls._md5sum} for cls in SERVED.values()})
    print(json.dumps(truth), flush=True)
    sys.stdin.read()
    rospy.signal_shutdown("done")


if __name__ == "__main__":
    main()
