"""A small double of rosbridge for ROS 2, its action operations only, for the runtime tests:
rosbridge_suite's ROS 2 server cannot run here (no ROS 2 middleware on Debian), so ROS#'s ROS 2
action API and the scripts built on it are checked against this instead.

It follows the public protocol (github.com/RobotWebTools/rosbridge_suite, ROSBRIDGE_PROTOCOL.md,
"Action operations") and what rosbridge's ROS 2 capabilities send and accept
(``rosbridge_library/capabilities``: send_action_goal, advertise_action, action_feedback,
action_result, unadvertise_action):

- As the ROS 2 side of a client's goal (``send_action_goal`` to an action this double serves):
  checks the fields (``action``, ``action_type`` strings; ``args`` a dict whose members are
  fields of the goal with values of their ROS types; ``feedback`` a bool; ``fragment_size`` an
  int; ``compression`` a string), then answers with ``action_feedback`` messages (only when
  ``feedback`` is true) and an ``action_result`` ``{action, values, status, result: true, id}``,
  ``id`` being the goal's ``id``. A goal the served behaviour refuses gets rosbridge's failure
  answer: ``values`` a text, ``status`` 0 (STATUS_UNKNOWN), ``result`` false.
  ``cancel_action_goal`` with the goal's ``id`` cancels it: the result then has status 5
  (CANCELED) and ``result`` true, as rosbridge passes on what the ROS 2 server returns.
- As a ROS 2 client of an action the client advertised (``advertise_action`` with ``action``
  and ``type``): sends ``send_action_goal`` ``{id: "action_goal:<action>:<n>", action,
  action_type, args, feedback: true}``, may send ``cancel_action_goal`` ``{id, action}``, and
  takes ``action_feedback`` ``{action, id, values}`` and ``action_result`` ``{action, id, values,
  status, result}``, checking fields and types as rosbridge does (``values`` must be a dict of
  the feedback's or result's fields); ``unadvertise_action`` ends the advertisement.

Every departure from the protocol is recorded in ``errors`` (real rosbridge answers with a
``status`` op and drops the message; ROS# ignores ``status``). What it does not model: ROS 2
itself (goal UUIDs, the GoalStatus topic, get_result), topics and services, nested message
types in values (flat fields of primitive types and arrays of them only), fragmentation,
compression, CBOR, authentication, and timing (everything is answered at once).
"""

from __future__ import annotations

import json
import threading
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from dataclasses import dataclass, field
from typing import Any

from websockets.exceptions import ConnectionClosed
from websockets.sync.server import ServerConnection, serve

# action_msgs/msg/GoalStatus
STATUS_UNKNOWN, STATUS_SUCCEEDED, STATUS_CANCELED = 0, 4, 5
_INTEGERS = {"byte", "char", "uint8", "int8", "uint16", "int16", "uint32", "int32"}
_INTEGERS |= {"uint64", "int64"}

#: A message's fields: ``{name: ROS 2 type}`` (``string``, ``bool``, ``float32``, ``int32[]``...).
Fields = dict[str, str]


@dataclass(frozen=True)
class ActionType:
    """An action's name as rosbridge takes it (``pkg/action/Name``) and its three messages."""

    name: str
    goal: Fields
    result: Fields
    feedback: Fields


def _value_fits(value: Any, ros_type: str) -> bool:
    if ros_type.endswith("]"):
        base = ros_type[: ros_type.index("[")]
        if base in ("uint8", "char") and isinstance(value, str):
            return True  # rosbridge takes byte arrays as base64 text too
        return isinstance(value, list) and all(_value_fits(v, base) for v in value)
    if ros_type in ("string", "wstring") or ros_type.startswith("string<="):
        return isinstance(value, str)
    if ros_type == "bool":
        return isinstance(value, bool)
    if ros_type in ("float32", "float64"):
        return isinstance(value, int | float) and not isinstance(value, bool)
    if ros_type in _INTEGERS:
        return isinstance(value, int) and not isinstance(value, bool)
    raise NotImplementedError(f"the double models primitive fields only, not {ros_type}")


def message_problems(values: Any, fields: Fields, where: str) -> list[str]:
    """What rosbridge's populate_instance would refuse in ``values`` for a message of ``fields``
    (members it does not have, values of another type); missing members take defaults."""
    if not isinstance(values, dict):
        return [f"{where}: expected an object, got {values!r}"]
    problems = [f"{where}: no field {name!r}" for name in values if name not in fields]
    problems += [
        f"{where}.{name}: {value!r} is not a {fields[name]}"
        for name, value in values.items()
        if name in fields and not _value_fits(value, fields[name])
    ]
    return problems


def _type_problems(message: dict[str, Any], spec: tuple[tuple[bool, str, Any], ...]) -> list[str]:
    """rosbridge's Capability.basic_type_check: required members present, types right."""
    op = message.get("op")
    problems = []
    for required, name, kinds in spec:
        if name not in message:
            if required:
                problems.append(f"{op}: missing {name!r}")
        elif not isinstance(message[name], kinds) or (
            kinds is int and isinstance(message[name], bool)
        ):
            problems.append(f"{op}: {name!r} is {message[name]!r}")
    return problems


_SEND_GOAL = (
    (True, "action", str),
    (True, "action_type", str),
    (False, "id", str),
    (False, "args", dict),
    (False, "feedback", bool),
    (False, "fragment_size", (int, type(None))),
    (False, "compression", str),
)
_CANCEL = ((True, "action", str), (True, "id", str))
_ADVERTISE = ((True, "action", str), (True, "type", str))
_UNADVERTISE = ((True, "action", str),)
_FEEDBACK = ((True, "action", str), (True, "id", str), (False, "values", dict))
_RESULT = (
    (True, "action", str),
    (True, "id", str),
    (False, "values", dict),
    (True, "status", int),
    (True, "result", bool),
)

#: What a served action does with a goal: ``run(goal_args, feedback, cancelled)`` returns
#: ``(status, result values)`` or raises ``Refused``. ``feedback(values)`` sends one feedback;
#: ``cancelled`` is set when the client cancels the goal.
Behaviour = Callable[[dict[str, Any], Callable[[dict[str, Any]], None], threading.Event], Any]


class Refused(Exception):
    """A served action's refusal of a goal (rosbridge passes the error text on)."""


@dataclass
class _Goal:
    """A goal the double sent to an advertised action, and what came back for it."""

    args: dict[str, Any]
    feedback: list[dict[str, Any]] = field(default_factory=list)
    result: dict[str, Any] | None = None
    first_feedback: threading.Event = field(default_factory=threading.Event)
    done: threading.Event = field(default_factory=threading.Event)


class RosbridgeDouble:
    """One double for a test: ``serve`` actions for clients, ``advertised`` ones to call."""

    def __init__(self, action_type: ActionType) -> None:
        self.action_type = action_type
        self.served: dict[str, Behaviour] = {}
        self.advertised: dict[str, str] = {}  # action name -> type
        self.unadvertised: list[str] = []
        self.advertised_event = threading.Condition()
        self.errors: list[str] = []
        self.received: list[dict[str, Any]] = []
        self._goals: dict[str, _Goal] = {}
        self._running: dict[str, threading.Event] = {}  # client goal id -> cancelled
        self._counter = 0
        self._lock = threading.Lock()
        self._connection: ServerConnection | None = None
        self._server: Any = None  # websockets.sync.server.Server

    @property
    def url(self) -> str:
        assert self._server is not None
        host, port = self._server.socket.getsockname()[:2]
        return f"ws://{host}:{port}"

    def _error(self, text: str) -> None:
        with self._lock:
            self.errors.append(text)

    def _send(self, message: dict[str, Any]) -> None:
        assert self._connection is not None
        try:
            self._connection.send(json.dumps(message))
        except ConnectionClosed:
            self._error(f"connection closed before {message['op']} could be sent")

    # The connection: one client at a time, as each test has one.
    def handle(self, connection: ServerConnection) -> None:
        self._connection = connection
        try:
            for frame in connection:
                try:
                    message = json.loads(frame)
                except ValueError:
                    self._error(f"not JSON: {frame[:200]!r}")
                    continue
                with self._lock:
                    self.received.append(message)
                self._dispatch(message)
        except ConnectionClosed:
            pass

    def _dispatch(self, message: dict[str, Any]) -> None:
        handlers = {
            "send_action_goal": (_SEND_GOAL, self._on_send_goal),
            "cancel_action_goal": (_CANCEL, self._on_cancel),
            "advertise_action": (_ADVERTISE, self._on_advertise),
            "unadvertise_action": (_UNADVERTISE, self._on_unadvertise),
            "action_feedback": (_FEEDBACK, self._on_feedback),
            "action_result": (_RESULT, self._on_result),
        }
        op = message.get("op")
        if op not in handlers:
            self._error(f"unexpected op {op!r}")
            return
        spec, handler = handlers[op]
        problems = _type_problems(message, spec)
        if problems:
            for problem in problems:
                self._error(problem)
            return
        handler(message)

    # The double as the ROS 2 side of the client's goals.
    def _on_send_goal(self, message: dict[str, Any]) -> None:
        action, goal_id = message["action"], message.get("id")
        if action not in self.served:
            self._error(f"send_action_goal: no action server for {action}")
            return
        if message["action_type"] != self.action_type.name:
            self._error(f"send_action_goal: action_type {message['action_type']!r}")
            return
        args = message.get("args", {})
        problems = message_problems(args, self.action_type.goal, "send_action_goal.args")
        if problems:
            for problem in problems:
                self._error(problem)
            return
        cancelled = threading.Event()
        if goal_id is not None:
            with self._lock:
                self._running[goal_id] = cancelled
        wants_feedback = message.get("feedback", False)
        threading.Thread(
            target=self._run_goal,
            args=(action, goal_id, args, wants_feedback, cancelled),
            daemon=True,
        ).start()

    def _run_goal(
        self,
        action: str,
        goal_id: str | None,
        args: dict[str, Any],
        wants_feedback: bool,
        cancelled: threading.Event,
    ) -> None:
        def answer(message: dict[str, Any]) -> None:
            if goal_id is not None:
                message["id"] = goal_id
            self._send(message)

        def feedback(values: dict[str, Any]) -> None:
            if wants_feedback:
                answer({"op": "action_feedback", "action": action, "values": values})

        try:
            status, values = self.served[action](args, feedback, cancelled)
        except Refused as refusal:
            status, values, result = STATUS_UNKNOWN, str(refusal), False
        else:
            result = True
        answer(
            {
                "op": "action_result",
                "action": action,
                "values": values,
                "status": status,
                "result": result,
            }
        )
        with self._lock:
            self._running.pop(goal_id or "", None)

    def _on_cancel(self, message: dict[str, Any]) -> None:
        with self._lock:
            cancelled = self._running.get(message["id"])
        if message["action"] in self.advertised:  # not for us: a client cancels our goal
            self._error(f"cancel_action_goal for advertised {message['action']}")
        elif cancelled is None:
            self._error(f"cancel_action_goal: no goal {message['id']!r} in progress")
        else:
            cancelled.set()

    # The double as a ROS 2 client of the actions the client advertises.
    def _on_advertise(self, message: dict[str, Any]) -> None:
        if message["type"] != self.action_type.name:
            self._error(f"advertise_action: type {message['type']!r}")
        with self.advertised_event:
            self.advertised[message["action"]] = message["type"]
            self.advertised_event.notify_all()

    def _on_unadvertise(self, message: dict[str, Any]) -> None:
        with self.advertised_event:
            if self.advertised.pop(message["action"], None) is None:
                self._error(f"unadvertise_action: {message['action']} was not advertised")
            self.unadvertised.append(message["action"])
            self.advertised_event.notify_all()

    def wait_advertised(self, action: str, timeout: float) -> bool:
        """Whether ``action`` is advertised within ``timeout`` (a guard against a hang)."""
        with self.advertised_event:
            return self.advertised_event.wait_for(lambda: action in self.advertised, timeout)

    def wait_unadvertised(self, action: str, timeout: float) -> bool:
        with self.advertised_event:
            return self.advertised_event.wait_for(lambda: action in self.unadvertised, timeout)

    def send_goal(self, action: str, args: dict[str, Any]) -> tuple[str, _Goal]:
        """Send a goal to an advertised action; its id, and where its answers collect."""
        with self._lock:
            self._counter += 1
            goal_id = f"action_goal:{action}:{self._counter}"
            goal = self._goals[goal_id] = _Goal(args)
        self._send(
            {
                "op": "send_action_goal",
                "id": goal_id,
                "action": action,
                "action_type": self.advertised.get(action, self.action_type.name),
                "args": args,
                "feedback": True,
            }
        )
        return goal_id, goal

    def cancel_goal(self, action: str, goal_id: str) -> None:
        self._send({"op": "cancel_action_goal", "id": goal_id, "action": action})

    def _advertised_goal(self, message: dict[str, Any]) -> _Goal | None:
        if message["action"] not in self.advertised:
            self._error(f"{message['op']}: {message['action']} has not been advertised")
            return None
        goal = self._goals.get(message["id"])
        if goal is None or goal.done.is_set():
            self._error(f"{message['op']}: no goal {message['id']!r} in progress")
        return goal if goal is not None and not goal.done.is_set() else None

    def _on_feedback(self, message: dict[str, Any]) -> None:
        goal = self._advertised_goal(message)
        values = message.get("values", {})
        problems = message_problems(values, self.action_type.feedback, "action_feedback.values")
        for problem in problems:
            self._error(problem)
        if goal is not None and not problems:
            goal.feedback.append(values)
            goal.first_feedback.set()

    def _on_result(self, message: dict[str, Any]) -> None:
        goal = self._advertised_goal(message)
        values = message.get("values", {})
        problems = message_problems(values, self.action_type.result, "action_result.values")
        for problem in problems:
            self._error(problem)
        if goal is not None and not problems:
            goal.result = {k: message[k] for k in ("values", "status", "result")}
            goal.done.set()


@contextmanager
def running(action_type: ActionType) -> Iterator[RosbridgeDouble]:
    """The double listening on a free loopback port, for the ``with`` block."""
    double = RosbridgeDouble(action_type)
    with serve(double.handle, "127.0.0.1", 0) as server:
        double._server = server
        thread = threading.Thread(target=server.serve_forever, daemon=True)
        thread.start()
        try:
            yield double
        finally:
            server.shutdown()
            thread.join(timeout=5)
