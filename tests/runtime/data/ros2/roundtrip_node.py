"""The rclpy side of the ROS 2 message round trip; runs in the ROS 2 stack's venv.

For every planned type (``pkg/msg/Name``) it publishes one instance with random values in every
field, limits included (each integer is its type's minimum, maximum or a random value; floats
include the largest float32/float64), on the plan's input topic, again every half second until
answered, subscribes to its output topic and compares the first message that comes back with
what it sent, field by field, exactly. float32 fields hold values float32 represents exactly.
Writes {type: null | "first difference" | "no answer"} as JSON.
Usage: roundtrip_node.py PLAN.json RESULT.json SEED TIMEOUT
"""

import json
import random
import sys
import threading
import time

import rclpy
from rclpy.executors import SingleThreadedExecutor
from values import difference, message_class, random_message

STARTUP = 60.0  # seconds the echo may take to subscribe


def main(plan_path, result_path, seed, timeout):
    with open(plan_path) as handle:
        plan = json.load(handle)
    rng = random.Random(int(seed))
    rclpy.init()
    node = rclpy.create_node("roundtrip")
    lock = threading.Lock()
    results = {}
    pending = []

    def receiver(entry, sent):
        def receive(message):
            with lock:
                if entry["type"] not in results:
                    try:
                        results[entry["type"]] = difference(sent, message, "")
                    except Exception as error:  # a bug here must not stop the other types
                        results[entry["type"]] = f"cannot compare: {error!r}"

        return receive

    for entry in plan:
        cls = message_class(entry["type"])
        sent = random_message(rng, cls)
        publisher = node.create_publisher(cls, entry["in"], 10)
        node.create_subscription(cls, entry["out"], receiver(entry, sent), 10)
        pending.append((entry, publisher, sent))
    executor = SingleThreadedExecutor()
    executor.add_node(node)
    threading.Thread(target=executor.spin, daemon=True).start()
    print("ready", flush=True)
    start = time.monotonic()
    deadline = start + STARTUP
    subscribed = False
    while time.monotonic() < deadline:
        with lock:
            pending = [p for p in pending if p[0]["type"] not in results]
        if not pending:
            break
        if not subscribed and any(p.get_subscription_count() for _, p, _ in pending):
            subscribed = True
            deadline = time.monotonic() + float(timeout)
        for _entry, publisher, sent in pending:
            if publisher.get_subscription_count():
                publisher.publish(sent)
        time.sleep(0.5)
    with lock:
        for entry, _publisher, _sent in pending:
            results.setdefault(entry["type"], "no answer")
        with open(result_path, "w") as handle:
            json.dump(results, handle, indent=1, sort_keys=True)
    executor.shutdown()
    rclpy.shutdown()


if __name__ == "__main__":
    main(*sys.argv[1:])
