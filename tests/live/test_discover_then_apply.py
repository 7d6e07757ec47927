"""Discovery's purpose end to end: from a running ROS 1 system to a wired Unity project whose
code compiles, without the robot's workspace (its custom types come from the cache alone)."""

from __future__ import annotations

import json
from pathlib import Path

from csharp import compile_applied_project
from helpers import run_cli


def test_discover_then_apply_generates_compiling_code_without_the_workspace(
    ros1_system, mcs: str, tmp_path: Path
) -> None:
    project = tmp_path / "robot_unity"
    assert run_cli("init", str(project), "--ros", "1").code == 0
    manifest = project / "robot.yaml"
    # The custom service's .srv text is never sent by ROS 1, nor all of an action's texts by a
    # master, so they are left out here (tests/runtime/test_discover.py applies an action
    # discovered through a rosbridge).
    found = run_cli(
        "discover",
        str(manifest),
        "--master",
        ros1_system.url,
        "--timeout",
        "2",
        "--exclude",
        "ghost|calibrate|two_ints|served_by_unity",
    )
    assert found.code == 0, found.err
    applied = run_cli("apply", str(manifest), "--json")
    assert applied.code == 0, applied.err
    files = {entry["path"] for entry in json.loads(applied.out)["files"]}
    assert "Assets/RosGenerated/Messages/ScaffoldTest/msg/Reading.cs" in files
    assert "Assets/RosGenerated/Scripts/ReadingSubscriber.cs" in files
    assert "Assets/RosGenerated/Scripts/ImuSubscriber.cs" in files
    assert run_cli("apply", "--check", str(manifest)).code == 0
    compile_applied_project(mcs, manifest, tmp_path / "build", ros2=False)
