"""``discover --rosbridge`` against the real rosbridge and its rosapi (ROS 1), with a rospy node
that publishes, subscribes to and serves standard types and the sample's custom ones
(data/discover_node.py). What the real server cannot do (malformed replies, a drop mid-call,
silence) stays with the fake in tests/live/test_rosbridge_discovery.py."""

from __future__ import annotations

import json
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest
from csharp import compile_applied_project
from helpers import SYSTEM_PYTHON, run_cli

from tests.runtime.bridge import DATA, Bridge
from tests.runtime.lines import start
from unityscaffold.interfaces.identity_ros1 import Ros1Identity
from unityscaffold.interfaces.live import Direction, NameFilter, discover, list_live_types
from unityscaffold.interfaces.live.definitions import stage_definitions
from unityscaffold.interfaces.model import Dialect, ServiceSpec
from unityscaffold.interfaces.registry import Registry

OURS = "^/(chatter|odom|base_status|undock/feedback|cmd_vel|trigger|set_speed_limit)$"
ACTIONS = "^/(charger/)?dock/"
ACTION_TOPICS = ("goal", "cancel", "status", "feedback", "result")


@pytest.fixture(scope="module")
def truth(bridge: Bridge) -> Iterator[dict[str, Any]]:
    """The node's genpy md5sums and full texts, while it runs."""
    node = start([str(SYSTEM_PYTHON), str(DATA / "discover_node.py")], env=bridge.env)
    try:
        # stderr comes in the same stream: the truth is the one line of JSON
        assert node.wait_for(lambda line: line.startswith("{"), 60), node.finish()
        yield json.loads(next(line for line in node.seen if line.startswith("{")))
    finally:
        node.finish()


def test_topics_types_directions_definitions_and_services(
    bridge: Bridge, truth: dict[str, Any]
) -> None:
    found = discover(rosbridge_url=bridge.url, timeout=5, names=NameFilter.of(select=OURS))
    assert found.dialect is Dialect.ROS1
    assert found.warnings == ()
    topics = {t.name: (t.type, t.direction) for t in found.topics}
    assert topics == {
        "/chatter": ("std_msgs/String", Direction.SUBSCRIBE),
        "/odom": ("nav_msgs/Odometry", Direction.SUBSCRIBE),
        "/base_status": ("diffbot_msgs/BaseStatus", Direction.SUBSCRIBE),
        "/undock/feedback": ("diffbot_msgs/DockActionFeedback", Direction.SUBSCRIBE),
        "/cmd_vel": ("geometry_msgs/Twist", Direction.PUBLISH),
    }
    # rosapi's full texts are genpy's, byte for byte.
    for topic in found.topics:
        assert topic.definition == truth[topic.type]["definition"], topic.name
    assert [(s.name, s.type) for s in found.services] == [
        ("/set_speed_limit", "diffbot_msgs/SetSpeedLimit"),
        ("/trigger", "std_srvs/Trigger"),
    ]
    # No .srv text crosses ROS 1: a type defined nowhere here (diffbot_msgs) is rebuilt from
    # rosapi's request and response details (fields only); std_srvs is left to its file.
    assert [s.definition for s in found.services] == [
        "float32 max_linear\n---\nbool success\nstring message\n",
        None,
    ]
    # Unfiltered: rosbridge's and rosapi's own topics and services are left out by default.
    everything = discover(rosbridge_url=bridge.url, timeout=5)
    assert set(topics) <= {t.name for t in everything.topics}
    assert not [s.name for s in everything.services if s.name.startswith("/rosapi")]
    assert ("/base_status", "diffbot_msgs/BaseStatus") in list_live_types(bridge.url, timeout=5)


def test_actionlib_topics_are_actions_rebuilt_with_genpy_md5sums(
    bridge: Bridge, truth: dict[str, Any], tmp_path: Path
) -> None:
    found = discover(rosbridge_url=bridge.url, timeout=5, names=NameFilter.of(select=ACTIONS))
    assert found.warnings == () and found.topics == ()
    # The node serves /dock (Unity is its client) and only sends goals on /charger/dock.
    assert [(a.name, a.type, a.role) for a in found.actions] == [
        ("/charger/dock", "diffbot_msgs/action/Dock", "server"),
        ("/dock", "diffbot_msgs/action/Dock", "client"),
    ]
    for action in found.actions:
        assert [t.name for t in action.topics] == [f"{action.name}/{t}" for t in ACTION_TOPICS]
        for topic in action.topics:  # rosapi sends every text, published or only subscribed
            assert topic.definition == truth[topic.type]["definition"], topic.name
    staged = stage_definitions(found, tmp_path / "cache")
    assert staged.warnings == []
    staged.commit()
    # The .action file comes back from the goal, result and feedback texts: its messages have
    # genpy's md5sums and full texts, from the cache alone.
    alone = Registry.load(
        Dialect.ROS1, [tmp_path / "cache"], use_environment=False, use_builtin=False
    )
    sample = Path(__file__).resolve().parents[2] / "sample_project" / "ros_ws" / "src"
    rebuilt = tmp_path / "cache" / "diffbot_msgs" / "action" / "Dock.action"
    original = sample / "diffbot_msgs" / "action" / "Dock.action"
    assert rebuilt.read_text() == original.read_text()
    identity = Ros1Identity(alone)
    for kind in ("DockActionGoal", "DockActionFeedback", "DockActionResult"):
        spec = alone.message(f"diffbot_msgs/{kind}")
        assert identity.md5sum(spec) == truth[f"diffbot_msgs/{kind}"]["md5sum"], kind
        assert identity.full_text(spec) == truth[f"diffbot_msgs/{kind}"]["definition"], kind
    assert not (tmp_path / "cache" / "diffbot_msgs" / "msg" / "DockActionGoal.msg").exists()


def test_staged_definitions_reproduce_genpy_md5sums(
    bridge: Bridge, truth: dict[str, Any], tmp_path: Path
) -> None:
    found = discover(rosbridge_url=bridge.url, timeout=5, names=NameFilter.of(select=OURS))
    stage_definitions(found, tmp_path / "cache").commit()
    alone = Registry.load(
        Dialect.ROS1, [tmp_path / "cache"], use_environment=False, use_builtin=False
    )
    identity = Ros1Identity(alone)
    for topic in found.topics:
        spec = alone.message(topic.type)
        assert identity.md5sum(spec) == truth[topic.type]["md5sum"], topic.type
        assert identity.full_text(spec) == truth[topic.type]["definition"], topic.type
    # Services: the one rebuilt from rosapi's details has the md5sum rospy serves it under,
    # from the cache alone; std_srvs/Trigger resolves from Debian's share with its md5sum.
    rebuilt = alone.get("diffbot_msgs/SetSpeedLimit")
    assert isinstance(rebuilt, ServiceSpec)
    assert identity.md5sum(rebuilt) == truth["diffbot_msgs/SetSpeedLimit"]["md5sum"]
    local = Registry.load(Dialect.ROS1, use_builtin=False)
    trigger = local.get("std_srvs/Trigger")
    assert isinstance(trigger, ServiceSpec)
    assert Ros1Identity(local).md5sum(trigger) == truth["std_srvs/Trigger"]["md5sum"]


def test_discover_then_apply_without_the_workspace(
    bridge: Bridge, truth: dict[str, Any], mcs: str, tmp_path: Path
) -> None:
    project = tmp_path / "robot_unity"
    assert run_cli("init", str(project), "--ros", "1").code == 0
    manifest = project / "robot.yaml"
    found = run_cli(
        "discover",
        str(manifest),
        "--rosbridge",
        bridge.url,
        "--timeout",
        "5",
        "--select",
        f"{OURS}|{ACTIONS}",
        "--progress",
    )
    assert found.code == 0, found.err
    assert "probing 17/17" in found.err  # 5 topics, 2 services, 2 actions of 5 topics
    text = manifest.read_text()
    assert "- {name: /cmd_vel, type: geometry_msgs/Twist, direction: publish" in text
    assert "- {name: /base_status, type: diffbot_msgs/BaseStatus, direction: subscribe" in text
    assert "- {name: /dock, type: diffbot_msgs/action/Dock, role: client" in text
    assert "- {name: /charger/dock, type: diffbot_msgs/action/Dock, role: server" in text
    applied = run_cli("apply", str(manifest), "--json")
    assert applied.code == 0, applied.err
    files = {entry["path"] for entry in json.loads(applied.out)["files"]}
    assert "Assets/RosGenerated/Messages/Diffbot/msg/BaseStatus.cs" in files
    assert "Assets/RosGenerated/Scripts/BaseStatusSubscriber.cs" in files
    assert "Assets/RosGenerated/Scripts/TriggerClient.cs" in files
    assert "Assets/RosGenerated/Scripts/SetSpeedLimitClient.cs" in files
    assert "Assets/RosGenerated/Scripts/DockActionClient.cs" in files
    assert "Assets/RosGenerated/Scripts/ChargerDockActionServer.cs" in files
    compile_applied_project(mcs, manifest, tmp_path / "build", ros2=False)
