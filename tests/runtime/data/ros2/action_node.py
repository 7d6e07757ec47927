"""The rclpy side of the ROS 2 action tests; runs in the ROS 2 stack's venv. Action: the sample's
diffbot_msgs/action/Dock (built for ROS 2).

Server (rclpy's ActionServer on PY_ACTION): refuses a goal whose dock_id is "reject-me"; for
"cancel-me" sends one feedback (9.5 m) and runs until a cancel arrives, then ends CANCELED
(docked false, battery -1); any other goal sends two feedbacks (2.5 m, 1.25 m) and ends
SUCCEEDED (docked true, battery 87.5).
Client (rclpy's ActionClient on CS_ACTION): goal "from-rclpy" to its end, then goal
"cancel-me", cancelled once its first feedback has arrived.
Prints "ready" once the server runs and "done" once both sides are through (or the timeout
passed); writes what both sides saw as JSON when its stdin closes.
Usage: action_node.py PY_ACTION CS_ACTION RESULT.json TIMEOUT
"""

import json
import sys
import threading
import time

import rclpy
from action_msgs.msg import GoalStatus
from diffbot_msgs.action import Dock
from rclpy.action import ActionClient, ActionServer, CancelResponse, GoalResponse
from rclpy.callback_groups import ReentrantCallbackGroup
from rclpy.executors import MultiThreadedExecutor


def until(condition, deadline):
    """Wait for ``condition``; False at the deadline (a guard against a hang, not a check)."""
    while not condition():
        if time.monotonic() > deadline:
            return False
        time.sleep(0.02)
    return True


def serve(node, name, deadline, seen):
    def decide(goal):
        accepted = goal.dock_id != "reject-me"
        seen["server_decided"].append([goal.dock_id, accepted])
        return GoalResponse.ACCEPT if accepted else GoalResponse.REJECT

    def cancel(handle):
        seen["server_cancel"].append(handle.request.dock_id)
        return CancelResponse.ACCEPT

    def execute(handle):
        dock_id = handle.request.dock_id
        seen["server"].append(dock_id)
        if dock_id == "cancel-me":
            handle.publish_feedback(Dock.Feedback(distance_remaining=9.5))
            until(lambda: handle.is_cancel_requested, deadline)
            handle.canceled()
            return Dock.Result(docked=False, battery=-1.0)
        for distance in (2.5, 1.25):
            handle.publish_feedback(Dock.Feedback(distance_remaining=distance))
        handle.succeed()
        return Dock.Result(docked=True, battery=87.5)

    return ActionServer(
        node,
        Dock,
        name,
        execute_callback=execute,
        goal_callback=decide,
        cancel_callback=cancel,
        callback_group=ReentrantCallbackGroup(),
    )


def wait(future, deadline):
    until(future.done, deadline)
    return future.result() if future.done() else None


def run_client(node, name, deadline, seen):
    client = ActionClient(node, Dock, name, callback_group=ReentrantCallbackGroup())
    seen["client"]["server_found"] = client.wait_for_server(timeout_sec=deadline - time.monotonic())
    for dock_id in ("from-rclpy", "cancel-me"):
        feedback = seen["client"]["feedback"].setdefault(dock_id, [])
        handle = wait(
            client.send_goal_async(
                Dock.Goal(dock_id=dock_id),
                feedback_callback=lambda m, f=feedback: f.append(m.feedback.distance_remaining),
            ),
            deadline,
        )
        if handle is None or not handle.accepted:
            seen["client"][dock_id] = {"accepted": False}
            continue
        if dock_id == "cancel-me":
            until(lambda f=feedback: f, deadline)
            cancelled = wait(handle.cancel_goal_async(), deadline)
            seen["client"]["cancel_accepted"] = bool(cancelled and cancelled.goals_canceling)
        answer = wait(handle.get_result_async(), deadline)
        seen["client"][dock_id] = {
            "accepted": True,
            "status": answer.status if answer else None,
            "result": [answer.result.docked, answer.result.battery] if answer else None,
        }


def wait_for_bridge(node, deadline):
    """Until this node's participant sees rosbridge's node. rosbridge 2.x gives a new action
    client one second to find its server (SendGoal's server_timeout_time) and then sends the goal
    anyway; on a loaded machine DDS discovery of this process can take longer, and the goal is
    lost without an answer. Once the two processes know each other, the action's own endpoints
    match well within that second."""
    while "rosbridge_websocket" not in node.get_node_names():
        if time.monotonic() > deadline:
            raise SystemExit("rosbridge_websocket never appeared in the ROS 2 graph")
        time.sleep(0.05)


def main(py_action, cs_action, result_path, timeout):
    deadline = time.monotonic() + float(timeout)
    seen = {
        "server": [],
        "server_decided": [],
        "server_cancel": [],
        "client": {"feedback": {}},
        "canceled_status": GoalStatus.STATUS_CANCELED,
    }
    rclpy.init()
    node = rclpy.create_node("dock_node")
    serve(node, py_action, deadline, seen)
    executor = MultiThreadedExecutor(num_threads=4)
    executor.add_node(node)
    threading.Thread(target=executor.spin, daemon=True).start()
    wait_for_bridge(node, deadline)
    print("ready", flush=True)
    run_client(node, cs_action, deadline, seen)
    print("done", flush=True)
    sys.stdin.read()
    with open(result_path, "w") as handle:
        json.dump(seen, handle, indent=1, sort_keys=True)
    executor.shutdown()
    rclpy.shutdown()


if __name__ == "__main__":
    main(*sys.argv[1:])
