"""A `robots` entry whose GameObject the scene already has, not made by apply: a robot imported
by hand in Unity's editor, or an object that is no robot at all."""

from __future__ import annotations

from pathlib import Path

import pytest
from helpers import build_tree, run_cli, snapshot
from test_apply_robots import HEADER, SCENE, URDF

from unityscaffold.unity.catalog import rossharp_catalog
from unityscaffold.unity.scene import SceneDocument


@pytest.fixture
def project(tmp_path: Path) -> Path:
    assert run_cli("init", str(tmp_path / "p"), "--ros", "2").code == 0
    return build_tree(tmp_path / "p", {"ros/bot.urdf": URDF})


def _by_hand(project: Path, path: str, class_name: str) -> None:
    """``class_name`` of ROS# attached to ``path`` as a user would in the Inspector."""
    guid = next(g for g, name in rossharp_catalog().all_class_names().items() if name == class_name)
    run = run_cli("scene", "attach", str(project / SCENE), "-g", path, "--guid", guid, "--create")
    assert run.code == 0, run.err


def test_a_robot_imported_by_hand_is_refused_at_its_entry_and_nothing_is_written(
    project: Path,
) -> None:
    _by_hand(project, "bot", "UrdfRobot")
    (project / "robot.yaml").write_text(HEADER)
    before = snapshot(project)
    run = run_cli("apply", str(project / "robot.yaml"))
    assert run.code == 2, run.out + run.err
    assert (
        "robot.yaml:6:5: error: Assets/Scenes/Main.unity already has a GameObject 'bot' with a "
        "UrdfRobot component, imported by hand (apply did not make it)" in run.err
    )
    assert "hint: apply does not take over a robot imported in Unity's editor" in run.err
    assert snapshot(project) == before


def test_an_object_that_is_no_robot_where_the_robot_goes_is_refused(project: Path) -> None:
    (project / "robot.yaml").write_text(HEADER + "    gameobject: Main Camera\n")
    before = snapshot(project)
    run = run_cli("apply", str(project / "robot.yaml"))
    assert run.code == 2, run.out + run.err
    assert (
        "robot.yaml:7:17: error: Assets/Scenes/Main.unity already has a GameObject "
        "'Main Camera' (Transform, Camera, AudioListener), which is not a robot" in run.err
    )
    assert "hint: rename or move that GameObject in Unity" in run.err
    assert snapshot(project) == before


def test_a_robot_under_an_object_of_its_name_is_refused_only_there(project: Path) -> None:
    """Only the robot's own place counts: a same-named object elsewhere is another path."""
    _by_hand(project, "World/bot", "UrdfLink")
    (project / "robot.yaml").write_text(HEADER + "    gameobject: World/bot\n")
    run = run_cli("apply", str(project / "robot.yaml"))
    assert run.code == 2 and "'World/bot' (Transform, UrdfLink), which is not a robot" in run.err
    (project / "robot.yaml").write_text(HEADER)
    run = run_cli("apply", str(project / "robot.yaml"))
    assert run.code == 0, run.err


def test_a_robot_apply_made_is_its_own_even_without_the_lock(project: Path) -> None:
    (project / "robot.yaml").write_text(HEADER)
    assert run_cli("apply", str(project / "robot.yaml")).code == 0
    (project / "robot.lock.json").unlink()
    scene = (project / SCENE).read_bytes()
    run = run_cli("apply", str(project / "robot.yaml"))
    assert run.code == 0, run.err
    assert (project / SCENE).read_bytes() == scene


def test_the_robots_root_takes_the_name_its_gameobject_path_gives(project: Path) -> None:
    body = (
        "    gameobject: World/Robot\n"
        "components:\n  - {script: JointStateWriter, gameobject: World/Robot/base/arm}\n"
    )
    (project / "robot.yaml").write_text(HEADER + body)
    run = run_cli("apply", str(project / "robot.yaml"))
    assert run.code == 0, run.err
    scene = SceneDocument.load(project / SCENE)
    assert scene.find_gameobject("World/Robot").name == "Robot"
    assert [go.name for go in scene.children(scene.find_gameobject("World"))] == ["Robot"]
    before = snapshot(project)
    assert run_cli("apply", str(project / "robot.yaml")).code == 0
    assert snapshot(project) == before
