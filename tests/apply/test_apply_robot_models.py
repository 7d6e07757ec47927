"""The manifest's `robots` with mesh geometries: each an instance of our STL prefab or of the
copied COLLADA model, written with its files, idempotent, removed with the mesh, and what the
import cannot make as checked refused at its element with nothing written."""

from __future__ import annotations

from pathlib import Path

import pytest
from robot_helpers import (
    FINGER,
    MESH_MANIFEST,
    MESH_URDF,
    SCENE,
    apply,
    apply_refused,
    apply_writes_nothing,
    copy_meshes,
    init_project,
    meta_guid,
    prefab_instances,
)


@pytest.fixture
def project(tmp_path: Path) -> Path:
    root = init_project(tmp_path, {"ros/bot.urdf": MESH_URDF, "robot.yaml": MESH_MANIFEST})
    copy_meshes(root, ("G1_Rod.STL", "l_finger.dae", "l_finger_color.png"))
    return root


def instances(project: Path) -> dict[str, str]:
    """Each prefab instance's document by the path of the object it sits under (one visual and
    one collision a link here, so the paths are distinct)."""
    return dict(prefab_instances(project))


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
        name: meta_guid(folder / f"{name}.meta")
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
    apply_writes_nothing(project)
    assert apply(project, "--check").code == 0


def test_a_mesh_the_urdf_drops_leaves_no_instance_behind_and_comes_back(project: Path) -> None:
    assert apply(project).code == 0
    urdf = MESH_URDF.replace(
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
    (project / "ros/bot.urdf").write_text(MESH_URDF)
    assert apply(project).code == 0
    assert len(instances(project)) == 4 and "m_Name: Sphere" not in (project / SCENE).read_text()
    assert apply(project, "--check").code == 0


def test_a_model_the_import_cannot_make_as_checked_is_refused_and_nothing_written(
    project: Path,
) -> None:
    (project / "ros/desc/meshes/arm.fbx").write_text("; FBX 7.4.0 project file\n")
    urdf = MESH_URDF.replace(
        'meshes/l_finger.dae"/></geometry></visual>', 'meshes/arm.fbx"/></geometry></visual>'
    )
    (project / "ros/bot.urdf").write_text(urdf)
    run = apply_refused(project)
    assert "bot.urdf:7:" in run.err and "no Unity-written scene" in run.err
