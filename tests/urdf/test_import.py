"""The stage's entry point on real files: r2d2 as ROS#'s sample ships it, and a robot with the
Niryo gripper's STL meshes."""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest

from unityscaffold.errors import LocatedError
from unityscaffold.urdf import import_robot


def test_r2d2_imports_with_its_materials_and_collada_meshes(r2d2_urdf: Path) -> None:
    sample = r2d2_urdf.parent
    packages = {"urdf_tutorial": sample / "Urdf" / "file_server2" / "urdf_tutorial"}
    result = import_robot(r2d2_urdf, packages=packages, project=sample)
    assert list(result.files) == [
        f"Materials/{name}.mat" for name in ("Default", "black", "blue", "white")
    ]
    assert sorted(result.meshes) == [
        "package://urdf_tutorial/meshes/l_finger.dae",
        "package://urdf_tutorial/meshes/l_finger_tip.dae",
    ]
    assert len(result.objects.walk()) == 114
    plugin = result.objects.children[0].components[1]
    assert plugin.name == "UrdfPlugin" and "\r\n  <plugin" in str(plugin.field("PluginText"))


def test_stl_meshes_become_assets_beside_where_rossharp_puts_the_stl(
    niryo: Path, tmp_path: Path
) -> None:
    package = tmp_path / "project" / "niryo_one_description"
    (package / "meshes").mkdir(parents=True)
    for stem in ("G1_Rod", "G1_ServoHead"):
        shutil.copy(niryo / f"{stem}.STL", package / "meshes" / f"{stem}.STL")
    urdf = tmp_path / "project" / "gripper.urdf"
    urdf.write_text(
        '<robot name="gripper"><link name="base"><visual><geometry>'
        '<mesh filename="package://niryo_one_description/meshes/G1_ServoHead.STL"/>'
        "</geometry></visual><collision><geometry>"
        '<mesh filename="package://niryo_one_description/meshes/G1_Rod.STL"/>'
        "</geometry></collision></link></robot>",
        encoding="utf-8",
    )
    result = import_robot(urdf, packages={}, project=tmp_path / "project")
    assert list(result.files) == [
        "Materials/Default.mat",
        "niryo_one_description/meshes/G1_Rod_0.asset",
        "niryo_one_description/meshes/G1_ServoHead_0.asset",
    ]
    rod = result.files["niryo_one_description/meshes/G1_Rod_0.asset"]
    assert "  m_Name: G1_Rod_0\n" in rod
    names = [(depth, o.name) for depth, o in result.objects.walk()]
    assert names[2:] == [
        (1, "base"),
        (2, "Visuals"),
        (3, "unnamed"),
        (4, "G1_ServoHead"),
        (2, "Collisions"),
        (3, "unnamed"),
        (4, "G1_Rod"),
    ]


def test_a_missing_mesh_stops_the_import_with_its_location(tmp_path: Path) -> None:
    urdf = tmp_path / "r.urdf"
    urdf.write_text(
        '<robot name="r">\n<link name="a"><visual><geometry>\n'
        '<mesh filename="package://nowhere/m.stl"/></geometry></visual></link></robot>\n',
        encoding="utf-8",
    )
    with pytest.raises(LocatedError) as caught:
        import_robot(urdf, packages={}, project=tmp_path)
    assert caught.value.render().startswith(f"{urdf}:3:1: error: mesh 'package://nowhere/m.stl'")
