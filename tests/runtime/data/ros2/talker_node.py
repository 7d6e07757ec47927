"""An rclpy node for the stack's own test: publishes ``std_msgs/String`` "hello N" on argv[1]
every 0.1 s and serves ``std_srvs/SetBool`` on argv[2] (success = the request's data, message
"set <data>"), prints "ready" once both exist, and runs until its stdin closes."""

import sys
import threading

import rclpy
from rclpy.executors import SingleThreadedExecutor
from std_msgs.msg import String
from std_srvs.srv import SetBool


def main() -> None:
    topic, service = sys.argv[1], sys.argv[2]
    rclpy.init()
    node = rclpy.create_node("talker")
    publisher = node.create_publisher(String, topic, 10)
    count = [0]

    def tick() -> None:
        count[0] += 1
        publisher.publish(String(data=f"hello {count[0]}"))

    def serve(request: SetBool.Request, response: SetBool.Response) -> SetBool.Response:
        response.success = request.data
        response.message = f"set {request.data}"
        return response

    node.create_timer(0.1, tick)
    node.create_service(SetBool, service, serve)
    executor = SingleThreadedExecutor()
    executor.add_node(node)
    threading.Thread(target=executor.spin, daemon=True).start()
    print("ready", flush=True)
    sys.stdin.read()
    executor.shutdown()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
