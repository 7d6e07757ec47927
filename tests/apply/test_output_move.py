"""Changing ``output:`` moves what apply generated instead of refusing or duplicating it.

Scripts keep their ``.meta`` GUIDs (scenes refer to them by GUID, so every component stays
attached and the scene is not touched), user halves keep their content, and the old folder is
pruned with the folders it leaves empty and their ``.meta`` files.
"""

from __future__ import annotations

import shutil
from pathlib import Path

from helpers import run_cli

REPO = Path(__file__).resolve().parents[2]


def test_changing_output_moves_scripts_with_their_guids_and_code(tmp_path: Path) -> None:
    sample = tmp_path / "sample_project"
    shutil.copytree(REPO / "sample_project", sample)
    assets = sample / "unity" / "Assets"
    old = assets / "RosGenerated" / "Scripts"
    user_code = old / "OdomSubscriber.User.cs"
    user_code.write_text(user_code.read_text() + "// my code\n")
    metas = {p.name: p.read_text() for p in old.glob("*.meta")}
    scene = (assets / "Scenes" / "Main.unity").read_bytes()
    manifest = sample / "robot.yaml"
    manifest.write_text(
        manifest.read_text().replace("output: Assets/RosGenerated", "output: Assets/Ros/Gen2")
    )

    run = run_cli("apply", str(manifest))
    assert run.code == 0, run.out + run.err  # was: "would be named CmdVelPublisher, like ..."
    new = assets / "Ros" / "Gen2" / "Scripts"
    assert {p.name: p.read_text() for p in new.glob("*.meta")} == metas
    assert (new / "OdomSubscriber.User.cs").read_text().endswith("// my code\n")
    assert (assets / "Scenes" / "Main.unity").read_bytes() == scene
    assert sorted(p.name for p in assets.iterdir()) == ["Ros", "Ros.meta", "Scenes", "Scenes.meta"]
    check = run_cli("apply", "--check", str(manifest))
    assert check.code == 0, check.out + check.err


def test_moving_output_and_changing_a_type_at_once_is_done_in_one_apply(tmp_path: Path) -> None:
    """An untouched user half is made afresh for the new type where it moves to (it was moved
    as it was, so the next apply rewrote it: apply --check failed right after an apply); an
    edited one keeps its content, and is said to be written for the earlier type."""
    sample = tmp_path / "sample_project"
    shutil.copytree(REPO / "sample_project", sample)
    old = sample / "unity" / "Assets" / "RosGenerated" / "Scripts"
    edited = old / "OdomSubscriber.User.cs"
    edited.write_text(edited.read_text() + "// my code\n")
    manifest = sample / "robot.yaml"
    manifest.write_text(
        manifest.read_text()
        .replace("output: Assets/RosGenerated", "output: Assets/Gen")
        .replace("/cmd_vel, type: geometry_msgs/Twist", "/cmd_vel, type: std_msgs/String")
        .replace("/odom, type: nav_msgs/Odometry", "/odom, type: std_msgs/String")
    )
    run = run_cli("apply", str(manifest))
    assert run.code == 0, run.out + run.err
    new = sample / "unity" / "Assets" / "Gen" / "Scripts"
    assert "MessageTypes.Std.String message" in (new / "CmdVelPublisher.User.cs").read_text()
    assert (new / "OdomSubscriber.User.cs").read_text().endswith("// my code\n")
    assert "Assets/Gen/Scripts/OdomSubscriber.User.cs was written for an earlier version" in run.out
    assert "CmdVelPublisher.User.cs was written" not in run.out
    check = run_cli("apply", "--check", str(manifest))
    assert check.code == 0, check.out + check.err
