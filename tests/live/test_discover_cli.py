"""``scaffold discover`` end to end against a real ROS 1 master, and its clean failures."""

from __future__ import annotations

import difflib
import json
import subprocess
from pathlib import Path

import pytest
from processes import free_port

from tests.live.helpers_live import (
    MANIFEST,
    Ros1System,
    assert_clean_failure,
    run_cli,
    snapshot,
)
from unityscaffold.interfaces.identity_ros1 import Ros1Identity
from unityscaffold.interfaces.model import Dialect
from unityscaffold.interfaces.registry import Registry

# With the silent /ghost excluded every node answers, so a generous limit costs nothing; at
# 1 s a loaded machine sometimes missed the rospy node's answer, and its topics' definitions
# were then skipped with a warning (run twice, the second run fetched what the first missed).
NODE_TIMEOUT = "10"


@pytest.fixture()
def project(tmp_path: Path) -> Path:
    (tmp_path / "robot.yaml").write_text(MANIFEST)
    return tmp_path


def test_discover_fills_manifest_and_cache_from_a_live_master(
    ros1_system: Ros1System, project: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    manifest = project / "robot.yaml"
    run = run_cli(
        capsys,
        "discover",
        str(manifest),
        "--master",
        ros1_system.url,
        "--timeout",
        NODE_TIMEOUT,
        "--exclude",
        "ghost",
    )
    assert run.code == 0, run.err
    text = manifest.read_text()
    kept = [
        line
        for line in difflib.ndiff(MANIFEST.splitlines(), text.splitlines())
        if line.startswith("- ")
    ]
    assert kept == ["- services: []"], "every other line of the manifest is kept"
    assert "# hand-written" in text and text.count("name: /imu") == 1
    for line in (
        "- {name: /chatter, type: std_msgs/String, direction: subscribe, gameobject: RosConnector}",
        "- {name: /cmd_vel, type: geometry_msgs/Twist, direction: publish, "
        "gameobject: RosConnector}",
        "- {name: /reading, type: scaffold_test_msgs/Reading, direction: subscribe, "
        "gameobject: RosConnector}",
        "- {name: /calibrate, type: scaffold_test_msgs/Calibrate, role: client, "
        "gameobject: RosConnector}",
        "- {name: /trigger, type: std_srvs/Trigger, role: client, gameobject: RosConnector}",
        "interfaces:\n  - ros_definitions\n",
        # actionlib's five topics under a name are one action, with Unity's role in it.
        "actions:\n  - {name: /served_by_unity, type: actionlib/action/Test, role: server, "
        "gameobject: RosConnector}\n  - {name: /two_ints, type: actionlib/action/TwoInts, "
        "role: client, gameobject: RosConnector}\n",
    ):
        assert line in text
    assert "/two_ints/" not in text and "/served_by_unity/" not in text
    assert "found 4 topics, 2 services and 2 actions" in run.out
    assert "added 3 topics, 2 services and 2 actions" in run.out
    # The custom .srv cannot come over the wire; the user is told, and nothing fails.
    assert "warning: no definition of scaffold_test_msgs/Calibrate" in run.err
    cached_types_resolve_alone_with_genmsg_md5(project / "ros_definitions", ros1_system)


def cached_types_resolve_alone_with_genmsg_md5(cache: Path, system: Ros1System) -> None:
    """What `scaffold apply` needs: every discovered message resolves from the cache alone,
    without the test package's folder or Debian's, with genmsg's md5sum."""
    alone = Registry.load(Dialect.ROS1, [cache], use_environment=False, use_builtin=False)
    identity = Ros1Identity(alone)
    for kind in ("std_msgs/String", "sensor_msgs/Imu", "scaffold_test_msgs/Reading"):
        spec = alone.message(kind)
        assert identity.md5sum(spec) == system.truth[kind]["md5sum"], kind
        assert [m.full_name for m in alone.closure([spec])]  # the whole closure is there


def test_discovering_twice_changes_nothing(
    ros1_system: Ros1System, project: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    args = (
        "discover",
        str(project / "robot.yaml"),
        "--master",
        ros1_system.url,
        "--timeout",
        NODE_TIMEOUT,
        "--exclude",
        "ghost",
    )
    assert run_cli(capsys, *args).code == 0
    before = snapshot(project)
    again = run_cli(capsys, *args)
    assert again.code == 0
    assert "added 0 topics, 0 services and 0 actions" in again.out
    assert snapshot(project) == before


def test_print_and_json_leave_the_manifest_alone(
    ros1_system: Ros1System, project: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    manifest = project / "robot.yaml"
    run = run_cli(
        capsys,
        "discover",
        str(manifest),
        "--master",
        ros1_system.url,
        "--timeout",
        "1",
        "--select",
        "^/(imu|reading)$",
        "--print",
        "--json",
    )
    assert run.code == 0, run.err
    document = json.loads(run.out)
    assert [t["name"] for t in document["topics"]] == ["/imu", "/reading"]
    assert (
        document["topics"][1]["md5sum"] == ros1_system.truth["scaffold_test_msgs/Reading"]["md5sum"]
    )
    assert "- {name: /reading, type: scaffold_test_msgs/Reading" in document["fragment"]
    assert manifest.read_text() == MANIFEST
    assert (project / "ros_definitions/scaffold_test_msgs/msg/Reading.msg").is_file()


def test_dry_run_writes_nothing(
    ros1_system: Ros1System, project: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    before = snapshot(project)
    run = run_cli(
        capsys,
        "discover",
        str(project / "robot.yaml"),
        "--master",
        ros1_system.url,
        "--timeout",
        NODE_TIMEOUT,
        "--exclude",
        "ghost",
        "--dry-run",
    )
    assert run.code == 0, run.err
    assert "would add" in run.out
    assert snapshot(project) == before


def test_unreachable_master_fails_cleanly(
    project: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    before = snapshot(project)
    url = f"http://127.0.0.1:{free_port()}"
    run = run_cli(capsys, "discover", str(project / "robot.yaml"), "--master", url)
    assert_clean_failure(
        run, project, before, f"error: no ROS master at {url} (connection refused)"
    )


def test_a_wrong_ros_version_fails_before_writing(
    ros1_system: Ros1System, project: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    manifest = project / "robot.yaml"
    manifest.write_text(MANIFEST.replace("ros: 1 ", "ros: 2 "))
    before = snapshot(project)
    run = run_cli(
        capsys,
        "discover",
        str(manifest),
        "--master",
        ros1_system.url,
        "--timeout",
        NODE_TIMEOUT,
        "--exclude",
        "ghost",
    )
    assert_clean_failure(run, project, before, "the manifest is for ROS 2")


@pytest.mark.parametrize(
    ("args", "message"),
    [
        ((), "give exactly one source"),
        (("--master", "http://a:1", "--bag", "x.bag"), "give exactly one source"),
        (("--master", "ws://127.0.0.1:1"), "not a ROS master URL"),
        (("--rosbridge", "http://127.0.0.1:1"), "not a rosbridge URL"),
        (("--bag", "missing.bag"), "bag not found"),
        (("--master", "http://127.0.0.1:1", "--select", "("), "not a valid regular expression"),
    ],
)
def test_bad_arguments_are_user_errors(
    project: Path, capsys: pytest.CaptureFixture[str], args: tuple[str, ...], message: str
) -> None:
    before = snapshot(project)
    run = run_cli(capsys, "discover", str(project / "robot.yaml"), *args)
    assert_clean_failure(run, project, before, message)


def test_a_missing_manifest_is_reported(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    run = run_cli(
        capsys,
        "discover",
        str(tmp_path / "robot.yaml"),
        "--master",
        f"http://127.0.0.1:{free_port()}",
    )
    assert_clean_failure(run, tmp_path, {}, "manifest not found")


def test_discovered_definitions_generate_compiling_csharp(
    ros1_system: Ros1System, project: Path, mcs: str, capsys: pytest.CaptureFixture[str]
) -> None:
    """The point of discovery: C# for the robot's types without its workspace. The custom
    package's folder is on no search path; its types come from the cache alone."""
    from csharp import MCS_FLAGS, ROSSHARP_STUB

    run = run_cli(
        capsys,
        "discover",
        str(project / "robot.yaml"),
        "--master",
        ros1_system.url,
        "--timeout",
        NODE_TIMEOUT,
        "--exclude",
        "ghost",
    )
    assert run.code == 0, run.err
    out = project / "Generated"
    gen = run_cli(
        capsys,
        "msgs",
        "gen",
        "--ros",
        "1",
        "--path",
        str(project / "ros_definitions"),
        "--include-shipped",
        "--out",
        str(out),
        "scaffold_test_msgs/Reading",
        "sensor_msgs/Imu",
        "std_msgs/String",
        "geometry_msgs/Twist",
        "actionlib_msgs/GoalStatusArray",
    )  # the ROS# stub's action classes use these
    assert gen.code == 0, gen.err
    sources = sorted(out.rglob("*.cs"))
    assert any(p.name == "Reading.cs" for p in sources)
    done = subprocess.run(
        [mcs, *MCS_FLAGS, f"-out:{project / 'robot.dll'}", str(ROSSHARP_STUB), *map(str, sources)],
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert done.returncode == 0, done.stdout + done.stderr
