"""The rospy side of the script test; runs under Debian's /usr/bin/python3.

Publishes /odom (30 Hz), /base_status (30 Hz, header.frame_id counting 1, 2, ...) and /scan
(50 Hz), and records every /cmd_vel with its arrival time. Runs until its stdin closes, then
writes {"cmd_vel": [[seconds, linear.x], ...]} as JSON.
Usage: script_node.py RESULT.json
"""

import json
import sys
import threading
import time

import rosgraph
import rospy
from diffbot_msgs.msg import BaseStatus
from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry
from sensor_msgs.msg import LaserScan


def registered(published, subscribed, timeout=30):
    """Wait until the master lists this node's topics: rospy registers them from a background
    thread, and a /cmd_vel published before our subscription is known would be lost."""
    master = rosgraph.Master(rospy.get_name())
    me = rospy.get_name()
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        publishers, subscribers, _ = master.getSystemState()
        mine = (
            {t for t, nodes in publishers if me in nodes},
            {t for t, nodes in subscribers if me in nodes},
        )
        if set(published) <= mine[0] and set(subscribed) <= mine[1]:
            return
        time.sleep(0.05)
    raise SystemExit(f"the master never listed {published} and {subscribed} for {me}")


def main(result_path):
    rospy.init_node("script_test", disable_signals=True)
    received = []
    rospy.Subscriber("/cmd_vel", Twist, lambda m: received.append([time.monotonic(), m.linear.x]))
    odom = rospy.Publisher("/odom", Odometry, queue_size=10)
    status = rospy.Publisher("/base_status", BaseStatus, queue_size=100)
    scan = rospy.Publisher("/scan", LaserScan, queue_size=10)
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

    registered(["/odom", "/base_status", "/scan"], ["/cmd_vel"])
    thread = threading.Thread(target=publish)
    thread.start()
    print("ready", flush=True)
    sys.stdin.read()
    stop.set()
    thread.join()
    with open(result_path, "w") as handle:
        json.dump({"cmd_vel": received}, handle)
    rospy.signal_shutdown("done")


if __name__ == "__main__":
    main(*sys.argv[1:])
