"""A small ROS 2 robot for discover's tests; runs in the ROS 2 stack's venv.

Publishes /odom (nav_msgs/msg/Odometry) and /base_status (the sample's diffbot_msgs/msg/
BaseStatus), subscribes to /cmd_vel (geometry_msgs/msg/Twist), serves /trigger (std_srvs/srv/
Trigger) and /set_speed_limit (diffbot_msgs/srv/SetSpeedLimit) and only calls /hmi/confirm
(std_srvs/srv/Trigger), serves the action /dock (diffbot_msgs/action/Dock) and is only a client
of /charger/dock. Prints what it offers as one JSON line ({"topics": {name: [type, "publishes" |
"subscribes"]}, "services" and "actions": {name: [type, "server" | "client"]}}), then "ready";
runs until stdin closes.
"""

import json
import sys
import threading

import rclpy
from diffbot_msgs.action import Dock
from diffbot_msgs.msg import BaseStatus
from diffbot_msgs.srv import SetSpeedLimit
from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry
from rclpy.action import ActionClient, ActionServer
from rclpy.executors import SingleThreadedExecutor
from std_srvs.srv import Trigger


def main():
    rclpy.init()
    node = rclpy.create_node("robot")
    offers = {"topics": {}, "services": {}, "actions": {}}
    for name, cls in (("/odom", Odometry), ("/base_status", BaseStatus)):
        node.create_publisher(cls, name, 10)
        offers["topics"][name] = [_type(cls, "msg"), "publishes"]
    node.create_subscription(Twist, "/cmd_vel", lambda message: None, 10)
    offers["topics"]["/cmd_vel"] = [_type(Twist, "msg"), "subscribes"]
    for name, cls in (("/trigger", Trigger), ("/set_speed_limit", SetSpeedLimit)):
        node.create_service(cls, name, lambda request, response: response)
        offers["services"][name] = [_type(cls, "srv"), "server"]
    node.create_client(Trigger, "/hmi/confirm")
    offers["services"]["/hmi/confirm"] = [_type(Trigger, "srv"), "client"]
    ActionServer(node, Dock, "/dock", lambda goal: Dock.Result())
    offers["actions"]["/dock"] = [_type(Dock, "action"), "server"]
    ActionClient(node, Dock, "/charger/dock")
    offers["actions"]["/charger/dock"] = [_type(Dock, "action"), "client"]
    executor = SingleThreadedExecutor()
    executor.add_node(node)
    threading.Thread(target=executor.spin, daemon=True).start()
    print(json.dumps(offers), flush=True)
    print("ready", flush=True)
    sys.stdin.read()
    executor.shutdown()
    node.destroy_node()
    rclpy.try_shutdown()


def _type(cls, kind):
    return f"{cls.__module__.split('.')[0]}/{kind}/{cls.__name__}"


if __name__ == "__main__":
    main()
