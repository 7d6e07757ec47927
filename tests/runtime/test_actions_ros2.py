"""ROS 2 actions through ROS#'s real action API (``RosSocket.SendActionGoalRequest``,
``CancelActionGoalRequest``, ``AdvertiseAction``, ``RespondFeedback``, ``RespondResult``,
``UnadvertiseAction``; ROS# built with ``-define:ROS2``) with the classes unityscaffold
generates for diffbot_msgs/action/Dock, against a double of rosbridge's ROS 2 action protocol
(rosbridge2_double.py: rosbridge for ROS 2 cannot run here). Both roles: C# client -> the
double's action server, and the double as a ROS 2 client -> the C# action server; each with a
goal that succeeds and one that is cancelled (csharp/Ros2ActionProbe.cs)."""

from __future__ import annotations

from pathlib import Path

from tests.runtime.client import CSHARP, mcs_compile
from tests.runtime.dock_action import DOCK, TIMEOUT, dock
from tests.runtime.lines import start
from tests.runtime.rosbridge2_double import STATUS_CANCELED, STATUS_SUCCEEDED, running
from tests.runtime.runtime_helpers import SAMPLE_INTERFACES, write_code
from unityscaffold.codegen import Options, generate
from unityscaffold.interfaces.model import Dialect
from unityscaffold.interfaces.registry import Registry


def _build(mcs: str, client: Path, out: Path) -> Path:
    registry = Registry.load(Dialect.ROS2, [SAMPLE_INTERFACES])
    code = generate(registry, [registry.get("diffbot_msgs/action/Dock")], Options(Dialect.ROS2))
    folder = client.parent
    exe = folder / "Ros2ActionProbe.exe"
    mcs_compile(
        mcs,
        [CSHARP / "Ros2ActionProbe.cs", *write_code(code, out)],
        exe,
        references=[client, folder / "Newtonsoft.Json.dll", folder / "websocket-sharp.dll"],
        target="exe",
        defines=["ROS2"],
    )
    return exe


def _values(lines: list[str], key: str) -> list[str]:
    return [line.split(" ", 1)[1] for line in lines if line.startswith(key + " ")]


def test_ros2_actions_goal_feedback_result_cancel_both_ways(
    mcs: str, mono: str, rossharp_ros2_client: Path, tmp_path: Path
) -> None:
    exe = _build(mcs, rossharp_ros2_client, tmp_path / "src")
    with running(DOCK) as double:
        double.served["/dock_double"] = dock
        probe = start([mono, str(exe), double.url, "/dock_double", "/dock_cs"])
        try:
            # The double as a ROS 2 client of the C# server.
            assert double.wait_advertised("/dock_cs", TIMEOUT), probe.finish()
            first, succeeding = double.send_goal("/dock_cs", {"dock_id": "from-double"})
            succeeding.done.wait(TIMEOUT)
            second, cancelled = double.send_goal("/dock_cs", {"dock_id": "cancel-me"})
            cancelled.first_feedback.wait(TIMEOUT)
            double.cancel_goal("/dock_cs", second)
            cancelled.done.wait(TIMEOUT)
            # The C# client's three goals, the last one refused.
            probe.wait_for(lambda line: line.startswith("Error in ConsumeResultResponse"), TIMEOUT)
        finally:
            output = probe.finish()
        double.wait_unadvertised("/dock_cs", TIMEOUT)
    lines = output.splitlines()
    assert double.errors == [], f"{double.errors}\n{output}"

    # C# client -> the double's server.
    assert _values(lines, "client_sent") == [
        "/dock_double:0 alpha",
        "/dock_double:1 cancel-me",
        "/dock_double:3 reject-me",
    ], output
    goals = [m for m in double.received if m["op"] == "send_action_goal"]
    assert [(g["action_type"], g["feedback"], g["args"]) for g in goals] == [
        ("diffbot_msgs/action/Dock", True, {"dock_id": "alpha"}),
        ("diffbot_msgs/action/Dock", True, {"dock_id": "cancel-me"}),
        ("diffbot_msgs/action/Dock", True, {"dock_id": "reject-me"}),
    ]
    assert _values(lines, "client_feedback") == [
        "/dock_double:0 /dock_double 2.5",
        "/dock_double:0 /dock_double 1.25",
        "/dock_double:1 /dock_double 9.5",
    ], output
    # ROS#'s cancel names the goal by its send_action_goal id; the result of the cancelled goal
    # comes to that goal's result handler (the handler given to CancelActionGoalRequest is
    # never called: rosbridge sends nothing with the id ROS# registers it under).
    assert _values(lines, "client_cancel") == ["/dock_double:1"], output
    assert [m["id"] for m in double.received if m["op"] == "cancel_action_goal"] == [
        "/dock_double:1"
    ]
    assert _values(lines, "client_result") == [
        f"/dock_double:0 /dock_double {STATUS_SUCCEEDED} True True 87.5",
        f"/dock_double:1 /dock_double {STATUS_CANCELED} True False -1",
    ], output
    assert _values(lines, "client_cancel_response") == [], output
    # A refused goal: rosbridge's failure result carries a text as "values", which ROS# cannot
    # read into the result class; it writes this line and never calls the result handler.
    assert any(line.startswith("Error in ConsumeResultResponse: ") for line in lines), output

    # The double (a ROS 2 client) -> the C# server.
    assert _values(lines, "server_goal") == [
        f"{first} /dock_cs diffbot_msgs/action/Dock True from-double",
        f"{second} /dock_cs diffbot_msgs/action/Dock True cancel-me",
    ], output
    assert _values(lines, "server_cancel") == [f"{second} /dock_cs"], output
    assert succeeding.feedback == [{"distance_remaining": 3.5}]
    assert succeeding.result == {
        "values": {"docked": True, "battery": 42.25},
        "status": STATUS_SUCCEEDED,
        "result": True,
    }
    assert cancelled.feedback == [{"distance_remaining": 3.5}]
    assert cancelled.result == {
        "values": {"docked": False, "battery": -1.0},
        "status": STATUS_CANCELED,
        "result": True,
    }
    assert double.unadvertised == ["/dock_cs"]
    assert "Unhandled Exception" not in output
