"""The GameObject tree ROS#'s importer builds, checked rule by rule and against the scene Unity
2022.3 saved after ROS#'s importer built r2d2 (ROS#'s "Gazebo Simulation Scenes ROS2" sample)."""

from __future__ import annotations

import math
from pathlib import Path

import pytest
from robot_helpers import inertial

from unityscaffold.unity import SceneDocument
from unityscaffold.unity.catalog import rossharp_catalog
from unityscaffold.unity.setvalue import component_label
from unityscaffold.urdf import parse_urdf, read_urdf
from unityscaffold.urdf.objects import ImportedObject, importer_tree
from unityscaffold.urdf.transforms import f32

#: What the tutorial's author added by hand after importing (not the importer's).
HAND_MADE = {"r2d2/base_link/head/box/CameraPlane"}
INERTIAL = inertial()


def lines(tree: ImportedObject) -> list[str]:
    return [f"{'  ' * depth}{o.name} {o.component_names}" for depth, o in tree.walk()]


def test_links_hold_visuals_collisions_then_child_links_in_joint_order() -> None:
    robot = parse_urdf(
        b'<robot name="bot"><gazebo/><transmission name="t"/>'
        b'<link name="base"><visual name="shell"><geometry><box size="1 2 3"/></geometry></visual>'
        b'<visual><geometry><mesh filename="package://p/meshes/arm.STL"/></geometry></visual>'
        b'<collision name="ignored"><geometry><cylinder radius="1" length="2"/></geometry>'
        b"</collision></link>"
        b'<link name="b"/><link name="a"/>'
        b'<joint name="to_b" type="fixed"><parent link="base"/><child link="b"/></joint>'
        b'<joint name="to_a" type="fixed"><parent link="base"/><child link="a"/></joint>'
        b"</robot>"
    )
    assert lines(importer_tree(robot)) == [
        "bot ['UrdfRobot']",
        "  Plugins ['UrdfPlugins', 'UrdfPlugin', 'UrdfPlugin']",
        "  base ['UrdfLink']",
        "    Visuals ['UrdfVisuals']",
        "      shell ['UrdfVisual']",
        "        Cube ['MeshFilter', 'MeshRenderer']",
        "      unnamed ['UrdfVisual']",
        "        arm []",
        "    Collisions ['UrdfCollisions']",
        "      unnamed ['UrdfCollision']",
        "        Cylinder ['MeshCollider']",
        "    b ['UrdfLink']",
        "      Visuals ['UrdfVisuals']",
        "      Collisions ['UrdfCollisions']",
        "    a ['UrdfLink']",
        "      Visuals ['UrdfVisuals']",
        "      Collisions ['UrdfCollisions']",
    ]


@pytest.mark.parametrize(
    ("parent_inertial", "child_inertial", "components"),
    [
        (
            True,
            True,
            [
                "UrdfLink",
                "Rigidbody",
                "UrdfInertial",
                "UrdfJointPrismatic",
                "ConfigurableJoint",
                "PrismaticJointLimitsManager",
            ],
        ),
        (False, True, ["UrdfLink", "Rigidbody", "UrdfInertial"]),
        (True, False, ["UrdfLink"]),
    ],
)
def test_a_joint_gets_components_only_between_two_links_with_inertials(
    parent_inertial: bool, child_inertial: bool, components: list[str]
) -> None:
    parent = INERTIAL if parent_inertial else ""
    child = INERTIAL if child_inertial else ""
    robot = parse_urdf(
        f'<robot name="r"><link name="p">{parent}</link><link name="c">{child}</link>'
        '<joint name="j" type="prismatic"><parent link="p"/><child link="c"/>'
        '<limit effort="1" velocity="1"/></joint></robot>'.encode()
    )
    link = importer_tree(robot).children[1].children[2]
    assert link.name == "c" and link.component_names == components


def test_poses_and_sizes_follow_the_origins_and_shapes() -> None:
    robot = parse_urdf(
        b'<robot name="r"><link name="p"/><link name="c">'
        b'<visual><origin xyz="1 2 3" rpy="0 0 1.5707963267948966"/>'
        b'<geometry><cylinder radius="0.5" length="4"/></geometry></visual></link>'
        b'<joint name="j" type="fixed"><origin xyz="0 -0.22 0.25"/>'
        b'<parent link="p"/><child link="c"/></joint></robot>'
    )
    link = importer_tree(robot).children[1].children[2]
    assert link.transform.position == (pytest.approx(0.22), 0.25, 0.0)
    visual = link.children[0].children[0]
    assert visual.transform.position == (-2.0, 3.0, 1.0)
    assert visual.transform.scale == (1.0, 2.0, 1.0)
    # yaw 90° about ROS's z (up) is -90° about Unity's y (up)
    assert visual.transform.rotation == pytest.approx((0, -(0.5**0.5), 0, 0.5**0.5), abs=1e-7)


def _scene_tree(scene: SceneDocument, root: str) -> list[tuple[int, str, str, list[str]]]:
    names = rossharp_catalog().all_class_names()
    found = []
    walking = False
    for depth, go in scene.tree():
        if go.path == root:
            walking, base = True, depth
        elif walking and depth <= base:
            break
        if walking and go.path not in HAND_MADE:
            labels = (
                []
                if go.is_prefab_instance
                else [component_label(c, names) for c in scene.components_of(go)][1:]
            )
            found.append((depth - base, go.name, go.path, labels))
    return found


def test_the_tree_matches_the_one_rossharps_importer_built_for_r2d2(
    r2d2_urdf: Path, r2d2_scene: Path
) -> None:
    scene = SceneDocument.load(r2d2_scene)
    expected = [(d, name, labels) for d, name, _, labels in _scene_tree(scene, "r2d2")]
    ours = [(d, o.name, o.component_names) for d, o in importer_tree(read_urdf(r2d2_urdf)).walk()]
    assert len(ours) == 114
    assert ours == expected


def test_every_pose_and_size_matches_the_scene_rotations_and_sizes_bit_for_bit(
    r2d2_urdf: Path, r2d2_scene: Path
) -> None:
    """Rotations and scales are Unity's float32 values exactly, negative zeros included (ROS#'s
    alignment leaves them). Positions are within 1e-6: Unity's ``Translate`` adds in world
    space and converts back (0.19999999 for 0.2), which is not reproduced."""
    scene = SceneDocument.load(r2d2_scene)
    paths = [path for _, _, path, _ in _scene_tree(scene, "r2d2")]
    checked = 0
    for path, (_, ours) in zip(paths, importer_tree(read_urdf(r2d2_urdf)).walk(), strict=True):
        go = scene.find_gameobject(path)
        if go.is_prefab_instance or path == "r2d2":  # the author moved the robot by hand
            continue
        for key, value in (
            ("m_LocalPosition", ours.transform.position),
            ("m_LocalRotation", ours.transform.rotation),
            ("m_LocalScale", ours.transform.scale),
        ):
            stored = scene.field(go.transform_id, key)
            assert isinstance(stored, dict)
            unity = [f32(float(stored[axis])) for axis in "xyzw"[: len(value)]]
            signs = [math.copysign(1, v) for v in unity]
            assert signs == [math.copysign(1, v) for v in value], f"{path} {key}"
            if key == "m_LocalPosition":
                assert unity == pytest.approx(list(value), abs=1e-6), f"{path} {key}"
            else:
                assert unity == list(value), f"{path} {key}"
        checked += 1
    assert checked == 106 - 1


def test_the_not_editable_objects_are_the_ones_unity_saved_with_hide_flags_8(
    r2d2_urdf: Path, r2d2_scene: Path
) -> None:
    scene = SceneDocument.load(r2d2_scene)
    found = _scene_tree(scene, "r2d2")
    ours = importer_tree(read_urdf(r2d2_urdf)).walk()
    hidden = {path for _, _, path, _ in found if _hide_flags(scene, path) == (8, 8)}
    not_editable = {
        path for (_, _, path, _), (_, o) in zip(found, ours, strict=True) if o.not_editable
    }
    assert len(hidden) == 32 and not_editable == hidden


def _hide_flags(scene: SceneDocument, path: str) -> tuple[int, ...]:
    """``m_ObjectHideFlags`` of a GameObject and of its Transform."""
    go = scene.find_gameobject(path)
    if go.is_prefab_instance or go.transform_id is None:
        return ()
    flags = []
    for file_id in (go.file_id, go.transform_id):
        doc = scene.document(file_id)
        assert doc is not None
        flags.append(int(doc.text.split("m_ObjectHideFlags: ")[1].split("\n")[0]))
    return tuple(flags)


def test_plugin_texts_are_the_ones_rossharp_stored_with_the_importing_machines_newlines(
    r2d2_urdf: Path, r2d2_scene: Path
) -> None:
    """The tutorial was imported on Windows: ``XElement.ToString()`` wrote CRLF."""
    scene = SceneDocument.load(r2d2_scene)
    names = rossharp_catalog().all_class_names()
    plugins = [
        c
        for c in scene.components_of(scene.find_gameobject("r2d2/Plugins"))
        if component_label(c, names) == "UrdfPlugin"
    ]
    stored = [scene.field(c, "PluginText") for c in plugins]
    ours = [p.text.replace("\n", "\r\n") for p in read_urdf(r2d2_urdf).plugins]
    assert len(ours) == 4 and stored == ours


def test_a_serial_chain_deeper_than_pythons_stack_is_built_link_under_link() -> None:
    # a long chain (a cable, a snake robot) nests each link under the last: building it
    # recursively went past Python's recursion limit at about 500 links
    count = 1500
    links = "".join(f'<link name="l{i}">{INERTIAL}</link>' for i in range(count))
    joints = "".join(
        f'<joint name="j{i}" type="fixed"><parent link="l{i - 1}"/><child link="l{i}"/></joint>'
        for i in range(1, count)
    )
    tree = importer_tree(parse_urdf(f'<robot name="chain">{links}{joints}</robot>'.encode()))
    chain = [(depth, o.name) for depth, o in tree.walk() if o.name.startswith("l")]
    assert chain == [(i + 1, f"l{i}") for i in range(count)]
    deepest = next(o for _, o in tree.walk() if o.name == f"l{count - 1}")
    assert deepest.key == f"link[{count - 1}]"
    assert "FixedJoint" in deepest.component_names
    assert [o.name for o in deepest.children] == ["Visuals", "Collisions"]
