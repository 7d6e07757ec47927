"""The rosbridge ROS 2 double refuses what rosbridge's ROS 2 capabilities refuse, so that the
action tests built on it cannot pass on messages real rosbridge would drop: a client's
protocol mistakes end up in ``errors``, and a well-formed exchange (the shapes of the public
protocol document) leaves none."""

from __future__ import annotations

import json
import time
from collections.abc import Iterator
from typing import Any

import pytest
from websockets.sync.client import connect

from tests.runtime.dock_action import DOCK, dock
from tests.runtime.rosbridge2_double import RosbridgeDouble, running

GOAL = {
    "op": "send_action_goal",
    "id": "/dock:0",
    "action": "/dock",
    "action_type": "diffbot_msgs/action/Dock",
    "args": {"dock_id": "alpha"},
    "feedback": True,
    "fragment_size": 2147483647,
    "compression": "none",
}


@pytest.fixture
def double() -> Iterator[RosbridgeDouble]:
    with running(DOCK) as served:
        served.served["/dock"] = dock
        yield served


def _exchange(double: RosbridgeDouble, *messages: dict[str, Any], answers: int = 0) -> list[Any]:
    """Send ``messages``; the first ``answers`` messages the double sends back."""
    with connect(double.url) as client:
        for message in messages:
            client.send(json.dumps(message))
        received = [json.loads(client.recv(timeout=10)) for _ in range(answers)]
        _settle(double, len(messages))
    return received


def _settle(double: RosbridgeDouble, sent: int) -> None:
    """Until the double has taken every message sent (a guard of 10 s against a hang)."""
    deadline = time.monotonic() + 10
    while len(double.received) < sent and time.monotonic() < deadline:
        time.sleep(0.01)


def test_a_goal_gets_feedback_then_its_result_with_its_id(double: RosbridgeDouble) -> None:
    answers = _exchange(double, GOAL, answers=3)
    assert answers == [
        {"op": "action_feedback", "action": "/dock", "values": {"distance_remaining": 2.5}}
        | {"id": "/dock:0"},
        {"op": "action_feedback", "action": "/dock", "values": {"distance_remaining": 1.25}}
        | {"id": "/dock:0"},
        {
            "op": "action_result",
            "action": "/dock",
            "values": {"docked": True, "battery": 87.5},
            "status": 4,
            "result": True,
            "id": "/dock:0",
        },
    ]
    assert double.errors == []


def test_without_feedback_true_only_the_result_comes(double: RosbridgeDouble) -> None:
    (answer,) = _exchange(double, {**GOAL, "feedback": False}, answers=1)
    assert answer["op"] == "action_result"


def test_a_refused_goal_gets_rosbridges_failure_answer(double: RosbridgeDouble) -> None:
    (answer,) = _exchange(double, {**GOAL, "args": {"dock_id": "reject-me"}}, answers=1)
    assert answer == {
        "op": "action_result",
        "action": "/dock",
        "values": "Goal was rejected",
        "status": 0,
        "result": False,
        "id": "/dock:0",
    }


@pytest.mark.parametrize(
    ("change", "error"),
    [
        ({"compression": None}, "send_action_goal: 'compression' is None"),
        ({"action_type": None}, "send_action_goal: 'action_type' is None"),
        ({"feedback": 1}, "send_action_goal: 'feedback' is 1"),
        ({"args": {"dock": "alpha"}}, "send_action_goal.args: no field 'dock'"),
        ({"args": {"dock_id": 7}}, "send_action_goal.args.dock_id: 7 is not a string"),
        ({"action_type": "diffbot_msgs/Dock"}, "send_action_goal: action_type 'diffbot_msgs/Dock'"),
        ({"action": "/nobody"}, "send_action_goal: no action server for /nobody"),
    ],
)
def test_a_malformed_goal_is_refused(
    double: RosbridgeDouble, change: dict[str, Any], error: str
) -> None:
    _exchange(double, {**GOAL, **change})
    assert double.errors == [error]


def test_an_advertised_action_gets_goals_and_takes_feedback_and_results(
    double: RosbridgeDouble,
) -> None:
    advertise = {"op": "advertise_action", "action": "/cs", "type": DOCK.name, "id": None}
    with connect(double.url) as client:
        client.send(json.dumps(advertise))
        assert double.wait_advertised("/cs", 10)
        goal_id, goal = double.send_goal("/cs", {"dock_id": "x"})
        sent = json.loads(client.recv(timeout=10))
        assert sent == {
            "op": "send_action_goal",
            "id": "action_goal:/cs:1",
            "action": "/cs",
            "action_type": DOCK.name,
            "args": {"dock_id": "x"},
            "feedback": True,
        }
        reply = {"action": "/cs", "id": goal_id}
        feedback = {"op": "action_feedback", **reply, "values": {"distance_remaining": 1}}
        result = {"op": "action_result", **reply, "values": {"docked": True}}
        client.send(json.dumps(feedback))
        client.send(json.dumps({**result, "status": 4, "result": True}))
        assert goal.done.wait(10)
        # After the result the goal is over: more answers for it are refused.
        client.send(json.dumps(feedback))
        client.send(json.dumps({"op": "unadvertise_action", "action": "/cs", "id": None}))
        assert double.wait_unadvertised("/cs", 10)
    assert goal.feedback == [{"distance_remaining": 1}]
    assert goal.result == {"values": {"docked": True}, "status": 4, "result": True}
    assert double.errors == [f"action_feedback: no goal {goal_id!r} in progress"]


@pytest.mark.parametrize(
    ("message", "error"),
    [
        ({"values": {"docked": "yes"}}, "action_result.values.docked: 'yes' is not a bool"),
        ({"values": "done"}, "action_result: 'values' is 'done'"),
        ({"status": "4"}, "action_result: 'status' is '4'"),
        ({"result": None}, "action_result: 'result' is None"),
        ({"id": "action_goal:/cs:9"}, "action_result: no goal 'action_goal:/cs:9' in progress"),
        ({"action": "/other"}, "action_result: /other has not been advertised"),
    ],
)
def test_a_malformed_result_is_refused(
    double: RosbridgeDouble, message: dict[str, Any], error: str
) -> None:
    with connect(double.url) as client:
        client.send(json.dumps({"op": "advertise_action", "action": "/cs", "type": DOCK.name}))
        assert double.wait_advertised("/cs", 10)
        goal_id, _ = double.send_goal("/cs", {})
        client.recv(timeout=10)
        result = {"op": "action_result", "action": "/cs", "id": goal_id, "values": {}}
        client.send(json.dumps({**result, "status": 4, "result": True, **message}))
        _settle(double, 2)
    assert error in double.errors


def test_a_cancel_ends_the_goal_as_canceled(double: RosbridgeDouble) -> None:
    goal = {**GOAL, "args": {"dock_id": "cancel-me"}}
    cancel = {"op": "cancel_action_goal", "id": "/dock:0", "action": "/dock"}
    with connect(double.url) as client:
        client.send(json.dumps(goal))
        assert json.loads(client.recv(timeout=10))["op"] == "action_feedback"
        client.send(json.dumps(cancel))
        result = json.loads(client.recv(timeout=10))
    assert (result["status"], result["result"], result["id"]) == (5, True, "/dock:0")
    assert double.errors == []


def test_cancelling_a_goal_not_in_progress_is_refused(double: RosbridgeDouble) -> None:
    _exchange(double, {"op": "cancel_action_goal", "id": "/dock:7", "action": "/dock"})
    assert double.errors == ["cancel_action_goal: no goal '/dock:7' in progress"]


def test_other_ops_and_non_json_are_reported(double: RosbridgeDouble) -> None:
    with connect(double.url) as client:
        client.send(json.dumps({"op": "publish", "topic": "/x", "msg": {}}))
        client.send("{not json")
        deadline = time.monotonic() + 10
        while len(double.errors) < 2 and time.monotonic() < deadline:
            time.sleep(0.01)
    assert double.errors == ["unexpected op 'publish'", "not JSON: '{not json'"]


def test_goals_run_concurrently_so_a_cancel_reaches_a_running_goal(
    double: RosbridgeDouble,
) -> None:
    # A goal waiting for its cancel does not hold up the next message (rosbridge always runs
    # cancels in a thread of their own).
    goal = {**GOAL, "args": {"dock_id": "cancel-me"}}
    other = {**GOAL, "id": "/dock:1"}
    with connect(double.url) as client:
        client.send(json.dumps(goal))
        client.send(json.dumps(other))
        answers = [json.loads(client.recv(timeout=10)) for _ in range(4)]
        client.send(json.dumps({"op": "cancel_action_goal", "id": "/dock:0", "action": "/dock"}))
        answers.append(json.loads(client.recv(timeout=10)))
    results = [(a["id"], a["status"]) for a in answers if a["op"] == "action_result"]
    assert results == [("/dock:1", 4), ("/dock:0", 5)]
    assert double.errors == []
