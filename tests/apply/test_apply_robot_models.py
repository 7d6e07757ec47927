"""The manifest's `robots` with mesh geometries: each an instance of our STL prefab or of the
copied COLLADA model, written with its files, idempotent, removed with the mesh, and what the
import cannot make as checked refused at its element with nothing written."""

from __future__ import annotations

import os
import re
import shutil
from pathlib import Path

import pytest
from helpers import build_tree, require, run_cli, snapshot

from unityscaffold.unity.scene import SceneDocument

REPO = Path(__file__).resolve().parents[2]
VENDOR = Path(os.environ.get("UNITYSCAFFOLD_VENDOR", REPO.parent / "shared" / "vendor"))
NIRYO = VENDOR / "unity-robotics-hub" / "niryo-gripper1"
FINGER = VENDOR / "ros-sharp/samples/gazebo-ros2-step1/Urdf/file_server2/urdf_tutorial/meshes"
SCENE = "Assets/Scenes/Main.unity"
MANIFEST = """\
version: 1
ros: 2
project: .
scene: Assets/Scenes/Main.unity
robots:
  - urdf: ros/bot.urdf
    packages: {desc: ros/desc}
    convex: true
"""
INERTIAL = (
    '<inertial><mass value="1"/>'
    '<inertia ixx="1" ixy="0" ixz="0" iyy="1" iyz="0" izz="1"/></inertial>'
)
URDF = f"""<robot name="bot">
  <link name="base">{INERTIAL}
    <visual><geometry><mesh filename="package://desc/meshes/G1_Rod.STL"/></geometry></visual>
    <collision><geometry><mesh filename="package://desc/meshes/G1_Rod.STL"/></geometry></collision>
  </link>
  <link name="finger">{INERTIAL}
    <visual><geometry><mesh filename="package://desc/meshes/l_finger.dae"/></geometry></visual>
    <collision><geometry><mesh filename="package://desc/meshes/l_finger.dae"/></geometry></collision>
  </link>
  <joint name="j" type="fixed"><parent link="base"/><child link="finger"/></joint>
</robot>
"""


@pytest.fixture
def project(tmp_path: Path) -> Path:
    require(
        (NIRYO / "G1_Rod.STL").is_file() and (FINGER / "l_finger.dae").is_file(),
        "the vendored meshes",
    )
    assert run_cli("init", str(tmp_path / "p"), "--ros", "2").code == 0
    root = build_tree(tmp_path / "p", {"ros/bot.urdf": URDF, "robot.yaml": MANIFEST})
    meshes = root / "ros/desc/meshes"
    meshes.mkdir(parents=True)
    shutil.copy(NIRYO / "G1_Rod.STL", meshes / "G1_Rod.STL")
    for name in ("l_finger.dae", "l_finger_color.png"):
        shutil.copy(FINGER / name, meshes / name)
    return root


def apply(project: Path, *extra: str):  # type: ignore[no-untyped-def]
    return run_cli("apply", str(project / "robot.yaml"), *extra)


def instances(project: Path) -> dict[str, str]:
    """Each prefab instance's document by the path of the object it sits under."""
    scene = SceneDocument.load(project / SCENE)
    found = {}
    for _, go in scene.tree():
        if go.is_prefab_instance:
            parent = scene.hierarchy.nodes[go.file_id].parent
            found[scene.gameobject(parent).path if parent else ""] = scene.document(go.file_id).text
    return found


def test_mesh_geometries_are_instances_of_the_stl_prefab_and_the_copied_model(
    project: Path,
) -> None:
    run = apply(project)
    assert run.code == 0, run.err
    folder = project / "Assets/Urdf/bot/desc/meshes"
    assert sorted(p.name for p in folder.iterdir()) == [
        "G1_Rod.prefab",
        "G1_Rod.prefab.meta",
        "G1_Rod_0.asset",
        "G1_Rod_0.asset.meta",
        "l_finger.dae",
        "l_finger.dae.meta",
        "l_finger_color.png",
        "l_finger_color.png.meta",
    ]
    assert (folder / "l_finger.dae").read_bytes() == (FINGER / "l_finger.dae").read_bytes()
    found = instances(project)
    assert sorted(found) == [
        "bot/base/Collisions/unnamed",
        "bot/base/Visuals/unnamed",
        "bot/base/finger/Collisions/unnamed",
        "bot/base/finger/Visuals/unnamed",
    ]
    guid = {
        name: re.search(r"guid: (\w+)", (folder / f"{name}.meta").read_text()).group(1)  # type: ignore[union-attr]
        for name in ("G1_Rod.prefab", "G1_Rod_0.asset", "l_finger.dae")
    }
    rod = found["bot/base/Collisions/unnamed"]
    assert f"m_SourcePrefab: {{fileID: 100100000, guid: {guid['G1_Rod.prefab']}, type: 3}}" in rod
    finger = found["bot/base/finger/Visuals/unnamed"]
    assert f"guid: {guid['l_finger.dae']}, type: 3}}" in finger and "value: l_finger\n" in finger
    text = (project / SCENE).read_text()
    # the colliders the collisions add: on the prefab's Mesh asset and the model's mesh, convex
    assert f"  m_Mesh: {{fileID: 4300000, guid: {guid['G1_Rod_0.asset']}, type: 2}}\n" in text
    assert (
        f"  m_Mesh: {{fileID: 1151293911155818299, guid: {guid['l_finger.dae']}, type: 3}}" in text
    )
    assert text.count("  m_Convex: 1\n") == 2 and text.count(" stripped\n") == 6
    before = snapshot(project)
    assert apply(project).code == 0 and snapshot(project) == before
    assert apply(project, "--check").code == 0


def test_a_mesh_the_urdf_drops_leaves_no_instance_behind_and_comes_back(project: Path) -> None:
    assert apply(project).code == 0
    urdf = URDF.replace(
        '<mesh filename="package://desc/meshes/l_finger.dae"/>', '<sphere radius="0.1"/>'
    )
    (project / "ros/bot.urdf").write_text(urdf)
    run = apply(project)
    assert run.code == 0, run.err
    assert sorted(instances(project)) == ["bot/base/Collisions/unnamed", "bot/base/Visuals/unnamed"]
    text = (project / SCENE).read_text()
    assert text.count("--- !u!1001 ") == 2 and text.count(" stripped\n") == 3
    assert "l_finger" not in text
    assert not (project / "Assets/Urdf/bot/desc/meshes/l_finger.dae").exists()
    # and back: the spheres go, the instances come again
    (project / "ros/bot.urdf").write_text(URDF)
    assert apply(project).code == 0
    assert len(instances(project)) == 4 and "m_Name: Sphere" not in (project / SCENE).read_text()
    assert apply(project, "--check").code == 0


def test_a_model_the_import_cannot_make_as_checked_is_refused_and_nothing_written(
    project: Path,
) -> None:
    (project / "ros/desc/meshes/arm.obj").write_text("o arm\n")
    urdf = URDF.replace(
        'meshes/l_finger.dae"/></geometry></visual>', 'meshes/arm.obj"/></geometry></visual>'
    )
    (project / "ros/bot.urdf").write_text(urdf)
    before = snapshot(project)
    run = apply(project)
    assert run.code == 2, run.out + run.err
    assert "bot.urdf:7:" in run.err and "models are not supported" in run.err
    assert snapshot(project) == before
