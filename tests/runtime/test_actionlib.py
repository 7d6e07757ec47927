"""ROS 1 actions over actionlib's topics (goal, cancel, status, feedback, result), with the
classes unityscaffold generates for the sample's diffbot_msgs/Dock and ROS#'s real RosSocket,
through a real rosbridge, against rospy's own SimpleActionServer and SimpleActionClient
(Debian's python3-actionlib): C# client -> rospy server and rospy client -> C# server, each
with a goal that succeeds and one that is cancelled (csharp/ActionlibProbe.cs,
data/action_node.py)."""

from __future__ import annotations

import json
from pathlib import Path

from helpers import SYSTEM_PYTHON

from tests.runtime.bridge import DATA, Bridge
from tests.runtime.client import CSHARP, mcs_compile
from tests.runtime.lines import Lines, start
from tests.runtime.runtime_helpers import ros1_registry, write_code
from unityscaffold.codegen import Options, generate
from unityscaffold.interfaces.model import Dialect

TIMEOUT = 60  # seconds; a guard against a hang only
# actionlib_msgs/GoalStatus
PREEMPTED, SUCCEEDED = 2, 3


def _build(mcs: str, client: Path, out: Path) -> Path:
    registry = ros1_registry()
    code = generate(registry, [registry.get("diffbot_msgs/action/Dock")], Options(Dialect.ROS1))
    folder = client.parent
    exe = folder / "ActionlibProbe.exe"
    mcs_compile(
        mcs,
        [CSHARP / "ActionlibProbe.cs", *write_code(code, out)],
        exe,
        references=[client, folder / "Newtonsoft.Json.dll", folder / "websocket-sharp.dll"],
        target="exe",
    )
    return exe


def _values(lines: list[str], key: str) -> list[str]:
    return [line.split(" ", 1)[1] for line in lines if line.startswith(key + " ")]


def test_actionlib_goals_feedback_results_and_cancel_both_ways(
    actionlib_python: None,
    bridge: Bridge,
    mcs: str,
    mono: str,
    rossharp_client: Path,
    tmp_path: Path,
) -> None:
    exe = _build(mcs, rossharp_client, tmp_path / "src")
    result = tmp_path / "node.json"
    node_argv = [str(SYSTEM_PYTHON), str(DATA / "action_node.py"), "/dock_py", "/dock_cs"]
    node = start([*node_argv, str(result), str(TIMEOUT)], bridge.env)
    probe: Lines | None = None
    try:
        assert node.wait_for(lambda line: line == "ready", TIMEOUT), node.finish()
        probe = start([mono, str(exe), bridge.url, "/dock_py", "/dock_cs"])
        node.wait_for(lambda line: line == "done", TIMEOUT + 30)
        probe.wait_for(lambda line: line.startswith("client_result cs-goal-2 "), TIMEOUT)
    finally:
        node_output = node.finish()
        probe_output = probe.finish() if probe else ""
    assert result.exists(), node_output
    seen = json.loads(result.read_text())
    output = f"{node_output}\n--- C#:\n{probe_output}"
    lines = probe_output.splitlines()

    # C# client -> rospy SimpleActionServer.
    assert seen["server"] == [
        {"dock_id": "alpha", "goal_id": "cs-goal-1", "stamp_nonzero": True},
        {
            "dock_id": "cancel-me",
            "goal_id": "cs-goal-2",
            "stamp_nonzero": True,
            "preempt_seen": True,
        },
    ], output
    assert _values(lines, "client_feedback") == [
        "cs-goal-1 1 2.5",
        "cs-goal-1 1 1.25",
        "cs-goal-2 1 9.5",
    ], output
    assert _values(lines, "client_result") == [
        f"cs-goal-1 {SUCCEEDED} True 87.5 docked at alpha",
        f"cs-goal-2 {PREEMPTED} False -1 preempted",
    ], output

    # rospy SimpleActionClient -> C# server.
    client = seen["client"]
    assert client["server_found"], output
    assert client["from-rospy"] == {
        "finished": True,
        "state": SUCCEEDED,
        "text": "docked at from-rospy",
        "result": [True, 42.25],
    }, output
    assert client["cancel-me"] == {
        "finished": True,
        "state": PREEMPTED,
        "text": "cancelled",
        "result": [False, -1.0],
    }, output
    # Each goal's feedback (status ACTIVE, 3.5 m), as it came on the topic.
    assert client["feedback"] == {"from-rospy": [[1, 3.5]], "cancel-me": [[1, 3.5]]}, output
    assert "Unhandled Exception" not in probe_output
