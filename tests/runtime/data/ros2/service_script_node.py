"""The rclpy side of the ROS 2 service script test; runs in the ROS 2 stack's venv.

Serves /set_speed_limit (diffbot_msgs/srv/SetSpeedLimit): a limit up to BaseStatus.MAX_SPEED is
taken ("limit <value>"), a higher one refused ("above <MAX_SPEED>"). Once /reset_cs
(std_srvs/srv/Trigger) is served, calls it twice. Prints "ready" once its service exists and
"done" once both calls are answered (or the timeout passed); writes what it saw as JSON when
its stdin closes.
Usage: service_script_node.py RESULT.json TIMEOUT
"""

import json
import sys
import threading
import time

import rclpy
from diffbot_msgs.msg import BaseStatus
from diffbot_msgs.srv import SetSpeedLimit
from rclpy.executors import SingleThreadedExecutor
from std_srvs.srv import Trigger


def main(result_path, timeout):
    deadline = time.monotonic() + float(timeout)
    seen = {"requests": [], "responses": []}
    rclpy.init()
    node = rclpy.create_node("service_script_test")

    def limit(request, response):
        seen["requests"].append(request.max_linear)
        response.success = request.max_linear <= BaseStatus.MAX_SPEED
        response.message = (
            f"limit {request.max_linear}" if response.success else f"above {BaseStatus.MAX_SPEED}"
        )
        return response

    node.create_service(SetSpeedLimit, "/set_speed_limit", limit)
    client = node.create_client(Trigger, "/reset_cs")
    executor = SingleThreadedExecutor()
    executor.add_node(node)
    threading.Thread(target=executor.spin, daemon=True).start()
    print("ready", flush=True)
    if client.wait_for_service(timeout_sec=max(deadline - time.monotonic(), 0.1)):
        for _ in range(2):
            future = client.call_async(Trigger.Request())
            while not future.done() and time.monotonic() < deadline:
                time.sleep(0.02)
            if future.done():
                answer = future.result()
                seen["responses"].append([answer.success, answer.message])
    print("done", flush=True)
    sys.stdin.read()
    with open(result_path, "w") as handle:
        json.dump(seen, handle)
    executor.shutdown()
    rclpy.shutdown()


if __name__ == "__main__":
    main(*sys.argv[1:])
