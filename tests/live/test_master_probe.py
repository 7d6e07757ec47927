"""Discovery from a real ROS 1 master and a rospy node, over XML-RPC and TCPROS."""

from __future__ import annotations

import time
from pathlib import Path

import pytest

from tests.live.helpers_live import Ros1System
from unityscaffold.errors import UserError
from unityscaffold.interfaces.identity_ros1 import Ros1Identity
from unityscaffold.interfaces.live import Direction, NameFilter, discover, list_live_types
from unityscaffold.interfaces.live.definitions import stage_definitions
from unityscaffold.interfaces.model import Dialect
from unityscaffold.interfaces.registry import Registry

FAST = 1.0


def test_master_discovery_finds_every_topic_and_service(ros1_system: Ros1System) -> None:
    found = discover(master_url=ros1_system.url, timeout=FAST)
    topics = {t.name: t for t in found.topics}
    assert found.dialect is Dialect.ROS1
    assert {"/chatter", "/imu", "/reading", "/cmd_vel", "/ghost"} <= topics.keys()
    assert "/rosout" not in topics  # plumbing is left out unless asked for
    truth = ros1_system.truth
    for name, kind in (
        ("/chatter", "std_msgs/String"),
        ("/imu", "sensor_msgs/Imu"),
        ("/reading", "scaffold_test_msgs/Reading"),
    ):
        assert topics[name].type == kind
        assert topics[name].md5 == truth[kind]["md5sum"]
        assert topics[name].definition == truth[kind]["definition"]
        assert topics[name].direction is Direction.SUBSCRIBE
    assert topics["/cmd_vel"].direction is Direction.PUBLISH
    assert topics["/cmd_vel"].definition is None  # nobody publishes it, so nobody can tell
    services = {s.name: s for s in found.services}
    assert services["/trigger"].type == "std_srvs/Trigger"
    assert services["/trigger"].md5 == truth["std_srvs/Trigger"]["md5sum"]
    assert services["/calibrate"].md5 == truth["scaffold_test_msgs/Calibrate"]["md5sum"]
    assert not any(name.endswith("/get_loggers") for name in services)


def test_a_node_that_never_answers_is_skipped_with_a_warning(ros1_system: Ros1System) -> None:
    started = time.monotonic()
    found = discover(master_url=ros1_system.url, timeout=0.5)
    assert time.monotonic() - started < 5
    ghost = next(t for t in found.topics if t.name == ros1_system.ghost_topic)
    assert ghost.definition is None and ghost.type == "std_msgs/Int32"
    assert any("/ghost" in w and "did not answer" in w for w in found.warnings)


def test_select_and_exclude_filter_before_probing(ros1_system: Ros1System) -> None:
    found = discover(
        master_url=ros1_system.url,
        timeout=FAST,
        names=NameFilter.of(select="^/(imu|reading|trigger)$", exclude="read"),
    )
    assert [t.name for t in found.topics] == ["/imu"]
    assert [s.name for s in found.services] == ["/trigger"]
    assert found.warnings == ()  # the silent /ghost node was never asked


def test_all_includes_system_topics(ros1_system: Ros1System) -> None:
    found = discover(
        master_url=ros1_system.url,
        timeout=FAST,
        names=NameFilter.of(select="rosout|get_loggers", include_system=True),
    )
    assert "/rosout" in {t.name for t in found.topics}
    assert any(s.name.endswith("/get_loggers") for s in found.services)


def test_live_types_lists_active_topics(ros1_system: Ros1System) -> None:
    listed = dict(list_live_types(ros1_system.url, timeout=FAST))
    assert listed["/imu"] == "sensor_msgs/Imu"
    assert listed["/reading"] == "scaffold_test_msgs/Reading"
    assert listed["/rosout"] == "rosgraph_msgs/Log"


def test_reconstructed_definitions_have_genmsg_md5sums(
    ros1_system: Ros1System, tmp_path: Path
) -> None:
    found = discover(master_url=ros1_system.url, timeout=FAST, names=NameFilter.of(exclude="ghost"))
    cache = tmp_path / "ros_definitions"
    staged = stage_definitions(found, cache)
    staged.commit()
    assert (cache / "scaffold_test_msgs" / "msg" / "Sample.msg").read_text() == (
        Path(__file__).parent / "data/scaffold_test_msgs/msg/Sample.msg"
    ).read_text()
    alone = Registry.load(Dialect.ROS1, [cache], use_environment=False, use_builtin=False)
    identity = Ros1Identity(alone)
    for kind in ("std_msgs/String", "sensor_msgs/Imu", "scaffold_test_msgs/Reading"):
        spec = alone.message(kind)
        assert identity.md5sum(spec) == ros1_system.truth[kind]["md5sum"]
        assert identity.full_text(spec) == ros1_system.truth[kind]["definition"]
    # The custom service's .srv never travels over the wire: ROS 1 only reports its md5.
    assert any("scaffold_test_msgs/Calibrate" in w for w in staged.warnings)


def test_a_custom_service_is_checked_against_a_local_srv(
    ros1_system: Ros1System, tmp_path: Path
) -> None:
    names = NameFilter.of(exclude="ghost|two_ints|served_by_unity")  # actions: see below
    found = discover(master_url=ros1_system.url, timeout=FAST, names=names)
    staged = stage_definitions(
        found, tmp_path / "cache", search_paths=[Path(__file__).parent / "data"]
    )
    staged.discard()
    assert staged.warnings == []


def test_actionlib_topic_sets_are_found_as_actions_with_unitys_role(
    ros1_system: Ros1System, tmp_path: Path
) -> None:
    found = discover(master_url=ros1_system.url, timeout=FAST, names=NameFilter.of(select="_"))
    actions = {a.name: (a.type, a.role) for a in found.actions}
    assert actions == {
        "/two_ints": ("actionlib/action/TwoInts", "client"),  # the node serves it
        "/served_by_unity": ("actionlib/action/Test", "server"),  # the node only sends goals
    }
    assert not [t.name for t in found.topics if t.name.startswith(tuple(actions))]
    two_ints = next(a for a in found.actions if a.name == "/two_ints")
    assert [t.name for t in two_ints.topics] == [
        f"/two_ints/{part}" for part in ("goal", "cancel", "status", "feedback", "result")
    ]
    # A master gives only what the node publishes: the node's server sends no goal text, its
    # client no result or feedback text, so neither action can be rebuilt from the wire ...
    staged = stage_definitions(found, tmp_path / "cache")
    staged.discard()
    assert sorted(w.split(" (")[0] for w in staged.warnings) == [
        "no definition of actionlib/action/Test",
        "no definition of actionlib/action/TwoInts",
    ]
    assert all("rosbridge" in w for w in staged.warnings)
    # ... and a local copy of actionlib's .action files is checked against the md5sums the
    # node reported for the topics it publishes (result, feedback, status; goal, cancel).
    local = Path(__file__).parent / "data" / "actionlib_ws"
    staged = stage_definitions(found, tmp_path / "cache", search_paths=[local])
    staged.discard()
    assert staged.warnings == []
    reported = {t.name for a in found.actions for t in a.topics if t.md5}
    assert reported == {
        "/two_ints/status",
        "/two_ints/feedback",
        "/two_ints/result",
        "/served_by_unity/goal",
        "/served_by_unity/cancel",
    }


def test_a_wrong_local_action_is_an_md5_mismatch(ros1_system: Ros1System, tmp_path: Path) -> None:
    local = tmp_path / "ws" / "actionlib"
    (local / "action").mkdir(parents=True)
    (local / "action" / "TwoInts.action").write_text("int64 a\nint64 b\n---\nint32 sum\n---\n")
    found = discover(
        master_url=ros1_system.url, timeout=FAST, names=NameFilter.of(select="two_ints")
    )
    with pytest.raises(UserError, match="md5sum mismatch for actionlib/TwoIntsActionResult"):
        stage_definitions(found, tmp_path / "cache", search_paths=[local.parent])


def test_unreachable_master_is_a_clear_error() -> None:
    from processes import free_port

    url = f"http://127.0.0.1:{free_port()}"
    with pytest.raises(UserError, match=f"no ROS master at {url} \\(connection refused\\)"):
        discover(master_url=url, timeout=FAST)
