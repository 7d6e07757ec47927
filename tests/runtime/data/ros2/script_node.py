"""The rclpy side of the ROS 2 script test; runs in the ROS 2 stack's venv (data/script_node.py
is its rospy twin).

Publishes /odom (30 Hz), /base_status (30 Hz, header.frame_id counting 1, 2, ...) and /scan
(50 Hz), and records every /cmd_vel with its arrival time. Runs until its stdin closes, then
writes {"cmd_vel": [[seconds, linear.x], ...]} as JSON.
Usage: script_node.py RESULT.json
"""

import json
import sys
import threading
import time

import rclpy
from diffbot_msgs.msg import BaseStatus
from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry
from rclpy.executors import SingleThreadedExecutor
from sensor_msgs.msg import LaserScan


def main(result_path):
    rclpy.init()
    node = rclpy.create_node("script_test")
    received = []
    node.create_subscription(
        Twist, "/cmd_vel", lambda m: received.append([time.monotonic(), m.linear.x]), 100
    )
    odom = node.create_publisher(Odometry, "/odom", 10)
    status = node.create_publisher(BaseStatus, "/base_status", 100)
    scan = node.create_publisher(LaserScan, "/scan", 10)
    stop = threading.Event()

    def publish():
        tick = 0
        while not stop.is_set():
            tick += 1
            scan.publish(LaserScan(ranges=[1.0, 2.0]))
            if tick % 5 in (0, 2, 4):  # 30 of every 50 ticks
                odom.publish(Odometry())
                message = BaseStatus()
                message.header.frame_id = str(tick)
                status.publish(message)
            time.sleep(0.02)

    executor = SingleThreadedExecutor()
    executor.add_node(node)
    threading.Thread(target=executor.spin, daemon=True).start()
    thread = threading.Thread(target=publish)
    thread.start()
    print("ready", flush=True)
    sys.stdin.read()
    stop.set()
    thread.join()
    with open(result_path, "w") as handle:
        json.dump({"cmd_vel": received}, handle)
    executor.shutdown()
    rclpy.shutdown()


if __name__ == "__main__":
    main(*sys.argv[1:])
