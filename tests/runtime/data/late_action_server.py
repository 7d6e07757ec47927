"""An actionlib server of diffbot_msgs/Dock that subscribes to its goals late, for the ROS 1
client's re-sent goals; runs under Debian's /usr/bin/python3 like action_node.py.

Once rosbridge's publisher of NAME/goal is registered (the client advertised it), it waits
past the first second in which rosbridge 0.11 replays to late subscribers, then publishes its
status (5 times a second, as actionlib's servers do); the client then publishes its goal, to no
subscriber: that publication is lost. Only later does it subscribe to NAME/goal, so it gets
the goal only if the client publishes it again. A goal is listed SUCCEEDED at once and its
result (docked true, battery 50) published; a goal id it already lists is ignored, as
actionlib's servers do. Prints "ready" once running and "done" once a goal came (or the
timeout passed); writes every goal id received, in order, as JSON when its stdin closes.
Usage: late_action_server.py NAME RESULT.json TIMEOUT
"""

import json
import sys
import threading
import time

import rosgraph
import rospy
from actionlib_msgs.msg import GoalStatus, GoalStatusArray
from diffbot_msgs.msg import DockActionGoal, DockActionResult, DockResult

# rosbridge 0.11 replays what a new publisher published to subscribers that connect within
# this many seconds of its creation (PublisherConsistencyListener); waited past, with a margin.
REPLAYED = 1.0
MARGIN = 1.0


def until(condition, deadline):
    """Wait for ``condition``; False at the deadline (a guard against a hang, not a check)."""
    while not condition():
        if time.monotonic() > deadline or rospy.is_shutdown():
            return False
        time.sleep(0.02)
    return True


def main(name, result_path, timeout):
    rospy.init_node("late_action_server", disable_signals=True)
    deadline = time.monotonic() + float(timeout)
    master = rosgraph.Master(rospy.get_name())

    def advertised():
        return any(topic == f"{name}/goal" for topic, _ in master.getSystemState()[0])

    print("ready", flush=True)
    until(advertised, deadline)
    time.sleep(REPLAYED + MARGIN)
    lock = threading.Lock()
    listed = []
    received = []
    status = rospy.Publisher(f"{name}/status", GoalStatusArray, queue_size=10)
    result = rospy.Publisher(f"{name}/result", DockActionResult, queue_size=10)

    def publish_status(_):
        with lock:
            status.publish(GoalStatusArray(status_list=list(listed)))

    timer = rospy.Timer(rospy.Duration(0.2), publish_status)
    # The client publishes its goal at the first status it reads: to no subscriber yet.
    time.sleep(REPLAYED + MARGIN)

    def on_goal(message):
        with lock:
            received.append(message.goal_id.id)
            if any(s.goal_id.id == message.goal_id.id for s in listed):
                return
            done = GoalStatus(goal_id=message.goal_id, status=GoalStatus.SUCCEEDED)
            listed.append(done)
        until(lambda: result.get_num_connections() > 0, deadline)
        result.publish(DockActionResult(status=done, result=DockResult(docked=True, battery=50.0)))

    rospy.Subscriber(f"{name}/goal", DockActionGoal, on_goal)
    until(lambda: received, deadline)
    print("done", flush=True)
    sys.stdin.read()
    timer.shutdown()
    with open(result_path, "w") as handle:
        json.dump({"received": received}, handle)
    rospy.signal_shutdown("done")


if __name__ == "__main__":
    main(*sys.argv[1:])
