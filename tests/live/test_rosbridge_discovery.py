"""Discovery through rosbridge's rosapi when the bridge misbehaves, against a protocol-faithful
fake: malformed or empty replies, failures, silence, a drop mid-call, what the real server
cannot be made to do. What a working rosbridge gives (topics, directions, definitions, services,
md5sums, the manifest edit) is tested against the real one in tests/runtime/test_discover.py."""

from __future__ import annotations

import socket
import time
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest
from processes import free_port

from tests.live.fake_rosbridge import FakeRosbridge, running
from tests.live.helpers_live import MANIFEST, assert_clean_failure, run_cli, snapshot
from unityscaffold.errors import UserError
from unityscaffold.interfaces.identity_ros1 import Ros1Identity
from unityscaffold.interfaces.live import Direction, NameFilter, discover
from unityscaffold.interfaces.live.definitions import stage_definitions
from unityscaffold.interfaces.model import Dialect
from unityscaffold.interfaces.registry import Registry

FAST = 0.5


@pytest.fixture()
def bridge(genmsg_truth: dict[str, Any]) -> Iterator[FakeRosbridge]:
    with running(genmsg_truth) as fake:
        yield fake


def test_empty_full_texts_fall_back_to_message_details(
    bridge: FakeRosbridge, tmp_path: Path
) -> None:
    bridge.faults["/rosapi/topics_and_raw_types"] = "empty_text"
    found = discover(
        rosbridge_url=bridge.url,
        timeout=FAST,
        names=NameFilter.of(select="^/(imu|chatter|reading)$"),
    )
    assert "/rosapi/message_details" in bridge.calls
    # Reading has constants, whose types rosapi does not give: refused, not guessed.
    assert any("cannot rebuild scaffold_test_msgs/Reading" in w for w in found.warnings)
    stage_definitions(found, tmp_path / "cache").commit()
    alone = Registry.load(
        Dialect.ROS1, [tmp_path / "cache"], use_environment=False, use_builtin=False
    )
    imu = alone.message("sensor_msgs/Imu")
    assert Ros1Identity(alone).md5sum(imu) == bridge.truth["sensor_msgs/Imu"]["md5sum"]


def test_service_definitions_are_rebuilt_from_request_and_response_details(
    bridge: FakeRosbridge, tmp_path: Path
) -> None:
    found = discover(
        rosbridge_url=bridge.url, timeout=FAST, names=NameFilter.of(select="^/(calibrate|trigger)$")
    )
    assert found.warnings == ()
    # std_srvs/Trigger is defined locally (the built-in set): its file is left to that.
    assert bridge.calls.count("/rosapi/service_request_details") == 1
    calibrate = next(s for s in found.services if s.name == "/calibrate")
    assert (
        calibrate.definition
        == "float64 gain\nscaffold_test_msgs/Sample reference\n---\nbool success\nstring message\n"
    )
    stage_definitions(found, tmp_path / "cache").commit()
    alone = Registry.load(
        Dialect.ROS1, [tmp_path / "cache"], use_environment=False, use_builtin=False
    )
    spec = alone.get("scaffold_test_msgs/Calibrate")
    assert (
        Ros1Identity(alone).md5sum(spec) == bridge.truth["scaffold_test_msgs/Calibrate"]["md5sum"]
    )


def test_a_failing_details_call_is_a_warning_and_ends_the_asking(
    bridge: FakeRosbridge,
) -> None:
    bridge.faults["/rosapi/topics_and_raw_types"] = "empty_text"
    bridge.faults["/rosapi/message_details"] = "fail"
    found = discover(
        rosbridge_url=bridge.url,
        timeout=FAST,
        names=NameFilter.of(select="^/(imu|chatter|calibrate)$"),
    )
    assert bridge.calls.count("/rosapi/message_details") == 1
    assert "/rosapi/service_request_details" not in bridge.calls
    assert [t.definition for t in found.topics] == [None, None]
    assert found.services[0].definition is None
    assert len(found.warnings) == 3
    assert any("not asked, rosapi failed before" in w and "Calibrate" in w for w in found.warnings)


def test_unknown_directions_are_a_warning_not_an_error(bridge: FakeRosbridge) -> None:
    bridge.faults["/rosapi/publishers"] = "fail"
    found = discover(rosbridge_url=bridge.url, timeout=FAST)
    assert {t.direction for t in found.topics} == {Direction.UNKNOWN}
    assert bridge.calls.count("/rosapi/publishers") == 1  # asked once, then given up
    assert len(found.warnings) == 1


@pytest.mark.parametrize(
    ("service", "fault", "message"),
    [
        (
            "/rosapi/topics_and_raw_types",
            "silent",
            "rosbridge at {url} did not answer /rosapi/topics_and_raw_types within 0.5 s",
        ),
        (
            "/rosapi/topics_and_raw_types",
            "drop",
            "rosbridge at {url} closed the connection while "
            "/rosapi/topics_and_raw_types was pending",
        ),
        (
            "/rosapi/topics_and_raw_types",
            "fail",
            "rosbridge at {url}: /rosapi/topics_and_raw_types failed: service call failed",
        ),
        (
            "/rosapi/topics_and_raw_types",
            "status",
            "rosbridge at {url} reported an error for /rosapi/topics_and_raw_types: Service",
        ),
        (
            "/rosapi/topics_and_raw_types",
            "not_json",
            "rosbridge at {url} sent a malformed reply to /rosapi/topics_and_raw_types: not JSON",
        ),
        (
            "/rosapi/topics_and_raw_types",
            "bad_shape",
            "malformed reply to /rosapi/topics_and_raw_types: topics is not a list of strings",
        ),
        ("/rosapi/services", "silent", "did not answer /rosapi/services within 0.5 s"),
        ("/rosapi/service_type", "bad_shape", "malformed reply to /rosapi/service_type"),
    ],
)
def test_misbehaving_bridges_are_clear_errors(
    bridge: FakeRosbridge, service: str, fault: str, message: str
) -> None:
    bridge.faults[service] = fault
    started = time.monotonic()
    with pytest.raises(UserError) as caught:
        discover(rosbridge_url=bridge.url, timeout=FAST)
    assert message.format(url=bridge.url) in caught.value.message
    assert time.monotonic() - started < 3


def test_a_server_that_is_not_a_websocket_is_a_clear_error() -> None:
    with socket.socket() as silent:  # accepts TCP, never completes the WebSocket handshake
        silent.bind(("127.0.0.1", 0))
        silent.listen(1)
        url = f"ws://127.0.0.1:{silent.getsockname()[1]}"
        with pytest.raises(UserError, match="did not accept a WebSocket connection within"):
            discover(rosbridge_url=url, timeout=FAST)


def test_unreachable_rosbridge_fails_cleanly(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    (tmp_path / "robot.yaml").write_text(MANIFEST)
    before = snapshot(tmp_path)
    url = f"ws://127.0.0.1:{free_port()}"
    run = run_cli(capsys, "discover", str(tmp_path / "robot.yaml"), "--rosbridge", url)
    assert_clean_failure(
        run, tmp_path, before, f"error: no rosbridge at {url} (connection refused)"
    )


def test_a_bridge_that_drops_mid_discovery_leaves_everything_untouched(
    bridge: FakeRosbridge, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    (tmp_path / "robot.yaml").write_text(MANIFEST)
    before = snapshot(tmp_path)
    bridge.faults["/rosapi/service_type"] = "drop"
    run = run_cli(
        capsys,
        "discover",
        str(tmp_path / "robot.yaml"),
        "--rosbridge",
        bridge.url,
        "--timeout",
        "0.5",
    )
    assert_clean_failure(
        run, tmp_path, before, "closed the connection while /rosapi/service_type was pending"
    )
