"""The acceptance test of adopting a robot imported by hand: the COMPLETED scene of ROS#'s
"Gazebo Simulation Scenes ROS2" step 1 (r2d2 imported by ROS#'s importer in Unity 2022.3, then
edited by hand), in a project holding the sample's assets and their ``.meta`` files where the
importer put them, given the manifest the step-1 test applies to the start scene.

The robot is taken over, not imported a second time: its fileIDs and its assets' GUIDs are
kept, nothing in it is rewritten, and a second apply writes nothing.
"""

from __future__ import annotations

import difflib
import json
import shutil
from pathlib import Path

import pytest
from helpers import require, run_cli, snapshot
from test_apply_robots_r2d2 import ASSETS, COMPLETED, SCENE, STEP, _manifest

URDF_ASSETS = "Assets/Urdf/file_server2"


@pytest.fixture
def project(tmp_path: Path) -> Path:
    require(COMPLETED.is_file() and ASSETS.is_dir(), f"ROS#'s gazebo step-1 sample ({STEP})")
    project = tmp_path / "p"
    assert run_cli("init", str(project), "--ros", "2").code == 0
    shutil.copy(COMPLETED, project / SCENE)
    shutil.copytree(ASSETS, project / URDF_ASSETS)
    (project / "ros").mkdir()
    shutil.copy(STEP / "custom_r2d2.urdf", project / "ros/custom_r2d2.urdf")
    shutil.copytree(ASSETS / "urdf_tutorial", project / "ros/urdf_tutorial")
    (project / "robot.yaml").write_text(_manifest(), encoding="utf-8")
    return project


def test_the_hand_imported_r2d2_is_adopted_and_nothing_in_it_changes(project: Path) -> None:
    assets = snapshot(project / URDF_ASSETS)
    run = run_cli("apply", str(project / "robot.yaml"))
    assert run.code == 0, run.err
    assert "adopt robot r2d2, imported by hand (106 objects)" in run.out
    assert "(robot r2d2)" not in run.out  # no object of the robot updated
    assert "import robot" not in run.out
    ours = (project / SCENE).read_text(encoding="utf-8").splitlines()
    theirs = COMPLETED.read_text(encoding="utf-8").splitlines()
    changed = [
        line for line in difflib.unified_diff(theirs, ours, lineterm="", n=0) if line[:1] in "+-"
    ][2:]
    # the one change is the CameraPlane's `objects:` entry: [0, 0.6, 2.26] where Unity's
    # Inspector saved the float32 below 0.6
    assert changed == [
        "-  m_LocalPosition: {x: 0, y: 0.59999996, z: 2.26}",
        "+  m_LocalPosition: {x: 0, y: 0.6, z: 2.26}",
    ]
    # the assets sit where the import puts them: kept byte for byte, GUIDs and all
    assert snapshot(project / URDF_ASSETS) == assets
    lock = json.loads((project / "robot.lock.json").read_text())
    assert len(lock["adopted"][SCENE]["r2d2"]) == len(lock["robots"][SCENE]["r2d2"])
    assert run_cli("apply", str(project / "robot.yaml"), "--check").code == 0
    before = snapshot(project)
    again = run_cli("apply", str(project / "robot.yaml"))
    assert again.code == 0 and "wrote 0 files" in again.out, again.out
    assert snapshot(project) == before


def test_a_hand_imported_robot_whose_assets_are_elsewhere_is_refused(project: Path) -> None:
    manifest = project / "robot.yaml"
    manifest.write_text(
        manifest.read_text().replace("    assets: Assets/Urdf/file_server2\n", ""),
        encoding="utf-8",
    )
    before = snapshot(project)
    run = run_cli("apply", str(manifest))
    assert run.code == 2, run.out + run.err
    assert "robot.yaml:7:5: error: the robot imported by hand at 'r2d2'" in run.err
    assert (
        "is an instance of the asset 15265ff30491d0e4c83378cfb1d1583d, not of "
        "Assets/Urdf/r2d2/urdf_tutorial/meshes/l_finger.dae" in run.err
    )
    assert snapshot(project) == before


def test_what_adopting_changes_is_listed_with_the_keys_that_keep_hand_edits(
    project: Path,
) -> None:
    """Without the entry's pose and switches, the robot is put where its URDF and the entry
    say: the root to [0, 0, 0], the links' Rigidbodies to the importer's switches and the
    model colliders not convex, each listed."""
    manifest = project / "robot.yaml"
    text = manifest.read_text()
    for line in ("position: [0, 0.47, 0]", "kinematic: true", "gravity: false", "convex: true"):
        text = text.replace(f"    {line}\n", "")
    manifest.write_text(text, encoding="utf-8")
    run = run_cli("apply", str(manifest))
    assert run.code == 0, run.err
    changed = [line.strip() for line in run.out.splitlines() if "(robot r2d2)" in line]
    assert "update r2d2 (robot r2d2)" in changed
    assert sum(line.startswith("update --- !u!64 &") for line in changed) == 4
    # the switches left out are the importer's: each link's Rigidbody not kinematic, with gravity
    links = [line for line in changed if line.startswith("update r2d2/base_link")]
    assert len(links) == 16
    assert len(changed) == 5 + len(links)
    assert "note: adopting robot r2d2 changes what differs from its URDF and entry" in run.out
    again = run_cli("apply", str(manifest))
    assert again.code == 0 and "note:" not in again.out and "wrote 0 files" in again.out
