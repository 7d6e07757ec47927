"""The asset files a robot's import writes, seen from the rest of the manifest and from the
project's folders: an `objects:` entry may name them on the very apply that first writes them,
and the folders their pruning empties go with their `.meta` (Unity would otherwise recreate
an orphan folder's asset or warn about its `.meta`), unless a file of the user's is there."""

from __future__ import annotations

from pathlib import Path

import pytest
from robot_helpers import (
    NO_ROBOTS,
    apply,
    apply_manifest,
    apply_robot,
    apply_writes_nothing,
    copy_meshes,
    field,
    init_project,
    meta_guid,
)

URDF = """<robot name="bot">
  <material name="blue"><color rgba="0 0 0.8 1"/></material>
  <link name="base">
    <visual><geometry><box size="1 2 3"/></geometry><material name="blue"/></visual>
  </link>
</robot>
"""
MESH = '<mesh filename="package://desc/meshes/G1_Rod.STL"/>'
PLANE = (
    "objects:\n  - {path: bot/base/Screen, primitive: plane, components: [{type: MeshRenderer, "
    "fields: {m_Materials: [Assets/Urdf/bot/Materials/blue.mat]}}]}\n"
)


@pytest.fixture
def project(tmp_path: Path) -> Path:
    return init_project(tmp_path, {"ros/bot.urdf": URDF})


def _materials(project: Path, path: str) -> object:
    return field(project, path, "MeshRenderer", "m_Materials")


def test_an_object_names_a_robots_material_on_the_apply_that_first_writes_it(
    project: Path,
) -> None:
    run = apply_robot(project, PLANE)
    assert run.code == 0, run.err
    guid = meta_guid(project / "Assets/Urdf/bot/Materials/blue.mat.meta")
    wanted = [{"fileID": "2100000", "guid": guid, "type": "2"}]
    assert _materials(project, "bot/base/Screen") == wanted
    # the robot's own renderer names the same file
    assert _materials(project, "bot/base/Visuals/unnamed/Cube") == wanted
    again = apply_writes_nothing(project)
    assert "the project matches the manifest" in again.out, again.out


def _urdf_tree(project: Path) -> list[str]:
    """Everything under Assets/ that a robot's import may have made, folders and metas."""
    assets = project / "Assets"
    return sorted(
        p.relative_to(assets).as_posix() for p in assets.rglob("*") if "Urdf" in p.as_posix()
    )


@pytest.fixture
def mesh_project(project: Path) -> Path:
    copy_meshes(project, ("G1_Rod.STL",))
    collision = f"  <collision><geometry>{MESH}</geometry></collision>\n  </link>"
    (project / "ros/bot.urdf").write_text(URDF.replace("  </link>", collision))
    return project


PACKAGES = "    packages: {desc: ros/desc}\n"


def test_a_mesh_the_urdf_drops_takes_the_folders_it_emptied_and_their_metas(
    mesh_project: Path,
) -> None:
    assert apply_robot(mesh_project, PACKAGES).code == 0
    assert "Urdf/bot/desc/meshes.meta" in _urdf_tree(mesh_project)
    (mesh_project / "ros/bot.urdf").write_text(URDF)
    run = apply_robot(mesh_project, PACKAGES)
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
    assert apply_robot(mesh_project, PACKAGES, "--check").code == 0


def test_a_robot_removed_takes_its_folders_but_one_holding_a_users_file(
    mesh_project: Path,
) -> None:
    assert apply_robot(mesh_project, PACKAGES).code == 0
    mine = mesh_project / "Assets/Urdf/bot/desc/notes.txt"
    mine.write_text("mine\n")
    run = apply_manifest(mesh_project, NO_ROBOTS)
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
    assert apply(mesh_project, "--check").code == 1
    assert apply(mesh_project).code == 0
    assert _urdf_tree(mesh_project) == []
