"""A plain JSON websocket client doing what csharp/Echo.cs and csharp/ServiceEcho.cs do through
ROS#, with rosbridge's JSON as it comes: what fails through this fails in rosbridge itself.

  json_echo.py topics URL PLAN    each line "IN OUT TYPE": republish every message from IN on OUT
  json_echo.py services URL PLAN  each line "PY CS TYPE": call PY with an empty request, keep its
                                  response; serve CS with that response, passing each request
                                  CS gets on to PY

Prints "ready" once every topic is subscribed and advertised (services: each is served once its
first call is answered; rosbridge never answers one it cannot carry), and every "status" or
failed "service_response" rosbridge sends; exits when stdin closes. Runs under the tests'
Python.
"""

import json
import sys
import threading
import time

from websockets.sync.client import connect


def main(kind, url, plan_path):
    with open(plan_path) as handle:
        lines = [line.split() for line in handle if line.strip()]
    stop = threading.Event()
    threading.Thread(target=lambda: (sys.stdin.read(), stop.set()), daemon=True).start()
    with connect(url, open_timeout=30, max_size=None) as socket:
        send = lambda message: socket.send(json.dumps(message))  # noqa: E731
        routes, kept, first = {}, {}, {}
        retries = {python: 40 for python, _, _ in lines}
        if kind == "topics":
            for source, target, ros_type in lines:
                send({"op": "advertise", "topic": target, "type": ros_type})
                send({"op": "subscribe", "topic": source, "type": ros_type})
                routes[source] = target
            print("ready", flush=True)
        else:
            # Every first call at once: rosbridge never answers one it cannot carry.
            for python, ours, ros_type in lines:
                first[f"first:{python}"] = (python, ours, ros_type)
                send({"op": "call_service", "service": python, "args": {}, "id": f"first:{python}"})
        while not stop.is_set():
            try:
                message = json.loads(socket.recv(timeout=0.5))
            except TimeoutError:
                continue
            op = message.get("op")
            if op == "publish" and message.get("topic") in routes:
                send({"op": "publish", "topic": routes[message["topic"]], "msg": message["msg"]})
            elif op == "service_response" and message.get("id") in first:
                python, ours, ros_type = first.pop(message["id"])
                if message.get("result"):
                    kept[ours] = message["values"]
                    send({"op": "advertise_service", "service": ours, "type": ros_type})
                    routes[ours] = python
                elif "does not exist" in str(message.get("values")) and retries[python] > 0:
                    retries[python] -= 1  # rosbridge's node has not discovered it yet
                    time.sleep(0.5)
                    first[message["id"]] = (python, ours, ros_type)
                    send({"op": "call_service", "service": python, "args": {}, "id": message["id"]})
                else:
                    print(f"failed {python}: {json.dumps(message)}", flush=True)
            elif op == "call_service" and message.get("service") in routes:
                service = message["service"]
                reply = {"op": "service_response", "service": service, "id": message.get("id")}
                send({**reply, "values": kept[service], "result": True})
                forward = {"op": "call_service", "service": routes[service], "id": "forward"}
                send({**forward, "args": message.get("args", {})})
            elif op == "status" or (op == "service_response" and not message.get("result")):
                print(json.dumps(message), flush=True)


if __name__ == "__main__":
    main(*sys.argv[1:])
