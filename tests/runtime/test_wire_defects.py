"""What does not survive the trip between ROS#'s client and rosbridge (ROS 1, 0.11), reproduced
with both real components, so that a change on either side shows here. What the tool does about
each is said per test; the README's "Known limitations on the wire" names them for users.

rospy publishes, ROS#'s client (Newtonsoft) echoes the object it received, rospy compares. Each
run waits a few seconds for answers that never come, so the cases share runs where they can.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import pytest

from tests.runtime.bridge import Bridge
from tests.runtime.runtime_helpers import build_echo, ros1_registry, round_trip

NO_ANSWER = "no answer"
LONG = "0.7704962251833261"  # a double whose shortest exact form has 17 digits


def _run(
    bridge: Bridge,
    mcs: str,
    mono: str,
    client: Path,
    work: Path,
    entries: list[dict[str, Any]],
    *,
    seed: int,
    namespace: str | None = None,
) -> dict[str, str | None]:
    registry = ros1_registry()
    roots = [registry.message(name) for name in sorted({e["type"] for e in entries})]
    echo = build_echo(mcs, client, registry, roots, work / f"Defects{seed}", namespace=namespace)
    return round_trip(bridge, mono, echo, entries, work / "run", seed=seed, timeout=5).results


def _string(key: str, text: str, message: str = "std_msgs/String") -> dict[str, Any]:
    field = "frame_id" if message == "std_msgs/Header" else "data"
    return {"key": key, "type": message, "set": {field: {"string": text}}}


NEGATIVE_DURATION = {
    "key": "negative duration",
    "type": "trajectory_msgs/JointTrajectoryPoint",
    "set": {"time_from_start": {"duration": [-2, 500000000]}},
}


def test_time_messages_need_our_classes_and_negative_durations_are_lost(
    bridge: Bridge, mcs: str, mono: str, rossharp_client: Path, tmp_path: Path
) -> None:
    entries = [
        {"key": "std_msgs/Time", "type": "std_msgs/Time"},
        {"key": "std_msgs/Duration", "type": "std_msgs/Duration"},
        NEGATIVE_DURATION,
    ]
    # ROS#'s Std.Time/Std.Duration are the bare {secs, nsecs}: rosbridge refuses what C# sends
    # ("Message type std_msgs/Time does not have a field secs"). apply refuses these types
    # unless a root namespace is set (tests/apply/test_apply_errors.py) ...
    with_rossharp = _run(bridge, mcs, mono, rossharp_client, tmp_path / "a", entries, seed=101)
    assert with_rossharp == {name: NO_ANSWER for name in with_rossharp}
    assert len(with_rossharp) == 3
    # ... where our classes of the right shape ({data: {secs, nsecs}}) round-trip. A negative
    # ROS 1 duration still does not: ROS#'s Std.Duration has uint secs (README limitation).
    ours = _run(
        bridge, mcs, mono, rossharp_client, tmp_path / "b", entries, seed=102, namespace="Wire"
    )
    assert ours == {
        "std_msgs/Time": None,
        "std_msgs/Duration": None,
        "negative duration": NO_ANSWER,
    }


def test_values_rossharp_changes(
    bridge: Bridge, mcs: str, mono: str, rossharp_client: Path, tmp_path: Path
) -> None:
    entries = [
        _string("non-ASCII", "Grüße, 東京"),
        _string("ISO timestamp", "2024-05-01T12:00:00+02:00"),
        _string("newline", "a\nb"),
        _string("tab", "a\tb"),
        _string("backslash", "a\\b"),
        {"key": "NaN", "type": "geometry_msgs/Vector3", "set": {"x": {"float": "nan"}}},
        {"key": "-inf", "type": "geometry_msgs/Vector3", "set": {"y": {"float": "-inf"}}},
        {"key": "17 digits", "type": "geometry_msgs/Point", "set": {"z": {"float": LONG}}},
    ]
    results = _run(bridge, mcs, mono, rossharp_client, tmp_path, entries, seed=103)
    assert results == {
        # Newtonsoft writes UTF-8 text, ROS#'s serializer encodes it as ASCII.
        "non-ASCII": ".data: got 'Gr??e, ??', sent 'Grüße, 東京'",
        # ROS# parses what it receives into a JObject, which reads dates and writes them as UTC.
        "ISO timestamp": ".data: got '2024-05-01T10:00:00+00:00', sent '2024-05-01T12:00:00+02:00'",
        # ROS# sends binary frames; rosbridge 0.11 reads them with str(bytes), which doubles
        # every backslash of the JSON escapes.
        "newline": ".data: got 'a\\\\nb', sent 'a\\nb'",
        "tab": ".data: got 'a\\\\tb', sent 'a\\tb'",
        "backslash": ".data: got 'a\\\\\\\\b', sent 'a\\\\b'",
        # rosbridge writes NaN/Infinity, which JSON lacks; the message never reaches C#.
        "NaN": NO_ANSWER,
        "-inf": NO_ANSWER,
        # Newtonsoft writes doubles with "R", which Mono's class library shortens to 15 digits
        # when those parse back to a value close enough (not to the same one).
        "17 digits": f".z: got 0.770496225183326, sent {LONG}",
    }


@pytest.mark.parametrize("text", ['say "hi"', "it's"], ids=["quote", "apostrophe"])
def test_a_quote_breaks_everything_the_client_sends_after_it(
    bridge: Bridge, mcs: str, mono: str, rossharp_client: Path, tmp_path: Path, text: str
) -> None:
    # str(bytes) turns the JSON's \" into \\" and a ' into \': the message is not JSON. rosbridge
    # keeps it in its input buffer, finds an inner object without "op" in it, and from then on
    # never parses another message from this client: the clean one sent 2 s later is lost too.
    entries = [
        _string("quote", text, "std_msgs/Header"),
        {**_string("after", "clean"), "delay": 2},
    ]
    seed = 104 if "'" in text else 105
    results = _run(bridge, mcs, mono, rossharp_client, tmp_path, entries, seed=seed)
    assert results == {"quote": NO_ANSWER, "after": NO_ANSWER}
