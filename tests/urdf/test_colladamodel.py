"""The objects and root pose of the model Unity imports from a COLLADA file.

Where the values come from:
- ``UR3``: github.com/Unity-Technologies/Robotics-Object-Pose-Estimation (Apache-2.0) at
  970a2396, ``PoseEstimationDemoProject/Assets/Scenes/TutorialPoseEstimation.unity``: Unity 2020.3
  saved URDF-Importer's instances of ur_description's UR3 visuals (``Z_UP``; ``base.dae`` has
  the top nodes Camera, Lamp and Base, ``wrist3.dae`` node0 and node1), each renderer given a
  material (``m_Materials.Array.data[0]``) and each root the post-processor's rotation.
- ``NIRYO``: github.com/Unity-Technologies/Unity-Robotics-Hub (Apache-2.0) at 7eb28682,
  ``tutorials/pick_and_place/PickAndPlaceProject/Assets/Scenes/Part1DoneScene.unity``: the
  Niryo One's ``Z_UP`` models of one unnamed top node (cameras and bodies below it).
- ROS#'s ``Editor/Urdf/MeshProcessing/ColladaAssetPostProcessor.cs``: the rotation and
  position fixes by up axis; the rest of a moved node's pose is inferred (module docstring).
"""

from __future__ import annotations

import math
from pathlib import Path

import pytest

from unityscaffold.errors import LocatedError
from unityscaffold.unity.modelids import model_file_id
from unityscaffold.urdf._creation import saved_rotation
from unityscaffold.urdf.collada import read_collada
from unityscaffold.urdf.colladamodel import drawn_nodes, imported_root_pose

HALF = 0.7071067690849304  # float32 of √½, as the scenes print it: 0.7071068


def dae(tmp_path: Path, nodes: str, *, up: str = "Z_UP", library: str = "") -> Path:
    path = tmp_path / "m.dae"
    path.write_text(
        '<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">'
        f'<asset><unit meter="1"/><up_axis>{up}</up_axis></asset>'
        '<library_geometries><geometry id="g"><mesh><triangles/></mesh></geometry>'
        f"</library_geometries><library_nodes>{library}</library_nodes>"
        f'<library_visual_scenes><visual_scene id="s">{nodes}</visual_scene>'
        '</library_visual_scenes><scene><instance_visual_scene url="#s"/></scene></COLLADA>',
        encoding="utf-8",
    )
    return path


def drawing(name: str, inner: str = "") -> str:
    return f'<node id="{name}" name="{name}"><instance_geometry url="#g"/>{inner}</node>'


def empty(name: str, inner: str = "") -> str:
    return f'<node id="{name}" name="{name}">{inner}</node>'


def pose(path: Path) -> tuple[tuple[float, float, float], tuple[float, float, float, float]]:
    position, rotation = imported_root_pose(read_collada(path))
    return position, saved_rotation(rotation)


def test_the_ur3_base_s_renderer_has_the_file_id_unity_saved(tmp_path: Path) -> None:
    path = dae(tmp_path, empty("Camera") + empty("Lamp") + drawing("Base"))
    (base,) = drawn_nodes(read_collada(path))
    assert (base.path, base.renderer) == ("//RootNode/root/Base", -2859109400176981367)


def test_the_ur3_wrist3_s_two_renderers_have_the_file_ids_unity_saved(tmp_path: Path) -> None:
    path = dae(tmp_path, drawing("node0") + drawing("node1"))
    renderers = [node.renderer for node in drawn_nodes(read_collada(path))]
    assert renderers == [55291342286754144, -7264643304161535556]


def test_a_z_up_model_of_several_top_nodes_is_turned_as_the_ur3_scene_shows(
    tmp_path: Path,
) -> None:
    """The scene: ``m_LocalRotation`` x -0, y 0.7071068, z -0, w 0.7071068, position 0:
    ROS#'s ``Euler(0, 90, 0)`` on a root Unity left unturned."""
    path = dae(tmp_path, drawing("node0") + drawing("node1"))
    assert pose(path) == ((0.0, 0.0, 0.0), (-0.0, HALF, -0.0, HALF))


def test_a_z_up_model_of_one_top_node_is_turned_as_the_niryo_scene_shows(tmp_path: Path) -> None:
    """The scene: (-0.5, 0.5, 0.5, 0.5), position 0: the FBX SDK's -90° about x on the one
    top node, folded into the root, then ROS#'s ``Euler(0, 90, 0)``."""
    path = dae(
        tmp_path, '<node><node id="b" name="Body_1"><instance_geometry url="#g"/></node></node>'
    )
    assert pose(path) == ((0.0, 0.0, 0.0), (-0.5, 0.5, 0.5, 0.5))
    (body,) = drawn_nodes(read_collada(path))
    assert body.path == "//RootNode/root/Body_1"  # below the folded root (inferred)


@pytest.mark.parametrize("up", ["Y_UP", "X_UP"])
def test_one_unmoved_top_node_ends_turned_alike_on_every_up_axis(tmp_path: Path, up: str) -> None:
    """ROS#'s fixes are chosen so: Y_UP ``Euler(-90, 90, 0)`` (r2d2's scene), X_UP
    ``Euler(-90, 90, 90)`` after the FBX SDK's 90° about z (inferred: ROS# says "not
    tested")."""
    assert pose(dae(tmp_path, drawing("n"), up=up)) == ((0.0, 0.0, 0.0), (-0.5, 0.5, 0.5, 0.5))


def test_an_x_up_model_of_several_top_nodes_takes_ros_sharp_s_x_up_turn(tmp_path: Path) -> None:
    """``Euler(-90, 90, 90)`` = (0, √½, √½, 0), the zeros saved as -0 on x."""
    path = dae(tmp_path, drawing("a") + drawing("b"), up="X_UP")
    assert pose(path) == ((0.0, 0.0, 0.0), (-0.0, HALF, HALF, 0.0))


def test_a_moved_z_up_top_node_puts_the_root_where_ros_sharp_s_position_fix_does(
    tmp_path: Path,
) -> None:
    """Franka's ``link1.dae``: its one node at z = -0.192. Turned to Y up (x, z, -y) and
    mirrored on x: (-0, -0.192, -0); ROS#'s Z_UP fix (-z, y, -x): (0, -0.192, 0)."""
    node = '<node id="n" name="n"><matrix>1 0 0 0 0 1 0 0 0 0 1 -0.192 0 0 0 1</matrix>'
    path = dae(tmp_path, node + '<instance_geometry url="#g"/></node>')
    position, rotation = pose(path)
    assert position == pytest.approx((0.0, -0.192, 0.0), abs=1e-12)
    assert rotation == (-0.5, 0.5, 0.5, 0.5)


def test_a_turned_y_up_top_node_turns_the_root_by_its_mirrored_rotation(tmp_path: Path) -> None:
    """A node turned 90° about y (right-handed) is turned -90° about y once x is mirrored
    (Unity's handedness change, (x, y, z) → (-x, y, z)), then by ``Euler(-90, 90, 0)``:
    ``Euler(-90, 90, 0) * Euler(0, -90, 0)`` = ``Euler(0, 0, 90)`` = (0, 0, √½, √½)."""
    node = '<node id="n" name="n"><rotate>0 1 0 90</rotate><instance_geometry url="#g"/></node>'
    position, rotation = pose(dae(tmp_path, node, up="Y_UP"))
    assert position == (0.0, 0.0, 0.0)
    assert rotation == (-0.0, -0.0, HALF, HALF)


def test_nested_nodes_and_instanced_nodes_are_below_their_parents_path(tmp_path: Path) -> None:
    """Paths by the hash rule of ``unity.modelids``; an ``<instance_node>`` is a child like
    any other (inferred)."""
    nodes = empty("arm", drawing("hand") + '<instance_node url="#finger"/>') + drawing("leg")
    path = dae(tmp_path, nodes, library=drawing("finger"))
    drawn = drawn_nodes(read_collada(path))
    assert [d.path for d in drawn] == [
        "//RootNode/root/arm/hand",
        "//RootNode/root/arm/finger",
        "//RootNode/root/leg",
    ]
    hand = drawn[0]
    assert hand.gameobject == model_file_id("GameObject", "//RootNode/root/arm/hand")
    assert hand.filter == model_file_id("MeshFilter", "//RootNode/root/arm/hand")
    assert hand.mesh == model_file_id("Mesh", "hand")  # a mesh is named after its node


def test_objects_of_one_class_at_one_path_are_counted_in_document_order(tmp_path: Path) -> None:
    """Two siblings of one name share a path: the second's objects take the counter 1, as
    ``unity.modelids`` counts objects of a class at a path; their meshes likewise."""
    path = dae(tmp_path, drawing("part") + drawing("part"))
    first, second = drawn_nodes(read_collada(path))
    assert second.gameobject == model_file_id("GameObject", "//RootNode/root/part", 1)
    assert second.renderer == model_file_id("MeshRenderer", "//RootNode/root/part", 1)
    assert (first.mesh, second.mesh) == (
        model_file_id("Mesh", "part", 0),
        model_file_id("Mesh", "part", 1),
    )


def test_a_file_outside_collada_1_4_s_namespace_is_turned_as_ros_sharp_s_undefined(
    tmp_path: Path,
) -> None:
    """ROS# reads ``up_axis`` in 1.4's namespace only; elsewhere "undefined": ``Euler(-90,
    90, 0)`` even on a Z_UP root the FBX SDK turned (-90° about x)."""
    path = dae(tmp_path, drawing("a") + drawing("b"))
    text = path.read_text(encoding="utf-8").replace("2005/11", "2008/03")
    path.write_text(text, encoding="utf-8")
    facts = read_collada(path)
    assert (facts.up_axis, facts.ros_up_axis) == ("Z_UP", "undefined")
    assert pose(path) == ((0.0, 0.0, 0.0), (-0.5, 0.5, 0.5, 0.5))


@pytest.mark.parametrize(
    ("meter", "read"),
    [
        ("0.001", 0.001),
        (" 1e-3 ", 0.001),
        ("1,5", 15.0),  # C#'s AllowThousands: a group separator between whole digits
        ("inf", 1.0),  # not a spelling float.Parse takes: ROS# falls back to 1
        ("1_000", 1.0),  # Python's spelling, not C#'s
        ("1e39", 1.0),  # past float32: Mono's OverflowException, caught by ROS#
        ("cm", 1.0),
    ],
)
def test_the_unit_is_read_as_ros_sharp_s_float_parse_reads_it(
    tmp_path: Path, meter: str, read: float
) -> None:
    """``ColladaAssetPostProcessor.readGlobalScale``: ``float.Parse(str, InvariantCulture)``
    in a try whose catch gives 1."""
    path = dae(tmp_path, drawing("n"))
    path.write_text(path.read_text().replace('meter="1"', f'meter="{meter}"'))
    assert read_collada(path).meter == read


@pytest.mark.parametrize(
    "transform",
    [
        "<rotate>0 0 1 inf</rotate>",
        "<translate>1e400 0 0</translate>",
        "<translate>a 0 0</translate>",
    ],
)
def test_a_transform_that_is_no_numbers_leaves_the_node_unposed(
    tmp_path: Path, transform: str
) -> None:
    node = f'<node id="n" name="n">{transform}<instance_geometry url="#g"/></node>'
    facts = read_collada(dae(tmp_path, node))
    assert all(math.isnan(v) for v in facts.nodes[0].matrix)


def test_a_node_instancing_a_node_it_lies_in_is_refused_at_the_instance(tmp_path: Path) -> None:
    """Its tree would never end; a repeated instance (twice itself) would have hung apply."""
    node = '<node id="a" name="a"><instance_node url="#a"/><instance_node url="#a"/></node>'
    with pytest.raises(LocatedError) as caught:
        read_collada(dae(tmp_path, node))
    assert "<instance_node> names '#a', a node it lies in" in caught.value.render()
    assert caught.value.location.line == 1
