"""The rospy side of the actionlib test; runs under Debian's /usr/bin/python3 with its
python3-actionlib. Action: diffbot_msgs/Dock (the sample's).

Server (rospy's SimpleActionServer on PY_ACTION): a goal whose dock_id is "cancel-me" sends
one feedback (9.5 m) and runs until a cancel arrives, then ends PREEMPTED (docked false,
battery -1); any other goal sends two feedbacks (2.5 m, 1.25 m) and ends SUCCEEDED (docked
true, battery 87.5, text "docked at <dock_id>").
Client (rospy's SimpleActionClient on CS_ACTION): goal "from-rospy" to its end, then goal
"cancel-me", cancelled once its first feedback has arrived and the server's status shows it
active.
Prints "ready" once the server runs and "done" once both sides are through (or the timeout
passed); writes what both sides saw as JSON when its stdin closes (the C# side may still be
reading the last result then).
Usage: action_node.py PY_ACTION CS_ACTION RESULT.json TIMEOUT
"""

import json
import sys
import threading
import time

import actionlib
import rospy
from diffbot_msgs.msg import DockAction, DockActionFeedback, DockFeedback, DockGoal, DockResult


def until(condition, deadline):
    """Wait for ``condition``; False at the deadline (a guard against a hang, not a check)."""
    while not condition():
        if time.monotonic() > deadline or rospy.is_shutdown():
            return False
        time.sleep(0.02)
    return True


def status_of(status):
    return {"goal_id": status.goal_id.id, "stamp": status.goal_id.stamp.to_sec()}


def serve(name, deadline, seen):
    def execute(goal):
        handle = server.current_goal
        entry = {
            "dock_id": goal.dock_id,
            "goal_id": handle.get_goal_id().id,
            "stamp_nonzero": not handle.get_goal_id().stamp.is_zero(),
        }
        seen["server"].append(entry)
        # rosbridge subscribes to feedback and result for the C# client, and connects to these
        # publishers in the background: what is published before that is lost.
        publishers = (server.action_server.feedback_pub, server.action_server.result_pub)
        until(lambda: all(p.get_num_connections() for p in publishers), deadline)
        if goal.dock_id == "cancel-me":
            server.publish_feedback(DockFeedback(distance_remaining=9.5))
            entry["preempt_seen"] = until(server.is_preempt_requested, deadline)
            server.set_preempted(DockResult(docked=False, battery=-1.0), "preempted")
            return
        for distance in (2.5, 1.25):
            server.publish_feedback(DockFeedback(distance_remaining=distance))
        server.set_succeeded(DockResult(docked=True, battery=87.5), f"docked at {goal.dock_id}")

    server = actionlib.SimpleActionServer(name, DockAction, execute, auto_start=False)
    server.start()
    return server


def call(name, deadline, seen):
    client = actionlib.SimpleActionClient(name, DockAction)
    # Feedback as it arrives on the topic: the client's own callback drops a feedback that
    # arrives after the result (the two come on separate connections, in no set order).
    arrived = []

    def on_topic(message):
        status = message.status
        arrived.append([status.goal_id.id, status.status, message.feedback.distance_remaining])

    topic = rospy.Subscriber(f"{name}/feedback", DockActionFeedback, on_topic)
    found = client.wait_for_server(rospy.Duration(deadline - time.monotonic()))
    found = found and until(lambda: topic.get_num_connections() > 0, deadline)
    seen["client"] = {"server_found": found}
    if not found:
        return
    ids = {}
    for dock_id in ("from-rospy", "cancel-me"):
        first, active = threading.Event(), threading.Event()
        client.send_goal(
            DockGoal(dock_id=dock_id),
            active_cb=active.set,
            feedback_cb=lambda _, first=first: first.set(),
        )
        ids[client.gh.comm_state_machine.action_goal.goal_id.id] = dock_id
        if dock_id == "cancel-me":
            # Cancel once the server's status lists the goal, not at the first feedback alone:
            # status and feedback come on separate connections, and a status published before
            # the goal arrived, read after a cancel, makes actionlib's client mark the goal LOST.
            first.wait(max(deadline - time.monotonic(), 0.1))
            active.wait(max(deadline - time.monotonic(), 0.1))
            client.cancel_goal()
        finished = client.wait_for_result(rospy.Duration(max(deadline - time.monotonic(), 0.1)))
        result = client.get_result()
        seen["client"][dock_id] = {
            "finished": finished,
            "state": client.get_state(),
            "text": client.get_goal_status_text(),
            "result": None if result is None else [result.docked, result.battery],
        }

    def grouped():
        by_goal = {}
        for goal, *rest in arrived:
            by_goal.setdefault(ids.get(goal, goal), []).append(rest)
        return by_goal

    return grouped


def main(py_action, cs_action, result_path, timeout):
    rospy.init_node("action_test", disable_signals=True)
    deadline = time.monotonic() + float(timeout)
    seen = {"server": [], "client": {}}
    server = serve(py_action, deadline, seen)
    print("ready", flush=True)
    feedback = call(cs_action, deadline, seen)
    # The C# client's two goals: the second one ends when it is cancelled.
    until(lambda: len(seen["server"]) == 2 and not server.is_active(), deadline)
    print("done", flush=True)
    sys.stdin.read()
    if feedback:
        seen["client"]["feedback"] = feedback()
    with open(result_path, "w") as handle:
        json.dump(seen, handle, indent=1, sort_keys=True)
    rospy.signal_shutdown("done")


if __name__ == "__main__":
    main(*sys.argv[1:])
