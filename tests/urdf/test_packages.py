"""Mesh filenames resolve against the given package folders, inside the project only."""

from __future__ import annotations

from pathlib import Path, PurePosixPath

import pytest
from helpers import build_tree

from unityscaffold.errors import LocatedError
from unityscaffold.urdf import parse_urdf, resolve_meshes


def robot_with_meshes(*filenames: str) -> bytes:
    visuals = "".join(
        f'<visual><geometry><mesh filename="{name}"/></geometry></visual>\n' for name in filenames
    )
    return f'<robot name="r">\n<link name="a">\n{visuals}</link>\n</robot>\n'.encode()


@pytest.fixture
def project(tmp_path: Path) -> Path:
    return build_tree(
        tmp_path / "project",
        {
            "ros/robot.urdf": "",
            "ros/desc/meshes/arm.stl": "solid arm\nendsolid arm\n",
            "ros/urdf_tutorial/meshes/finger.dae": "<COLLADA/>",
        },
    )


def test_package_and_find_forms_resolve_through_the_packages_map(project: Path) -> None:
    urdf = project / "ros" / "robot.urdf"
    robot = parse_urdf(
        robot_with_meshes("package://desc/meshes/arm.stl", "$(find desc)/meshes/arm.stl")
    )
    found = resolve_meshes(
        robot, urdf=urdf, packages={"desc": project / "ros" / "desc"}, project=project
    )
    for filename in ("package://desc/meshes/arm.stl", "$(find desc)/meshes/arm.stl"):
        assert found[filename].package == "desc"
        assert found[filename].relative == PurePosixPath("meshes/arm.stl")
        assert found[filename].path == (project / "ros/desc/meshes/arm.stl").resolve()


def test_a_package_not_in_the_map_is_looked_for_beside_the_urdf_as_rossharp_does(
    project: Path,
) -> None:
    robot = parse_urdf(robot_with_meshes("package://urdf_tutorial/meshes/finger.dae"))
    found = resolve_meshes(robot, urdf=project / "ros" / "robot.urdf", packages={}, project=project)
    assert found["package://urdf_tutorial/meshes/finger.dae"].path.name == "finger.dae"


def test_every_unresolvable_mesh_is_reported_at_its_line(project: Path, tmp_path: Path) -> None:
    outside = build_tree(tmp_path / "elsewhere", {"meshes/x.stl": "solid x\n"})
    robot = parse_urdf(
        robot_with_meshes(
            "package://nowhere/m.stl",
            "package://desc/meshes/missing.stl",
            "package://far/meshes/x.stl",
            "package://desc/../../../elsewhere/meshes/x.stl",
            "meshes/arm.stl",
        ),
        "robot.urdf",
    )
    packages = {"desc": project / "ros" / "desc", "far": outside}
    with pytest.raises(LocatedError) as caught:
        resolve_meshes(
            robot, urdf=project / "ros" / "robot.urdf", packages=packages, project=project
        )
    rendered = [d.render() for d in caught.value.diagnostics]
    assert [text.split(": error: ")[0] for text in rendered] == [
        f"robot.urdf:{n}:19" for n in range(3, 8)
    ]
    assert "no folder for package 'nowhere'" in rendered[0] and "(given: desc, far)" in rendered[0]
    assert "no file" in rendered[1] and "missing.stl" in rendered[1]
    assert "is outside the project" in rendered[2]
    assert "steps out of its package with '..'" in rendered[3]
    assert "names no ROS package" in rendered[4] and "package://<package>/<path>" in rendered[4]


def test_a_mesh_path_with_dotdot_inside_the_project_is_refused_as_its_assets_would_escape(
    project: Path,
) -> None:
    # the path inside the package is where the mesh's assets go under the robot's folder:
    # desc/../../ros/desc/meshes/arm_0.asset would land beside that folder
    robot = parse_urdf(
        robot_with_meshes("package://desc/../../ros/desc/meshes/arm.stl", "package://../m.stl"),
        "robot.urdf",
    )
    packages = {"desc": project / "ros" / "desc"}
    with pytest.raises(LocatedError) as caught:
        resolve_meshes(
            robot, urdf=project / "ros" / "robot.urdf", packages=packages, project=project
        )
    rendered = [d.render() for d in caught.value.diagnostics]
    assert [text.split(": error: ")[0] for text in rendered] == [
        "robot.urdf:3:19",
        "robot.urdf:4:19",
    ]
    assert all("steps out of its package with '..'" in text for text in rendered)
    assert all("hint: name the mesh by its package" in text for text in rendered)
