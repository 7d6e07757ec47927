"""GameObjects known by identity: renamed or moved in "Unity" (the scene text edited as Unity
writes it), a GameObject apply made is never created a second time; apply and --check stop at
the manifest line to change, or --follow-renames rewrites that line. A component deleted in Unity
is re-created and reported. A lock from before fileIDs were recorded still works."""

from __future__ import annotations

import json
import re
from pathlib import Path

import pytest
from helpers import run_cli, snapshot

from unityscaffold.unity.scene import SceneDocument

MANIFEST = """\
version: 1
ros: 2
project: .
scene: Assets/Scenes/Main.unity
connector: {gameobject: RosConnector}
topics:
  - {name: /odom, type: nav_msgs/Odometry, direction: subscribe, gameobject: TurtleBot3,
     create: true}
  - {name: /scan, type: sensor_msgs/LaserScan, direction: subscribe,
     gameobject: TurtleBot3/Lidar, create: true}
components:
  - script: TwistSubscriber
    gameobject: TurtleBot3
    fields: {Topic: /cmd_vel, SubscribedTransform: "@TurtleBot3/Lidar"}
"""
ROBOT_LINE = 7  # the first line that names TurtleBot3 as an entry's gameobject


@pytest.fixture
def project(tmp_path: Path) -> Path:
    assert run_cli("init", str(tmp_path / "p"), "--ros", "2").code == 0
    root = tmp_path / "p"
    (root / "robot.yaml").write_text(MANIFEST)
    run = run_cli("apply", str(root / "robot.yaml"))
    assert run.code == 0, run.err
    return root


def _scene(project: Path) -> Path:
    return project / "Assets" / "Scenes" / "Main.unity"


def _rename(project: Path, old: str, new: str) -> None:
    """What Unity writes when a GameObject is renamed in the Hierarchy: its m_Name only."""
    path = _scene(project)
    pattern = rf"(?m)^  m_Name: {re.escape(old)}$"
    text, count = re.subn(pattern, f"  m_Name: {new}", path.read_text())
    assert count == 1
    path.write_text(text)


def _reparent(project: Path, child: str, parent: str) -> None:
    """What Unity writes when a root GameObject is dragged under another: the child's
    m_Father, the parent's m_Children and the scene's roots."""
    path = _scene(project)
    doc = SceneDocument.load(path)
    child_tr = doc.find_gameobject(child).transform_id
    parent_tr = doc.find_gameobject(parent).transform_id
    out = []
    for part in re.split(r"(?m)^(?=--- )", path.read_text()):
        if part.startswith(f"--- !u!4 &{child_tr}\n"):
            part = part.replace("m_Father: {fileID: 0}", f"m_Father: {{fileID: {parent_tr}}}")
        elif part.startswith(f"--- !u!4 &{parent_tr}\n"):
            part = part.replace("m_Children: []", f"m_Children:\n  - {{fileID: {child_tr}}}")
        elif part.startswith("--- !u!1660057539 "):
            part = part.replace(f"  - {{fileID: {child_tr}}}\n", "")
        out.append(part)
    path.write_text("".join(out))


def _gameobject_count(project: Path) -> int:
    return _scene(project).read_text().count("--- !u!1 &")


def test_a_renamed_gameobject_stops_apply_at_the_manifest_lines_and_nothing_is_written(
    project: Path,
) -> None:
    _rename(project, "TurtleBot3", "Burger")
    before = snapshot(project)
    run = run_cli("apply", str(project / "robot.yaml"))
    assert run.code == 2, run.out
    assert (
        f"robot.yaml:{ROBOT_LINE}:78: error: `TurtleBot3` is now `Burger` in Main.unity "
        "(renamed or moved in Unity since the last apply); rename it at robot.yaml:7, "
        "robot.yaml:13" in run.err
    )
    # The Lidar under it moved with it: its own line and the reference to it are named too.
    assert "`TurtleBot3/Lidar` is now `Burger/Lidar`" in run.err
    assert "rename it at robot.yaml:10, robot.yaml:14" in run.err
    assert "--follow-renames" in run.err
    assert snapshot(project) == before
    check = run_cli("apply", "--check", str(project / "robot.yaml"))
    assert check.code == 2 and "`TurtleBot3` is now `Burger`" in check.err


def test_a_gameobject_moved_under_another_stops_apply(project: Path) -> None:
    _reparent(project, "TurtleBot3", "RosConnector")
    before = snapshot(project)
    run = run_cli("apply", str(project / "robot.yaml"))
    assert run.code == 2
    assert "`TurtleBot3` is now `RosConnector/TurtleBot3` in Main.unity" in run.err
    assert snapshot(project) == before


@pytest.mark.parametrize("move", ["rename", "reparent"])
def test_follow_renames_rewrites_the_manifest_and_never_duplicates(
    project: Path, move: str
) -> None:
    if move == "rename":
        _rename(project, "TurtleBot3", "Burger")
        new = "Burger"
    else:
        _reparent(project, "TurtleBot3", "RosConnector")
        new = "RosConnector/TurtleBot3"
    objects = _gameobject_count(project)
    scene_before = _scene(project).read_text()
    run = run_cli("apply", "--follow-renames", str(project / "robot.yaml"))
    assert run.code == 0, run.err
    assert (
        f"note: `TurtleBot3` is now `{new}` in Main.unity: followed; robot.yaml:7, "
        "robot.yaml:13 take the new path" in run.out
    )
    assert _gameobject_count(project) == objects
    assert _scene(project).read_text() == scene_before  # everything is still in place
    manifest = (project / "robot.yaml").read_text()
    assert manifest == MANIFEST.replace("TurtleBot3", new)
    lock = json.loads((project / "robot.lock.json").read_text())
    assert set(lock["gameobjects"]["Assets/Scenes/Main.unity"]) == {
        "RosConnector",
        new,
        f"{new}/Lidar",
    } | ({"RosConnector"} if move == "reparent" else set())
    assert run_cli("apply", "--check", str(project / "robot.yaml")).code == 0
    again = run_cli("apply", str(project / "robot.yaml"))
    assert again.out.endswith("wrote 0 files, removed 0\n")


def test_a_renamed_gameobject_the_manifest_already_follows_is_used_as_it_is(
    project: Path,
) -> None:
    _rename(project, "TurtleBot3", "Burger")
    (project / "robot.yaml").write_text(MANIFEST.replace("TurtleBot3", "Burger"))
    objects = _gameobject_count(project)
    run = run_cli("apply", str(project / "robot.yaml"))
    assert run.code == 0, run.err
    assert _gameobject_count(project) == objects
    assert "scene Assets/Scenes/Main.unity" not in run.out  # no scene edit at all
    assert run_cli("apply", "--check", str(project / "robot.yaml")).code == 0


def test_a_component_deleted_in_unity_is_recreated_and_reported(project: Path) -> None:
    doc = SceneDocument.load(_scene(project))
    robot = doc.find_gameobject("TurtleBot3")
    odom = next(c for c in doc.components_of(robot) if c.script is not None)
    assert doc.remove_component(odom)
    doc.write()
    run = run_cli("apply", str(project / "robot.yaml"))
    assert run.code == 0, run.err
    assert "re-add OdomSubscriber to TurtleBot3 (removed in Unity since the last apply)" in run.out
    assert run_cli("apply", "--check", str(project / "robot.yaml")).code == 0


def test_a_lock_without_file_ids_still_works_and_the_next_apply_records_them(
    project: Path,
) -> None:
    lock_path = project / "robot.lock.json"
    current = json.loads(lock_path.read_text())
    old = {k: v for k, v in current.items() if k != "gameobjects"}
    old["components"] = [
        {k: v for k, v in c.items() if k != "file_id"} for c in current["components"]
    ]
    lock_path.write_text(json.dumps(old, indent=2) + "\n")
    scene = _scene(project).read_text()
    check = run_cli("apply", "--check", str(project / "robot.yaml"))
    assert check.code == 1 and "update  robot.lock.json" in check.out
    run = run_cli("apply", str(project / "robot.yaml"))
    assert run.code == 0, run.err
    assert _scene(project).read_text() == scene
    assert json.loads(lock_path.read_text()) == current


def test_a_component_the_manifest_drops_is_removed_by_file_id_after_a_rename(
    project: Path,
) -> None:
    _rename(project, "TurtleBot3", "Burger")
    dropped = MANIFEST.replace("TurtleBot3", "Burger").split("components:")[0]
    (project / "robot.yaml").write_text(dropped)
    run = run_cli("apply", str(project / "robot.yaml"))
    assert run.code == 0, run.err
    assert "remove component TwistSubscriber from TurtleBot3" in run.out
    assert "81c5dfb51482c2e47b602e8096d45712" not in _scene(project).read_text()


def _add_gameobjects(project: Path, path: str) -> None:
    """GameObjects made in Unity (each a GameObject + Transform, as Create Empty makes it)."""
    doc = SceneDocument.load(_scene(project))
    assert doc.ensure_gameobject(path, create=True)
    doc.write()


def _components(project: Path, path: str) -> list[str]:
    doc = SceneDocument.load(_scene(project))
    return [c.type_name for c in doc.components_of(doc.find_gameobject(path))]


def test_a_renamed_gameobject_whose_old_path_another_one_took_stops_apply_naming_both(
    project: Path,
) -> None:
    # Renamed in Unity, then a new TurtleBot3 (a re-imported robot, Lidar and all) beside it:
    # the recorded one, with the user's settings on its components, is still the one meant.
    _rename(project, "TurtleBot3", "Old")
    _add_gameobjects(project, "TurtleBot3/Lidar")
    before = snapshot(project)
    for flags in ([], ["--check"]):
        run = run_cli("apply", *flags, str(project / "robot.yaml"))
        assert run.code == 2, run.out
        assert (
            f"robot.yaml:{ROBOT_LINE}:78: error: `TurtleBot3` is now `Old` in Main.unity "
            "(renamed or moved in Unity since the last apply; another GameObject is at "
            "`TurtleBot3` now); rename it at robot.yaml:7, robot.yaml:13" in run.err
        )
        assert "`TurtleBot3/Lidar` is now `Old/Lidar`" in run.err
        assert snapshot(project) == before
    run = run_cli("apply", "--follow-renames", str(project / "robot.yaml"))
    assert run.code == 0, run.err
    assert "`TurtleBot3` is now `Old` in Main.unity: followed" in run.out
    assert (project / "robot.yaml").read_text() == MANIFEST.replace("TurtleBot3", "Old")
    # Nothing moved from one GameObject to the other: the scene is as the user left it.
    assert _scene(project).read_bytes() == before["Assets/Scenes/Main.unity"]
    assert _components(project, "TurtleBot3") == ["Transform"]
    assert _components(project, "TurtleBot3/Lidar") == ["Transform"]
    assert run_cli("apply", "--check", str(project / "robot.yaml")).code == 0


def test_two_same_named_siblings_are_told_apart_by_the_one_the_lock_recorded(
    project: Path,
) -> None:
    # A second TurtleBot3 with its own Lidar beside the one apply made.
    _add_gameobjects(project, "Copy/Lidar")
    _rename(project, "Copy", "TurtleBot3")
    scene = _scene(project).read_bytes()
    lock = (project / "robot.lock.json").read_bytes()
    assert run_cli("apply", "--check", str(project / "robot.yaml")).code == 0
    run = run_cli("apply", str(project / "robot.yaml"))
    assert run.code == 0, run.err
    assert run.out.endswith("wrote 0 files, removed 0\n")
    assert _scene(project).read_bytes() == scene
    assert (project / "robot.lock.json").read_bytes() == lock


def test_a_declared_object_renamed_in_unity_is_reported_at_its_path_and_followed(
    tmp_path: Path,
) -> None:
    assert run_cli("init", str(tmp_path / "p"), "--ros", "2").code == 0
    project = tmp_path / "p"
    manifest = project / "robot.yaml"
    declared = (
        "version: 1\nros: 2\nscene: Assets/Scenes/Main.unity\n"
        "objects:\n  - {path: Base, position: [0, 1, 0], components: [Rigidbody]}\n"
        "components:\n"
        '  - {script: UrdfInertial, gameobject: Part, fields: {_rigidbody: "@Base"}}\n'
    )
    manifest.write_text(declared)
    assert run_cli("apply", str(manifest)).code == 0
    _rename(project, "Base", "Chassis")
    run = run_cli("apply", str(manifest))
    assert run.code == 2
    assert "robot.yaml:5:12: error: `Base` is now `Chassis` in Main.unity" in run.err
    assert "rename it at robot.yaml:5, robot.yaml:7" in run.err
    objects = _gameobject_count(project)
    assert run_cli("apply", "--follow-renames", str(manifest)).code == 0
    assert manifest.read_text() == declared.replace("Base", "Chassis")
    assert _gameobject_count(project) == objects
    assert run_cli("apply", "--check", str(manifest)).code == 0


HEADER = "version: 1\nros: 2\nscene: Assets/Scenes/Main.unity\n"
ODOM = "topics:\n  - {name: /odom, type: nav_msgs/Odometry, direction: subscribe}\n"


@pytest.mark.parametrize(
    ("connector", "followed", "fix"),
    [
        # No `connector:` section: the RosConnector (and /odom on it) is at the default path.
        ("", "connector: {gameobject: Bridge}\n", "add `connector: {gameobject: Bridge}` to the"),
        (
            "connector:\n  url: ws://robot:9090\n",
            "connector:\n  gameobject: Bridge\n  url: ws://robot:9090\n",
            "add `gameobject: Bridge` under `connector:`",
        ),
        (
            "connector: {url: ws://robot:9090}\n",
            "connector: {gameobject: Bridge, url: ws://robot:9090}\n",
            "add `gameobject: Bridge` under `connector:`",
        ),
        # Written: /odom, with no gameobject of its own, follows with the connector's line.
        ("connector: {gameobject: RosConnector}\n", "connector: {gameobject: Bridge}\n", ""),
    ],
)
def test_a_renamed_rosconnector_the_manifest_leaves_at_its_default_is_followed_by_writing_it(
    tmp_path: Path, connector: str, followed: str, fix: str
) -> None:
    assert run_cli("init", str(tmp_path / "p"), "--ros", "2").code == 0
    project = tmp_path / "p"
    manifest = project / "robot.yaml"
    manifest.write_text(HEADER + connector + ODOM)
    assert run_cli("apply", str(manifest)).code == 0
    _rename(project, "RosConnector", "Bridge")
    scene = _scene(project).read_bytes()
    run = run_cli("apply", str(manifest))
    assert run.code == 2
    assert "`RosConnector` is now `Bridge` in Main.unity" in run.err
    if fix:
        assert f"so the RosConnector is looked for at its default `RosConnector`: {fix}" in run.err
        assert "apply --follow-renames adds it for you" in run.err
    else:
        assert "rename it at robot.yaml:4\n" in run.err  # the connector's line, not /odom's
    run = run_cli("apply", "--follow-renames", str(manifest))
    assert run.code == 0, run.err
    assert manifest.read_text() == HEADER + followed + ODOM
    assert _scene(project).read_bytes() == scene
    assert run_cli("apply", "--check", str(manifest)).code == 0


def test_an_entry_on_the_default_gameobject_in_another_scene_is_told_to_name_it(
    tmp_path: Path,
) -> None:
    assert run_cli("init", str(tmp_path / "p"), "--ros", "2").code == 0
    project = tmp_path / "p"
    other = project / "Assets" / "Scenes" / "Other.unity"
    other.write_bytes(_scene(project).read_bytes())
    manifest = project / "robot.yaml"
    manifest.write_text(
        HEADER + "topics:\n  - {name: /odom, type: nav_msgs/Odometry, direction: subscribe,\n"
        "     scene: Assets/Scenes/Other.unity}\n"
    )
    assert run_cli("apply", str(manifest)).code == 0
    other.write_text(other.read_text().replace("  m_Name: RosConnector\n", "  m_Name: Bridge\n"))
    before = snapshot(project)
    for flags in ([], ["--follow-renames"]):
        run = run_cli("apply", *flags, str(manifest))
        assert run.code == 2
        assert "robot.yaml:5:5: error: `RosConnector` is now `Bridge`" in run.err
        assert "add `gameobject: Bridge` to this entry" in run.err
        assert snapshot(project) == before
