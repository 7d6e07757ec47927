"""A small rosbridge v2 server that answers rosapi calls from genmsg's output.

It speaks the protocol as rosbridge_suite's ROS 1 server does: JSON text frames,
``call_service`` with an ``id`` answered by ``service_response`` with the same ``id``,
``values`` and ``result``; a failed call gets ``result: false`` and the error text as ``values``.
``faults`` makes one rosapi service misbehave: ``silent`` (never answers), ``drop`` (closes the
connection), ``fail`` (result false), ``status`` (an error ``status`` op), ``not_json``,
``bad_shape`` (wrong field types), ``empty_text`` (empty full definitions).
"""

from __future__ import annotations

import json
import threading
from collections.abc import Iterator
from contextlib import contextmanager
from typing import Any

from websockets.exceptions import ConnectionClosed
from websockets.sync.server import ServerConnection, serve

TOPICS = {  # name: (type, publishers, subscribers)
    "/chatter": ("std_msgs/String", ["/talker"], []),
    "/imu": ("sensor_msgs/Imu", ["/driver"], ["/rosbridge_websocket"]),
    "/reading": ("scaffold_test_msgs/Reading", ["/sensor"], []),
    "/cmd_vel": ("geometry_msgs/Twist", [], ["/base"]),
    "/rosout": ("rosgraph_msgs/Log", ["/talker"], ["/rosout"]),
}
SERVICES = {
    "/trigger": "std_srvs/Trigger",
    "/calibrate": "scaffold_test_msgs/Calibrate",
    "/rosapi/topics": "rosapi/Topics",
    "/talker/get_loggers": "roscpp/GetLoggers",
}


class FakeRosbridge:
    def __init__(self, truth: dict[str, Any]) -> None:
        self.truth = truth
        self.faults: dict[str, str] = {}
        self.calls: list[str] = []
        # websockets.sync.server.Server (named WebSocketServer before websockets 13)
        self._server: Any = None

    @property
    def url(self) -> str:
        assert self._server is not None
        host, port = self._server.socket.getsockname()[:2]
        return f"ws://{host}:{port}"

    def rosapi(self, service: str, args: dict[str, Any]) -> dict[str, Any]:
        """The values a real rosapi would return, from genmsg's definitions."""
        empty = self.faults.get(service) == "empty_text"
        if service == "/rosapi/topics_and_raw_types":
            names = sorted(TOPICS)
            return {
                "topics": names,
                "types": [TOPICS[n][0] for n in names],
                "typedefs_full_text": [
                    "" if empty else self.truth[TOPICS[n][0]]["definition"] for n in names
                ],
            }
        if service == "/rosapi/topics":
            names = sorted(TOPICS)
            return {"topics": names, "types": [TOPICS[n][0] for n in names]}
        if service in ("/rosapi/publishers", "/rosapi/subscribers"):
            index = 1 if service.endswith("publishers") else 2
            return {service.rsplit("/", 1)[1]: TOPICS[args["topic"]][index]}
        if service == "/rosapi/services":
            return {"services": sorted(SERVICES)}
        if service == "/rosapi/service_type":
            return {"type": SERVICES.get(args["service"], "")}
        if service == "/rosapi/message_details":
            return {"typedefs": self.truth[args["type"]]["typedefs"]}
        if service in ("/rosapi/service_request_details", "/rosapi/service_response_details"):
            half = "request" if "request" in service else "response"
            return {"typedefs": self.truth[args["type"]][half]["typedefs"]}
        raise KeyError(f"service [{service}] does not exist")

    def handle(self, connection: ServerConnection) -> None:
        try:
            for frame in connection:
                request = json.loads(frame)
                if request.get("op") == "call_service":
                    self._answer(connection, request)
        except ConnectionClosed:
            pass

    def _answer(self, connection: ServerConnection, request: dict[str, Any]) -> None:
        service, call_id = request["service"], request.get("id")
        self.calls.append(service)
        fault = self.faults.get(service)
        if fault == "silent":
            return
        if fault == "drop":
            connection.close()
            return
        if fault == "not_json":
            connection.send("{'op': 'service_response'")
            return
        if fault == "status":
            connection.send(
                json.dumps(
                    {
                        "op": "status",
                        "level": "error",
                        "id": call_id,
                        "msg": f"Service {service} does not exist",
                    }
                )
            )
            return
        # Unrelated traffic first, as a busy bridge sends: the client must skip it.
        connection.send(json.dumps({"op": "publish", "topic": "/rosout", "msg": {"data": 1}}))
        try:
            values: Any = self.rosapi(service, request.get("args") or {})
            result = fault != "fail"
            if not result:
                values = "service call failed: transport error"
        except KeyError as exc:
            values, result = str(exc.args[0]), False
        if fault == "bad_shape":
            values = {key: 42 for key in values}
        connection.send(
            json.dumps(
                {
                    "op": "service_response",
                    "service": service,
                    "id": call_id,
                    "values": values,
                    "result": result,
                }
            )
        )


@contextmanager
def running(truth: dict[str, Any]) -> Iterator[FakeRosbridge]:
    bridge = FakeRosbridge(truth)
    with serve(bridge.handle, "127.0.0.1", 0) as server:
        bridge._server = server
        thread = threading.Thread(target=server.serve_forever, daemon=True)
        thread.start()
        try:
            yield bridge
        finally:
            server.shutdown()
            thread.join(timeout=5)
