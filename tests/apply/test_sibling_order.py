"""``sibling_index`` on an object: its place among its parent's children (``m_Children``) or the
scene's roots (``SceneRoots`` in 2022.3 files, ``m_RootOrder`` in older ones), as the Hierarchy
window lists them. Set by apply, a move made in Unity is drift for ``--check``, and a second run
writes nothing; a place past the last sibling stops at its line and writes nothing."""

from __future__ import annotations

from pathlib import Path

import pytest
from helpers import run_cli, snapshot

from unityscaffold.unity import _fields as F
from unityscaffold.unity.scene import SceneDocument

DATA = Path(__file__).resolve().parents[1] / "data" / "unity"
HEADER = """\
version: 1
ros: 2
project: .
scene: Assets/Scenes/Main.unity
"""
ORDERED = """\
objects:
  - {path: Robot, sibling_index: 0}
  - {path: Robot/C}
  - {path: Robot/A, sibling_index: 2}
  - {path: Robot/B, sibling_index: 0}
  - {path: Main Camera, sibling_index: 3}
"""


@pytest.fixture
def project(tmp_path: Path) -> Path:
    root = tmp_path / "p"
    assert run_cli("init", str(root), "--ros", "2").code == 0
    return root


def _apply(project: Path, body: str, *extra: str):
    (project / "robot.yaml").write_text(HEADER + body)
    return run_cli("apply", *extra, str(project / "robot.yaml"))


def _scene_path(project: Path) -> Path:
    return project / "Assets" / "Scenes" / "Main.unity"


def _names(scene: SceneDocument, path: str | None = None) -> list[str]:
    listed = scene.roots() if path is None else scene.children(scene.find_gameobject(path))
    return [go.name for go in listed]


def test_objects_take_their_places_among_the_roots_and_their_siblings(project: Path) -> None:
    run = _apply(project, ORDERED)
    assert run.code == 0, run.err
    scene = SceneDocument.load(_scene_path(project))
    assert _names(scene) == ["Robot", "Directional Light", "RosConnector", "Main Camera"]
    assert _names(scene, "Robot") == ["B", "C", "A"]
    # The lists Unity reads the order from, in that order.
    roots = next(d for d in scene.documents() if d.type_name == "SceneRoots")
    transforms = [scene.find_gameobject(n).transform_id for n in _names(scene)]
    assert F.list_refs(roots, "m_Roots") == transforms
    robot = scene.document(scene.find_gameobject("Robot").transform_id or 0)
    assert robot is not None
    children = [scene.find_gameobject(f"Robot/{n}").transform_id for n in "BCA"]
    assert F.list_refs(robot, "m_Children") == children
    assert "  move Robot/B to sibling index 0 among the children of Robot" in run.out.splitlines()
    assert run_cli("apply", "--check", str(project / "robot.yaml")).code == 0
    again = _apply(project, ORDERED)
    assert again.out.endswith("wrote 0 files, removed 0\n"), again.out


def test_a_move_made_in_unity_is_drift_and_apply_puts_it_back(project: Path) -> None:
    assert _apply(project, ORDERED).code == 0
    path = _scene_path(project)
    placed = path.read_text()
    scene = SceneDocument.load(path)
    first, second = (scene.find_gameobject(n).transform_id for n in ("Robot", "Directional Light"))
    swapped = placed.replace(f"  - {{fileID: {first}}}\n", "@@").replace(
        f"  - {{fileID: {second}}}\n", f"  - {{fileID: {first}}}\n"
    )
    path.write_text(swapped.replace("@@", f"  - {{fileID: {second}}}\n"))
    check = run_cli("apply", "--check", str(project / "robot.yaml"))
    assert check.code == 1, check.out + check.err
    assert "move Robot to sibling index 0 among the scene's roots" in check.out
    assert _apply(project, ORDERED).code == 0
    assert path.read_text() == placed


def test_an_older_scene_numbers_its_roots_and_children_in_m_root_order(project: Path) -> None:
    # DemoScene.unity was saved by Unity 2020.3: m_RootOrder, no SceneRoots.
    demo = DATA / "unity-robotics-hub" / "DemoScene.unity"
    _scene_path(project).write_bytes(demo.read_bytes())
    body = """\
connector: {gameobject: Demo}
objects:
  - {path: Demo, sibling_index: 0}
  - {path: Demo/X}
  - {path: Demo/Y, sibling_index: 0}
"""
    run = _apply(project, body)
    assert run.code == 0, run.err
    scene = SceneDocument.load(_scene_path(project))
    assert _names(scene) == ["Demo", "Main Camera", "Directional Light"]
    assert _names(scene, "Demo") == ["Y", "X"]
    for path, order in [("Demo", 0), ("Main Camera", 1), ("Directional Light", 2)]:
        transform = scene.document(scene.find_gameobject(path).transform_id or 0)
        assert transform is not None and F.field_value(transform, "m_RootOrder") == str(order)
    for name, order in [("Y", 0), ("X", 1)]:
        transform = scene.document(scene.find_gameobject(f"Demo/{name}").transform_id or 0)
        assert transform is not None and F.field_value(transform, "m_RootOrder") == str(order)
    assert run_cli("apply", "--check", str(project / "robot.yaml")).code == 0


def test_a_place_past_the_last_sibling_stops_at_its_line_and_writes_nothing(
    project: Path,
) -> None:
    before = snapshot(project)
    run = _apply(project, "objects:\n  - {path: Robot}\n  - {path: Robot/A, sibling_index: 1}\n")
    assert run.code == 2, run.out
    assert "robot.yaml:7:" in run.err
    assert "sibling_index 1 is past the last sibling (the only one there is 0)" in run.err
    assert snapshot(project) == {**before, "robot.yaml": (project / "robot.yaml").read_bytes()}
