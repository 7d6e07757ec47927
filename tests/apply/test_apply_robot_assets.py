"""The asset files a robot's import writes, seen from the rest of the manifest and from the
project's folders: an `objects:` entry may name them on the very apply that first writes them,
and the folders their pruning empties go with their `.meta` (Unity would otherwise recreate
an orphan folder's asset or warn about its `.meta`), unless a file of the user's is there."""

from __future__ import annotations

import os
import shutil
from pathlib import Path

import pytest
from helpers import build_tree, require, run_cli, snapshot

from unityscaffold.unity.scene import SceneDocument

HEADER = """\
version: 1
ros: 2
project: .
scene: Assets/Scenes/Main.unity
robots:
  - urdf: ros/bot.urdf
"""
URDF = """<robot name="bot">
  <material name="blue"><color rgba="0 0 0.8 1"/></material>
  <link name="base">
    <visual><geometry><box size="1 2 3"/></geometry><material name="blue"/></visual>
  </link>
</robot>
"""
SCENE = "Assets/Scenes/Main.unity"
REPO = Path(__file__).resolve().parents[2]
VENDOR = Path(os.environ.get("UNITYSCAFFOLD_VENDOR", REPO.parent / "shared" / "vendor"))
ROD = VENDOR / "unity-robotics-hub" / "niryo-gripper1" / "G1_Rod.STL"
MESH = '<mesh filename="package://desc/meshes/G1_Rod.STL"/>'
PLANE = (
    "objects:\n  - {path: bot/base/Screen, primitive: plane, components: [{type: MeshRenderer, "
    "fields: {m_Materials: [Assets/Urdf/bot/Materials/blue.mat]}}]}\n"
)


@pytest.fixture
def project(tmp_path: Path) -> Path:
    assert run_cli("init", str(tmp_path / "p"), "--ros", "2").code == 0
    return build_tree(tmp_path / "p", {"ros/bot.urdf": URDF})


def _apply(project: Path, body: str = "", *extra: str):  # type: ignore[no-untyped-def]
    (project / "robot.yaml").write_text(HEADER + body)
    return run_cli("apply", str(project / "robot.yaml"), *extra)


def _materials(project: Path, path: str) -> object:
    scene = SceneDocument.load(project / SCENE)
    renderer = next(
        c for c in scene.components_of(scene.find_gameobject(path)) if c.type_name == "MeshRenderer"
    )
    return scene.field(renderer, "m_Materials")


def test_an_object_names_a_robots_material_on_the_apply_that_first_writes_it(
    project: Path,
) -> None:
    run = _apply(project, PLANE)
    assert run.code == 0, run.err
    meta = (project / "Assets/Urdf/bot/Materials/blue.mat.meta").read_text()
    guid = meta.split("guid: ")[1].split()[0]
    wanted = [{"fileID": "2100000", "guid": guid, "type": "2"}]
    assert _materials(project, "bot/base/Screen") == wanted
    # the robot's own renderer names the same file
    assert _materials(project, "bot/base/Visuals/unnamed/Cube") == wanted
    before = snapshot(project)
    again = _apply(project, PLANE)
    assert again.code == 0 and "the project matches the manifest" in again.out, again.out
    assert snapshot(project) == before


def _urdf_tree(project: Path) -> list[str]:
    """Everything under Assets/ that a robot's import may have made, folders and metas."""
    assets = project / "Assets"
    return sorted(
        p.relative_to(assets).as_posix() for p in assets.rglob("*") if "Urdf" in p.as_posix()
    )


@pytest.fixture
def mesh_project(project: Path) -> Path:
    require(ROD.is_file(), "the Niryo gripper's STL file")
    (project / "ros/desc/meshes").mkdir(parents=True)
    shutil.copy(ROD, project / "ros/desc/meshes/G1_Rod.STL")
    collision = f"  <collision><geometry>{MESH}</geometry></collision>\n  </link>"
    (project / "ros/bot.urdf").write_text(URDF.replace("  </link>", collision))
    return project


PACKAGES = "    packages: {desc: ros/desc}\n"


def test_a_mesh_the_urdf_drops_takes_the_folders_it_emptied_and_their_metas(
    mesh_project: Path,
) -> None:
    assert _apply(mesh_project, PACKAGES).code == 0
    assert "Urdf/bot/desc/meshes.meta" in _urdf_tree(mesh_project)
    (mesh_project / "ros/bot.urdf").write_text(URDF)
    run = _apply(mesh_project, PACKAGES)
    assert run.code == 0, run.err
    assert _urdf_tree(mesh_project) == [
        "Urdf",
        "Urdf.meta",
        "Urdf/bot",
        "Urdf/bot.meta",
        "Urdf/bot/Materials",
        "Urdf/bot/Materials.meta",
        "Urdf/bot/Materials/Default.mat",
        "Urdf/bot/Materials/Default.mat.meta",
        "Urdf/bot/Materials/blue.mat",
        "Urdf/bot/Materials/blue.mat.meta",
    ]
    assert _apply(mesh_project, PACKAGES, "--check").code == 0


def test_a_robot_removed_takes_its_folders_but_one_holding_a_users_file(
    mesh_project: Path,
) -> None:
    assert _apply(mesh_project, PACKAGES).code == 0
    mine = mesh_project / "Assets/Urdf/bot/desc/notes.txt"
    mine.write_text("mine\n")
    (mesh_project / "robot.yaml").write_text(HEADER.split("robots:")[0])
    run = run_cli("apply", str(mesh_project / "robot.yaml"))
    assert run.code == 0, run.err
    assert _urdf_tree(mesh_project) == [
        "Urdf",
        "Urdf.meta",
        "Urdf/bot",
        "Urdf/bot.meta",
        "Urdf/bot/desc",
        "Urdf/bot/desc.meta",
        "Urdf/bot/desc/notes.txt",
    ]
    mine.unlink()
    # once the user's file is gone, the next apply clears what it held up
    assert run_cli("apply", str(mesh_project / "robot.yaml"), "--check").code == 1
    assert run_cli("apply", str(mesh_project / "robot.yaml")).code == 0
    assert _urdf_tree(mesh_project) == []
