"""A mesh named by a `file://` URI (what `file://$(find desc)/…` becomes once xacro expands it,
common in ROS 2 descriptions), an absolute path or a path relative to the URDF, inside one of
the robot's packages, makes the project `package://desc/…` makes: the same assets, GUIDs and
scene. ROS# 2.2.1 reads only `package://` (`UrdfAssetPathHandler.
GetRelativeAssetPathFromUrdfPath`), whose asset path is the package and the path inside it;
these forms are taken as the package's own name for the file."""

from __future__ import annotations

import importlib.util
from pathlib import Path

import pytest
from helpers import require, snapshot
from robot_helpers import (
    MESH_MANIFEST,
    MESH_URDF,
    ROBOTS,
    apply,
    apply_manifest,
    apply_refused,
    apply_writes_nothing,
    copy_meshes,
    init_project,
)

PACKAGE_FORM = 'filename="package://desc/meshes/'


@pytest.fixture
def project(tmp_path: Path) -> Path:
    root = init_project(tmp_path, {"ros/bot.urdf": MESH_URDF, "robot.yaml": MESH_MANIFEST})
    copy_meshes(root, ("G1_Rod.STL", "l_finger.dae", "l_finger_color.png"))
    assert apply(root).code == 0
    return root


@pytest.mark.parametrize(
    "prefix",
    [
        'filename="file://{root}/ros/desc/meshes/',  # file://$(find desc)/meshes/…, expanded
        'filename="file://localhost{root}/ros/desc/meshes/',
        'filename="{root}/ros/desc/meshes/',
        'filename="desc/meshes/',  # relative to ros/bot.urdf
    ],
)
def test_a_mesh_named_by_where_it_is_changes_nothing(project: Path, prefix: str) -> None:
    named = prefix.format(root=project.resolve().as_posix())
    (project / "ros/bot.urdf").write_text(MESH_URDF.replace(PACKAGE_FORM, named))
    apply_writes_nothing(project)
    assert apply(project, "--check").code == 0


def test_a_xacros_file_find_meshes_make_the_project_package_uris_make(project: Path) -> None:
    require(importlib.util.find_spec("xacro"), "xacro (the `xacro` extra)")
    imported = snapshot(project)
    xacro = MESH_URDF.replace(
        '<robot name="bot">', '<robot name="bot" xmlns:xacro="http://www.ros.org/wiki/xacro">'
    ).replace(PACKAGE_FORM, 'filename="file://$(find desc)/meshes/')
    (project / "ros/bot.urdf.xacro").write_text(xacro)
    manifest = MESH_MANIFEST.replace("ros/bot.urdf", "ros/bot.urdf.xacro")
    assert apply_manifest(project, manifest).code == 0
    ignored = {"robot.yaml", "ros/bot.urdf.xacro"}
    assert {k: v for k, v in snapshot(project).items() if k not in ignored} == {
        k: v for k, v in imported.items() if k not in ignored
    }
    apply_writes_nothing(project)


def test_a_mesh_outside_every_package_is_refused_at_its_line(project: Path) -> None:
    # meshes/ beside ros/: neither in package desc nor a package folder beside the URDF
    (project / "meshes").mkdir()
    (project / "ros/desc/meshes/G1_Rod.STL").rename(project / "meshes/G1_Rod.STL")
    (project / "ros/bot.urdf").write_text(
        MESH_URDF.replace(f"{PACKAGE_FORM}G1_Rod.STL", 'filename="../meshes/G1_Rod.STL')
    )
    run = apply_refused(
        project, ROBOTS + "  - urdf: ros/bot.urdf\n    packages: {desc: ros/desc}\n"
    )
    # line 3, column 23: the first <mesh> (MESH_URDF's line 3); line 4, column 26: the second
    assert (
        "bot.urdf:3:23: error: mesh '../meshes/G1_Rod.STL' (path relative to the URDF) lies "
        "in none of this robot's packages, so it has no asset path (looked in: desc (ros/desc), "
        "any package folder beside the URDF (ros/<package>))" in run.err
    ), run.err
    assert "bot.urdf:4:26: error: mesh '../meshes/G1_Rod.STL'" in run.err  # every one
    assert "hint: add the package that holds it to the entry's `packages`" in run.err
