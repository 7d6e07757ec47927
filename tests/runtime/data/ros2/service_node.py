"""The rclpy side of the ROS 2 service round trip; runs in the ROS 2 stack's venv.

For every planned service type it picks a random request R and response Q (values.py) and
serves the plan's "py" service: every call gets Q, and every call after the first (the client's
own empty one) has its request compared with R. Once the other side serves the plan's "cs"
service, it is called with R and its response compared with Q. So R crosses the client as a
server's request and a caller's request, and Q as a caller's response and a server's response.
Writes {type: {"request": null | difference | "no answer", "response": ...}} as JSON.
Usage: service_node.py PLAN.json RESULT.json SEED TIMEOUT
"""

import json
import random
import sys
import threading
import time

import rclpy
from rclpy.executors import SingleThreadedExecutor
from values import difference, message_class, random_message


def main(plan_path, result_path, seed, timeout):
    with open(plan_path) as handle:
        plan = json.load(handle)
    rng = random.Random(int(seed))
    rclpy.init()
    node = rclpy.create_node("service_roundtrip")
    lock = threading.Lock()
    results = {}
    cases = []

    def server(name, sent_request, answer):
        calls = []

        def handle(request, response):
            with lock:
                calls.append(request)
                if len(calls) > 1 and "request" not in results[name]:
                    results[name]["request"] = difference(sent_request, request, "")
            return answer

        return handle

    for entry in plan:
        cls = message_class(entry["type"])
        request = random_message(rng, cls.Request)
        response = random_message(rng, cls.Response)
        results[entry["type"]] = {}
        node.create_service(cls, entry["py"], server(entry["type"], request, response))
        cases.append((entry, node.create_client(cls, entry["cs"]), request, response))
    executor = SingleThreadedExecutor()
    executor.add_node(node)
    threading.Thread(target=executor.spin, daemon=True).start()
    print("ready", flush=True)
    deadline = time.monotonic() + float(timeout)
    # Every call at once, each made as soon as its service appears: rosbridge never answers a
    # call it cannot carry, which must not hold up the others.
    waiting, calls = list(cases), []
    while (waiting or calls) and time.monotonic() < deadline:
        for case in [c for c in waiting if c[1].service_is_ready()]:
            waiting.remove(case)
            calls.append((case, case[1].call_async(case[2])))
        for (entry, _client, _request, response), future in [c for c in calls if c[1].done()]:
            calls.remove(((entry, _client, _request, response), future))
            with lock:
                results[entry["type"]]["response"] = difference(response, future.result(), "")
        time.sleep(0.05)
    with lock:
        for entry, *_ in waiting:
            results[entry["type"]]["response"] = "no answer (service never advertised)"
        for (entry, *_), _future in calls:
            results[entry["type"]]["response"] = "no answer"
    while time.monotonic() < deadline:
        with lock:
            if all("request" in r for r in results.values()):
                break
        time.sleep(0.2)
    with lock:
        for result in results.values():
            result.setdefault("request", "no answer")
        with open(result_path, "w") as handle:
            json.dump(results, handle, indent=1, sort_keys=True)
    executor.shutdown()
    rclpy.shutdown()


if __name__ == "__main__":
    main(*sys.argv[1:])
