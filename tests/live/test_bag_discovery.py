"""Discovery from recordings written with rosbags: ROS 1 .bag, ROS 2 .db3 and .mcap."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import pytest
from rosbags.rosbag1 import Writer as Writer1
from rosbags.rosbag2 import StoragePlugin
from rosbags.rosbag2 import Writer as Writer2
from rosbags.typesys import Stores, get_typestore

from tests.live.helpers_live import MANIFEST, assert_clean_failure, run_cli, snapshot
from unityscaffold.interfaces.identity_ros1 import Ros1Identity
from unityscaffold.interfaces.live import Direction, discover
from unityscaffold.interfaces.live.definitions import stage_definitions
from unityscaffold.interfaces.model import Dialect
from unityscaffold.interfaces.registry import Registry

SEP = "\n" + "=" * 80 + "\n"
# A custom ROS 2 type in the ros2msg form rosbag2 records: MSG names without /msg/.
READING2 = (
    "std_msgs/Header header\nSample[] samples  # custom, same package\n"
    "uint8 MODE_RUN=1\n"
    f"{SEP}MSG: std_msgs/Header\nbuiltin_interfaces/Time stamp\nstring frame_id\n"
    f"{SEP}MSG: builtin_interfaces/Time\nint32 sec\nuint32 nanosec\n"
    f"{SEP}MSG: scaffold_test_msgs/Sample\nfloat64 value\nstring unit\n"
)


def write_ros1_bag(path: Path, truth: dict[str, Any], *, md5: str | None = None) -> Path:
    # The reader only looks at connection records, so message payloads can be anything.
    with Writer1(path) as writer:
        for topic, kind in (
            ("/imu", "sensor_msgs/Imu"),
            ("/reading", "scaffold_test_msgs/Reading"),
        ):
            # rosbags names ROS 1 types pkg/msg/Type too, and writes them as pkg/Type.
            connection = writer.add_connection(
                topic,
                kind.replace("/", "/msg/"),
                msgdef=truth[kind]["definition"],
                md5sum=md5 or truth[kind]["md5sum"],
            )
            writer.write(connection, 1, b"\x00")
    return path


def write_ros2_bag(folder: Path, plugin: StoragePlugin) -> Path:
    store = get_typestore(Stores.ROS2_JAZZY)
    with Writer2(folder, version=9, storage_plugin=plugin) as writer:
        imu = writer.add_connection("/imu", "sensor_msgs/msg/Imu", typestore=store)
        reading = writer.add_connection(
            "/reading",
            "scaffold_test_msgs/msg/Reading",
            msgdef=READING2,
            rihs01="RIHS01_" + "0" * 64,
        )
        for connection in (imu, reading):
            writer.write(connection, 1, b"\x00\x01\x00\x00")
    suffix = ".db3" if plugin is StoragePlugin.SQLITE3 else ".mcap"
    return next(folder.glob(f"*{suffix}"))


def test_a_ros1_bag_gives_topics_and_verified_definitions(
    genmsg_truth: dict[str, Any], tmp_path: Path
) -> None:
    found = discover(bag=write_ros1_bag(tmp_path / "run.bag", genmsg_truth))
    assert found.dialect is Dialect.ROS1
    assert [(t.name, t.type, t.direction) for t in found.topics] == [
        ("/imu", "sensor_msgs/Imu", Direction.SUBSCRIBE),
        ("/reading", "scaffold_test_msgs/Reading", Direction.SUBSCRIBE),
    ]
    stage_definitions(found, tmp_path / "cache").commit()
    alone = Registry.load(
        Dialect.ROS1, [tmp_path / "cache"], use_environment=False, use_builtin=False
    )
    spec = alone.message("scaffold_test_msgs/Reading")
    assert Ros1Identity(alone).md5sum(spec) == genmsg_truth["scaffold_test_msgs/Reading"]["md5sum"]


def test_a_ros1_bag_with_an_actions_topics_gives_the_action_and_its_file(
    genmsg_truth: dict[str, Any], tmp_path: Path
) -> None:
    """All five topics of /move_base recorded: one action, whose .action file comes back from
    genmsg's full texts byte for byte as Debian installs it, verified by the recorded md5sums."""
    kinds = {
        "goal": "move_base_msgs/MoveBaseActionGoal",
        "cancel": "actionlib_msgs/GoalID",
        "status": "actionlib_msgs/GoalStatusArray",
        "feedback": "move_base_msgs/MoveBaseActionFeedback",
        "result": "move_base_msgs/MoveBaseActionResult",
    }
    with Writer1(tmp_path / "run.bag") as writer:
        for part, kind in kinds.items():
            connection = writer.add_connection(
                f"/move_base/{part}",
                kind.replace("/", "/msg/"),
                msgdef=genmsg_truth[kind]["definition"],
                md5sum=genmsg_truth[kind]["md5sum"],
            )
            writer.write(connection, 1, b"\x00")
    found = discover(bag=tmp_path / "run.bag")
    assert found.topics == ()
    assert [(a.name, a.type, a.role) for a in found.actions] == [
        ("/move_base", "move_base_msgs/action/MoveBase", "client")  # its status was recorded
    ]
    staged = stage_definitions(found, tmp_path / "cache")
    assert staged.warnings == []
    staged.commit()
    rebuilt = tmp_path / "cache" / "move_base_msgs" / "action" / "MoveBase.action"
    assert (
        rebuilt.read_bytes()
        == Path("/usr/share/move_base_msgs/action/MoveBase.action").read_bytes()
    )
    alone = Registry.load(
        Dialect.ROS1, [tmp_path / "cache"], use_environment=False, use_builtin=False
    )
    for kind in kinds.values():
        spec = alone.message(kind)
        assert Ros1Identity(alone).md5sum(spec) == genmsg_truth[kind]["md5sum"], kind


def test_a_ros1_bag_with_a_wrong_md5sum_names_the_type(
    genmsg_truth: dict[str, Any], tmp_path: Path
) -> None:
    bag = write_ros1_bag(tmp_path / "run.bag", genmsg_truth, md5="0" * 32)
    with pytest.raises(Exception, match="md5sum mismatch for sensor_msgs/Imu"):
        stage_definitions(discover(bag=bag), tmp_path / "cache")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["run.bag"]  # no cache, no staging


@pytest.mark.parametrize("plugin", [StoragePlugin.SQLITE3, StoragePlugin.MCAP])
def test_ros2_bags_give_topics_and_parsable_definitions(
    plugin: StoragePlugin, tmp_path: Path
) -> None:
    storage_file = write_ros2_bag(tmp_path / "rec", plugin)
    for source in (storage_file, tmp_path / "rec"):  # the storage file or the bag folder
        found = discover(bag=source)
        assert found.dialect is Dialect.ROS2
        assert [(t.name, t.type) for t in found.topics] == [
            ("/imu", "sensor_msgs/msg/Imu"),
            ("/reading", "scaffold_test_msgs/msg/Reading"),
        ]
    stage_definitions(found, tmp_path / "cache").commit()
    alone = Registry.load(
        Dialect.ROS2, [tmp_path / "cache"], use_environment=False, use_builtin=False
    )
    reading = alone.message("scaffold_test_msgs/msg/Reading")
    assert [f.type.base for f in reading.fields] == [
        "std_msgs/msg/Header",
        "scaffold_test_msgs/msg/Sample",
    ]
    assert [m.full_name for m in alone.closure([alone.message("sensor_msgs/msg/Imu")])] == [
        "builtin_interfaces/msg/Time",
        "geometry_msgs/msg/Quaternion",
        "geometry_msgs/msg/Vector3",
        "sensor_msgs/msg/Imu",
        "std_msgs/msg/Header",
    ]


def test_discover_from_a_bag_edits_the_manifest(
    genmsg_truth: dict[str, Any], tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    (tmp_path / "robot.yaml").write_text(MANIFEST)
    bag = write_ros1_bag(tmp_path / "run.bag", genmsg_truth)
    run = run_cli(capsys, "discover", str(tmp_path / "robot.yaml"), "--bag", str(bag))
    assert run.code == 0, run.err
    text = (tmp_path / "robot.yaml").read_text()
    assert text.count("name: /imu") == 1  # already listed
    assert "- {name: /reading, type: scaffold_test_msgs/Reading, direction: subscribe" in text


@pytest.mark.parametrize(
    ("name", "content"),
    [
        ("corrupt.bag", b"#ROSBAG V2.0\n" + b"\xff" * 64),
        ("corrupt.bag", b"not a bag at all"),
        ("corrupt.db3", b"SQLite format 3\x00" + b"\x00" * 80),
        ("corrupt.mcap", b"\x89MCAP0\r\n" + b"\x00" * 40),
        ("notes.txt", b"hello"),
    ],
)
def test_a_corrupt_bag_fails_cleanly(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], name: str, content: bytes
) -> None:
    (tmp_path / "robot.yaml").write_text(MANIFEST)
    (tmp_path / name).write_bytes(content)
    before = snapshot(tmp_path)
    run = run_cli(capsys, "discover", str(tmp_path / "robot.yaml"), "--bag", str(tmp_path / name))
    assert_clean_failure(run, tmp_path, before, "error: ")
    assert "bag" in run.err
