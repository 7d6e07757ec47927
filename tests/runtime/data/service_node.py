"""The rospy side of the service round trip; runs under Debian's /usr/bin/python3.

For every planned service type it picks a random request R and response Q (roundtrip_node's
filler) and serves the plan's "py" service: the first call gets Q; every later call's request is
compared with R. Once the C# program serves the plan's "cs" service, it is called with R and
its response compared with Q. So R crosses ROS#'s client as a server's request and a client's
request, and Q as a client's response and a server's response.
"ready" is printed only once the master lists every "py" service: rospy registers them from a
background thread, and a call that reaches rosbridge before that gets "Service ... does not
exist", which ROS# cannot parse (its response handler is then never called).
Writes {type: {"request": null | difference | "no answer", "response": ...}} as JSON.
Usage: service_node.py PLAN.json RESULT.json SEED TIMEOUT
"""

import json
import random
import sys
import threading
import time

import roslib.message
import rospy
from roundtrip_node import difference, random_message


def bounded_call(proxy, request, deadline):
    """The proxy's call, given up at the deadline: rosbridge 0.11 waits without limit for the
    client that advertised the service to answer, and so would the caller."""
    answer = []

    def call():
        try:
            answer.append(proxy(request))
        except rospy.ServiceException as error:
            answer.append(error)

    caller = threading.Thread(target=call, daemon=True)
    caller.start()
    caller.join(max(deadline - time.monotonic(), 1.0))
    if not answer:
        raise rospy.ServiceException("no response in time")
    if isinstance(answer[0], rospy.ServiceException):
        raise answer[0]
    return answer[0]


def main(plan_path, result_path, seed, timeout):
    with open(plan_path) as handle:
        plan = json.load(handle)
    rng = random.Random(int(seed))
    rospy.init_node("service_roundtrip", disable_signals=True)
    lock = threading.Lock()
    results = {}
    cases = []

    def server(name, request_type, sent_request, response):
        calls = []

        def handle(request):
            with lock:
                calls.append(request)
                if len(calls) > 1 and "request" not in results[name]:
                    results[name]["request"] = difference(sent_request, request, "", request_type)
            return response

        return handle

    for entry in plan:
        cls = roslib.message.get_service_class(entry["type"])
        request = random_message(rng, cls._request_class)
        response = random_message(rng, cls._response_class)
        results[entry["type"]] = {}
        request_type = entry["type"] + "Request"
        rospy.Service(entry["py"], cls, server(entry["type"], request_type, request, response))
        cases.append((entry, cls, request, response))
    for entry in plan:
        rospy.wait_for_service(entry["py"], timeout=float(timeout))
    print("ready", flush=True)
    deadline = time.monotonic() + float(timeout)
    for entry, cls, request, response in cases:
        try:
            rospy.wait_for_service(entry["cs"], timeout=max(deadline - time.monotonic(), 0.1))
            got = bounded_call(rospy.ServiceProxy(entry["cs"], cls), request, deadline)
            found = difference(response, got, "", entry["type"] + "Response")
        except (rospy.ROSException, rospy.ServiceException) as error:
            found = f"no answer ({error})"
        with lock:
            results[entry["type"]]["response"] = found
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
    rospy.signal_shutdown("done")


if __name__ == "__main__":
    main(*sys.argv[1:])
