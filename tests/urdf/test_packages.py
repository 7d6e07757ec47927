"""Mesh filenames resolve against the given package folders, inside the project only.

ROS# 2.2.1 reads only ``package://pkg/path`` (``UrdfAssetPathHandler.
GetRelativeAssetPathFromUrdfPath`` warns "Path should start with \"package://\"" and leaves the
mesh out); its asset path is what follows ``package://``: the package and the path inside it.
A file named by where it is (a ``file://`` URI, which is what ``file://$(find pkg)/…`` becomes
once xacro expands it, an absolute path, a path relative to the URDF) inside one of the robot's
package folders is taken as that package's ``package://`` names it: the same ``ResolvedMesh``,
so the same assets."""

from __future__ import annotations

from pathlib import Path, PurePosixPath

import pytest
from helpers import build_tree

from unityscaffold.errors import Diagnostic, DiagnosticSink, LocatedError, SourceLocation
from unityscaffold.urdf import ResolvedMesh, parse_urdf, resolve_meshes
from unityscaffold.urdf._packages import resolve_file


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
            "https://example.com/meshes/arm.stl",
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
        f"robot.urdf:{n}:19" for n in range(3, 9)
    ]
    assert "names package 'nowhere', which has no folder" in rendered[0]
    assert "(given: desc, far)" in rendered[0]
    assert "names a file that does not exist" in rendered[1] and "missing.stl" in rendered[1]
    assert "is outside the project" in rendered[2]
    assert "steps out of its package with '..'" in rendered[3]
    # ros/meshes/arm.stl: relative to the URDF, in no package folder (desc is ros/desc)
    assert (
        "mesh 'meshes/arm.stl' (path relative to the URDF) lies in none of this robot's "
        in (rendered[4])
    )
    assert "(looked in: desc (ros/desc), far (" in rendered[4]
    assert "any package folder beside the URDF (ros/<package>)" in rendered[4]
    assert "mesh 'https://example.com/meshes/arm.stl' is a https: URI" in rendered[5]


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


def resolve_one(project: Path, filename: str, **packages: str) -> ResolvedMesh:
    """``filename`` resolved for the URDF ``ros/robot.urdf`` with ``packages`` (name: folder
    relative to the project)."""
    robot = parse_urdf(robot_with_meshes(filename), "robot.urdf")
    found = resolve_meshes(
        robot,
        urdf=project / "ros" / "robot.urdf",
        packages={name: project / folder for name, folder in packages.items()},
        project=project,
    )
    return found[filename]


@pytest.mark.parametrize(
    "filename",
    [
        "file://{root}/ros/desc/meshes/arm.stl",  # file://$(find desc)/meshes/arm.stl expanded
        "file://localhost{root}/ros/desc/meshes/arm.stl",  # RFC 8089's host form
        "file:{root}/ros/desc/meshes/arm.stl",  # RFC 8089's minimal form
        "file://{root}/ros/desc/./meshes/../meshes/arm.stl",  # dot segments (RFC 3986 5.2.4)
        "{root}/ros/desc/meshes/arm.stl",  # an absolute path
        "desc/meshes/arm.stl",  # relative to the URDF's folder, ros/
        "../ros/desc/meshes/arm.stl",
        "package://desc\\meshes\\arm.stl",  # Windows separators: ROS#'s SetSeparatorChar
        "desc\\meshes\\arm.stl",
    ],
)
def test_a_file_named_by_where_it_is_is_its_packages_file(project: Path, filename: str) -> None:
    # what package://desc/meshes/arm.stl is (the first test): asset path desc/meshes/arm.stl
    expected = ResolvedMesh(
        "desc", PurePosixPath("meshes/arm.stl"), (project / "ros/desc/meshes/arm.stl").resolve()
    )
    named = filename.format(root=project.resolve().as_posix())
    assert resolve_one(project, named, desc="ros/desc") == expected


def test_a_file_uri_is_percent_decoded(project: Path) -> None:
    build_tree(project, {"ros/my desc/meshes/arm 1.stl": "solid a\nendsolid a\n"})
    # RFC 8089 and RFC 3986 2.1: %20 is a space
    uri = f"file://{project.resolve().as_posix()}/ros/my%20desc/meshes/arm%201.stl"
    found = resolve_one(project, uri, desc="ros/my desc")
    assert (found.package, found.relative) == ("desc", PurePosixPath("meshes/arm 1.stl"))


def test_a_relative_path_into_a_package_beside_the_urdf_is_that_package(project: Path) -> None:
    # package://urdf_tutorial/meshes/finger.dae is ros/urdf_tutorial/meshes/finger.dae by the
    # beside-the-URDF rule; the same file named relative to the URDF is the same package's
    found = resolve_one(project, "urdf_tutorial/meshes/finger.dae")
    assert found == ResolvedMesh(
        "urdf_tutorial",
        PurePosixPath("meshes/finger.dae"),
        (project / "ros/urdf_tutorial/meshes/finger.dae").resolve(),
    )


def test_the_innermost_package_holds_a_file_of_nested_package_folders(project: Path) -> None:
    found = resolve_one(project, "desc/meshes/arm.stl", desc="ros/desc", parts="ros/desc/meshes")
    assert (found.package, found.relative) == ("parts", PurePosixPath("arm.stl"))


def test_a_package_folder_reached_through_a_symlink_holds_its_files(project: Path) -> None:
    real = build_tree(project / "src" / "desc_real", {"meshes/arm.stl": "solid a\nendsolid a\n"})
    (project / "ros" / "linked").symlink_to(real)
    # named through the link (as $(find linked) gives it) and by where the file really is
    for filename in ("linked/meshes/arm.stl", f"{real.resolve().as_posix()}/meshes/arm.stl"):
        found = resolve_one(project, filename, linked="ros/linked")
        assert (found.package, found.relative) == ("linked", PurePosixPath("meshes/arm.stl"))
        assert found.path == (real / "meshes/arm.stl").resolve()


def refusals(project: Path, *filenames: str) -> tuple[Diagnostic, ...]:
    """The errors of a robot ``ros/robot.urdf`` whose meshes are ``filenames``, with package
    ``desc`` at ``ros/desc``."""
    robot = parse_urdf(robot_with_meshes(*filenames), "robot.urdf")
    with pytest.raises(LocatedError) as caught:
        resolve_meshes(
            robot,
            urdf=project / "ros" / "robot.urdf",
            packages={"desc": project / "ros" / "desc"},
            project=project,
        )
    return caught.value.diagnostics


def test_a_symlink_out_of_the_project_is_refused(project: Path, tmp_path: Path) -> None:
    outside = build_tree(tmp_path / "elsewhere", {"x.stl": "solid x\nendsolid x\n"})
    (project / "ros/desc/meshes/escape.stl").symlink_to(outside / "x.stl")
    refused = refusals(project, "desc/meshes/escape.stl", "package://desc/meshes/escape.stl")
    rendered = [d.render() for d in refused]
    real = (outside / "x.stl").resolve()
    assert f"(path relative to the URDF) is outside the project: {real}" in rendered[0]
    assert f"is outside the project: {real}" in rendered[1]


@pytest.mark.parametrize(
    ("filename", "message"),
    [
        ("file://{outside}/x.stl", "(file URI) is outside the project: {outside}/x.stl"),
        ("{outside}/x.stl", "(absolute path) is outside the project: {outside}/x.stl"),
        ("../../elsewhere/x.stl", "(path relative to the URDF) is outside the project:"),
        ("file://robots.example.com/x.stl", "names a file on the host 'robots.example.com'"),
        ("file://meshes/x.stl", "names a file on the host 'meshes'"),
        ("file:///C:/ros/desc/meshes/arm.stl", "names a file on a Windows drive"),
        ("C:\\ros\\desc\\meshes\\arm.stl", "names a file on a Windows drive"),
        ("file:meshes/x.stl", "is a file: URI without an absolute path"),
        ("model://desc/meshes/arm.stl", "is a model: URI, and only files in the repository"),
        ("package://desc", "names no file inside a ROS package"),
        ("", "is empty"),
    ],
)
def test_a_filename_naming_no_file_of_the_repository_is_refused(
    project: Path, tmp_path: Path, filename: str, message: str
) -> None:
    outside = build_tree(tmp_path / "elsewhere", {"x.stl": "solid x\nendsolid x\n"}).resolve()
    named = filename.format(outside=outside.as_posix())
    (diagnostic,) = refusals(project, named)
    assert (diagnostic.location.line, diagnostic.location.col) == (3, 19)
    assert diagnostic.message.startswith(f"mesh {named!r} ")
    assert message.format(outside=outside.as_posix()) in diagnostic.message


def test_a_file_in_no_package_gets_a_hint_naming_the_package_that_holds_it(project: Path) -> None:
    build_tree(
        project,
        {
            "shared/wheels/package.xml": "<package>\n  <name>wheel_description</name>\n</package>",
            "shared/wheels/meshes/wheel.stl": "solid w\nendsolid w\n",
        },
    )
    robot = parse_urdf(robot_with_meshes("../shared/wheels/meshes/wheel.stl"), "robot.urdf")
    with pytest.raises(LocatedError) as caught:
        resolve_meshes(robot, urdf=project / "ros" / "robot.urdf", packages={}, project=project)
    (diagnostic,) = caught.value.diagnostics
    assert diagnostic.message == (
        "mesh '../shared/wheels/meshes/wheel.stl' (path relative to the URDF) lies in none of "
        "this robot's packages, so it has no asset path (looked in: any package folder beside "
        "the URDF (ros/<package>))"
    )
    # the package's name is its package.xml's <name> (REP 140), its folder the one holding it
    assert diagnostic.hint == (
        "add its package to the entry's `packages` (wheel_description: shared/wheels, relative "
        "to the manifest), or name it package://wheel_description/meshes/wheel.stl"
    )


def test_a_texture_resolves_like_a_mesh(project: Path) -> None:
    # resolve_file serves any URDF filename: <texture filename> as <mesh filename>
    build_tree(project, {"ros/desc/textures/wood.png": "png"})
    sink = DiagnosticSink()
    where = SourceLocation("robot.urdf", 7, 20)
    root = project.resolve().as_posix()
    found, missing = (
        resolve_file(
            filename,
            where,
            urdf=project / "ros/robot.urdf",
            packages={"desc": project / "ros/desc"},
            project=project,
            sink=sink,
            kind="texture",
        )
        for filename in (
            f"file://{root}/ros/desc/textures/wood.png",
            "package://desc/textures/oak.png",
        )
    )
    assert found == ResolvedMesh(
        "desc",
        PurePosixPath("textures/wood.png"),
        (project / "ros/desc/textures/wood.png").resolve(),
    )
    assert missing is None
    with pytest.raises(LocatedError) as caught:
        sink.raise_if_errors()
    (diagnostic,) = caught.value.diagnostics
    assert diagnostic.location == where
    assert diagnostic.message.startswith("texture 'package://desc/textures/oak.png' names a file")


def test_without_a_package_xml_the_hint_names_the_folder_of_the_urdf_and_the_file(
    project: Path,
) -> None:
    # Unitree's robots/a2_description/urdf/a2.urdf names its meshes ../meshes/base_link.STL and
    # ships no package.xml (https://github.com/unitreerobotics/unitree_ros)
    build_tree(
        project,
        {
            "ros/a2_description/urdf/a2.urdf": "",
            "ros/a2_description/meshes/base_link.STL": "solid b\nendsolid b\n",
        },
    )
    robot = parse_urdf(robot_with_meshes("../meshes/base_link.STL"), "a2.urdf")
    with pytest.raises(LocatedError) as caught:
        resolve_meshes(
            robot, urdf=project / "ros/a2_description/urdf/a2.urdf", packages={}, project=project
        )
    (diagnostic,) = caught.value.diagnostics
    assert diagnostic.hint == (
        "add its package to the entry's `packages` (a2_description: ros/a2_description, "
        "relative to the manifest), or name it package://a2_description/meshes/base_link.STL"
    )
    # and with that package the file is the package's
    found = resolve_meshes(
        robot,
        urdf=project / "ros/a2_description/urdf/a2.urdf",
        packages={"a2_description": project / "ros/a2_description"},
        project=project,
    )
    assert found["../meshes/base_link.STL"] == ResolvedMesh(
        "a2_description",
        PurePosixPath("meshes/base_link.STL"),
        (project / "ros/a2_description/meshes/base_link.STL").resolve(),
    )


def test_a_path_into_an_install_space_gets_a_hint_naming_its_package_uri(project: Path) -> None:
    # Kinova's ros2_kortex commits kortex_description/robots/gen3_2f85.urdf as xacro expanded it
    # on another machine: file:///root/c3pzero_ws/install/kortex_description/share/
    # kortex_description/arms/gen3/7dof/meshes/base_link.dae
    # (https://github.com/Kinovarobotics/ros2_kortex); ament installs a package's files in
    # <prefix>/share/<package>/
    uri = "file:///root/ws/install/desc/share/desc/meshes/arm.stl"
    (diagnostic,) = refusals(project, uri)
    assert "(file URI) is outside the project: /root/ws/install/desc/share/desc/meshes/arm.stl" in (
        diagnostic.message
    )
    assert diagnostic.hint == (
        "it is package desc's file as installed on another machine: write "
        "package://desc/meshes/arm.stl, or import the .xacro it was expanded from (its "
        "$(find desc) is then the package's folder in the repository)"
    )
