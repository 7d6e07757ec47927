"""The manifest's `robots`: a URDF put into a scene as ROS#'s importer builds it, idempotent,
updated in place when the URDF changes, keeping what the user added, and refusing what is not
written yet at its element (comparison with Unity's own r2d2: test_apply_robots_r2d2.py)."""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest
from helpers import build_tree, run_cli, snapshot
from robot_helpers import (
    BOT_URDF,
    HEADER,
    NO_ROBOTS,
    ROBOTS,
    SCENE,
    apply_manifest,
    apply_refused,
    apply_robot,
    apply_writes_nothing,
    component,
    drift_is_put_back,
    field,
    init_project,
    meta_guid,
)

from unityscaffold.unity.scene import SceneDocument

TREE = [
    "bot  [Transform, UrdfRobot]",
    "  Plugins  [Transform, UrdfPlugins, UrdfPlugin]",
    "  base  [Transform, UrdfLink, Rigidbody, UrdfInertial]",
    "    Visuals  [Transform, UrdfVisuals]",
    "      unnamed  [Transform, UrdfVisual]",
    "        Cube  [Transform, MeshFilter, MeshRenderer]",
    "    Collisions  [Transform, UrdfCollisions]",
    "      unnamed  [Transform, UrdfCollision]",
    "        Cylinder  [Transform, MeshCollider]",
    "    arm  [Transform, UrdfLink, Rigidbody, UrdfInertial, UrdfJointRevolute, HingeJoint, "
    "HingeJointLimitsManager, HingeJointAngleCalculator]",
    "      Visuals  [Transform, UrdfVisuals]",
    "        unnamed  [Transform, UrdfVisual]",
    "          Sphere  [Transform, MeshFilter, MeshRenderer]",
    "      Collisions  [Transform, UrdfCollisions]",
    "        unnamed  [Transform, UrdfCollision]",
    "          Sphere  [Transform, SphereCollider]",
]


@pytest.fixture
def project(tmp_path: Path) -> Path:
    return init_project(tmp_path, {"ros/bot.urdf": BOT_URDF})


def _tree(project: Path) -> list[str]:
    listed = run_cli("scene", "ls", str(project / SCENE)).out.splitlines()
    start = listed.index(TREE[0])
    return [line for line in listed[start:] if line.startswith(" ") or line == TREE[0]][: len(TREE)]


def test_a_robot_is_built_as_rossharps_importer_builds_it(project: Path) -> None:
    run = apply_robot(project)
    assert run.code == 0, run.err
    assert _tree(project) == TREE
    assert "import robot bot" in run.out
    assert (project / "Assets/Urdf/bot/Materials/blue.mat").is_file()
    assert (project / "Assets/Urdf/bot/Materials/blue.mat.meta").is_file()
    # the joint names its parent's Rigidbody, the renderer the robot's material
    hinge = field(project, "bot/base/arm", "HingeJoint", "m_ConnectedBody")
    rigidbody = component(SceneDocument.load(project / SCENE), "bot/base", "Rigidbody")
    assert hinge == {"fileID": str(rigidbody.file_id)}
    guid = meta_guid(project / "Assets/Urdf/bot/Materials/blue.mat.meta")
    materials = field(project, "bot/base/Visuals/unnamed/Cube", "MeshRenderer", "m_Materials")
    assert materials == [{"fileID": "2100000", "guid": guid, "type": "2"}]


def test_a_second_apply_writes_nothing_and_check_is_clean(project: Path) -> None:
    assert apply_robot(project).code == 0
    again = apply_writes_nothing(project)
    assert "the project matches the manifest" in again.out
    assert apply_robot(project, "", "--check").code == 0


def test_the_inspector_switches_and_the_root_pose_are_kept_as_declared(project: Path) -> None:
    body = "    position: [0, 0.47, 0]\n    kinematic: true\n    gravity: false\n"
    assert apply_robot(project, body).code == 0
    assert field(project, "bot/base/arm", "Rigidbody", "m_IsKinematic") == "1"
    assert field(project, "bot/base", "Rigidbody", "m_UseGravity") == "0"
    assert field(project, "bot", "Transform", "m_LocalPosition") == {
        "x": "0",
        "y": "0.47",
        "z": "0",
    }


def test_a_changed_urdf_updates_the_robot_in_place_keeping_fileids(project: Path) -> None:
    assert apply_robot(project).code == 0
    first = SceneDocument.load(project / SCENE)
    ids = {go.path: go.file_id for _, go in first.tree()}
    (project / "ros/bot.urdf").write_text(
        BOT_URDF.replace('<mass value="1"/>', '<mass value="3"/>')
    )
    run = apply_robot(project)
    assert run.code == 0, run.err
    assert "update bot/base/arm (robot bot)" in run.out
    assert {go.path: go.file_id for _, go in SceneDocument.load(project / SCENE).tree()} == ids
    assert field(project, "bot/base/arm", "Rigidbody", "m_Mass") == "3"


def test_drift_in_what_the_urdf_decides_is_reported_and_put_back(project: Path) -> None:
    assert apply_robot(project).code == 0
    drift_is_put_back(project, "  m_Mass: 2\n", "  m_Mass: 5\n")


def test_what_the_user_adds_to_a_link_is_kept(project: Path) -> None:
    body = (
        "objects:\n  - path: bot/base/Extra\n    components: [BoxCollider]\n"
        "components:\n  - {script: JointStateWriter, gameobject: bot/base/arm}\n"
    )
    run = apply_robot(project, body)
    assert run.code == 0, run.err
    tree = run_cli("scene", "ls", str(project / SCENE)).out
    assert "Extra  [Transform, BoxCollider]" in tree
    assert "HingeJointAngleCalculator, JointStateWriter]" in tree
    apply_writes_nothing(project)


PRISMATIC = BOT_URDF.replace('type="revolute"', 'type="prismatic"').replace(
    'lower="-1" upper="1"/>', 'lower="-0.05" upper="0.3"/><dynamics damping="0.7" friction="0.2"/>'
)


def test_a_prismatic_joint_gets_rossharps_configurable_joint_and_limits_manager(
    project: Path,
) -> None:
    build_tree(project, {"ros/bot.urdf": PRISMATIC})
    run = apply_robot(project)
    assert run.code == 0, run.err
    tree = run_cli("scene", "ls", str(project / SCENE)).out
    assert (
        "arm  [Transform, UrdfLink, Rigidbody, UrdfInertial, UrdfJointPrismatic, "
        "ConfigurableJoint, PrismaticJointLimitsManager]" in tree
    )
    rigidbody = component(SceneDocument.load(project / SCENE), "bot/base", "Rigidbody")
    joint = "bot/base/arm", "ConfigurableJoint"
    assert field(project, *joint, "m_ConnectedBody") == {"fileID": str(rigidbody.file_id)}
    assert field(project, *joint, "m_Axis") == {"x": "-1", "y": "0", "z": "0"}  # ROS's y
    assert field(project, *joint, "m_XMotion") == "1"  # Limited; the rest Locked
    assert field(project, *joint, "m_AngularZMotion") == "0"
    assert field(project, *joint, "m_XDrive") == {
        "serializedVersion": "4",
        "positionSpring": "0.2",
        "positionDamper": "0.7",
        "maximumForce": "3.4028235e+38",
        "useAcceleration": "0",
    }
    assert field(project, *joint, "m_YDrive")["maximumForce"] == "3.4028233e+38"  # type: ignore[index]
    # the manager (a MonoBehaviour, found by its fields)
    assert (
        "  PositionLimitMin: -0.05\n  PositionLimitMax: 0.3\n  Tolerance: 0.01\n"
        in (project / SCENE).read_text()
    )
    apply_writes_nothing(project)
    assert apply_robot(project, "", "--check").code == 0


def test_a_changed_prismatic_limit_is_put_back_by_apply(project: Path) -> None:
    build_tree(project, {"ros/bot.urdf": PRISMATIC})
    assert apply_robot(project).code == 0
    drift_is_put_back(project, "  m_XMotion: 1\n", "  m_XMotion: 2\n")


def test_a_planar_joint_with_an_unchecked_normal_is_refused_at_its_joint(project: Path) -> None:
    build_tree(project, {"ros/bot.urdf": BOT_URDF.replace('type="revolute"', 'type="planar"')})
    run = apply_refused(project, HEADER)
    assert "bot.urdf:16:3:" in run.err and "planar joint 'j' has a normal (0 1 0)" in run.err


@pytest.mark.parametrize(
    ("entry", "message"),
    [
        ("  - urdf: ros/missing.urdf\n", "robot.yaml:6:11: error: URDF file "),
        (
            "  - urdf: ros/bot.urdf\n    packages: {p: ros/none}\n",
            "robot.yaml:7:15: error: the folder of package p",
        ),
        ("  - urdf: ros/bot.urdf\n    kinematik: true\n", "unknown key 'kinematik' in robot"),
        ("  - urdf: ros/bot.sdf\n", "invalid value for 'urdf'"),
        ("  - urdf: ros/bot.urdf\n    args: [a]\n", "invalid value for 'args'"),
        ("  - urdf: ros/bot.urdf\n    args: {a: 1}\n", "invalid value for 'a'"),
        ("  - urdf: ros/bot.urdf\n    assets: Packages/x\n", "invalid value for 'assets'"),
        (
            "  - urdf: ros/bot.urdf\n  - urdf: ros/bot.urdf\n",
            "robot.yaml:7:5: error: a second robot at GameObject 'bot' in Assets/Scenes/Main.unity",
        ),
        (
            "  - {urdf: ros/bot.urdf, gameobject: R}\n  - {urdf: ros/bot.urdf, gameobject: R}\n",
            "robot.yaml:7:38: error: a second robot at GameObject 'R'",
        ),
    ],
)
def test_a_bad_robot_entry_is_a_located_error(project: Path, entry: str, message: str) -> None:
    run = apply_refused(project, ROBOTS + entry)
    assert message in run.err, run.err


@pytest.mark.parametrize(
    ("name", "message"),
    [
        ("..", "the robot's name '..' is not usable as a folder name under Assets/Urdf"),
        ("", "the robot's name '' is not usable as a GameObject name or a folder name"),
        (
            "arm/left",
            "the robot's name 'arm/left' is not usable as a GameObject name or a folder name",
        ),
    ],
)
def test_a_robot_name_that_cannot_be_its_gameobject_or_folder_is_a_located_error(
    project: Path, name: str, message: str
) -> None:
    build_tree(project, {"ros/bot.urdf": BOT_URDF.replace('name="bot"', f'name="{name}"')})
    run = apply_refused(project, HEADER)
    assert f"bot.urdf:1:1: error: {message}" in run.err, run.err
    run = apply_robot(project, "    gameobject: Robot\n    assets: Assets/Robot\n")
    assert run.code == 0, run.err
    assert (project / "Assets" / "Robot" / "Materials" / "blue.mat").is_file()


def test_robots_share_an_asset_folder_only_for_the_same_files(project: Path) -> None:
    build_tree(project, {"ros/red.urdf": BOT_URDF.replace('rgba="0 0 0.8 1"', 'rgba="1 0 0 1"')})
    twins = "    gameobject: A\n  - {urdf: ros/bot.urdf, gameobject: B}\n"
    assert apply_robot(project, twins).code == 0
    third = "  - {urdf: ros/red.urdf, gameobject: C}\n"
    run = apply_refused(project, HEADER + twins + third)
    assert (
        "robot.yaml:9:5: error: Assets/Urdf/bot/Materials/blue.mat would differ from the one "
        "the robot on line 6 puts there" in run.err
    )


@pytest.mark.parametrize(
    ("entry", "where"),
    [
        (
            "  - {path: bot/base/arm, position: [1, 2, 3]}\n",
            "robot.yaml:8:36: error: 'bot/base/arm'",
        ),
        ("  - {path: bot, rotation: [0, 90, 0]}\n", "robot.yaml:8:27: error: 'bot'"),
        ("  - {path: bot/base/arm, sibling_index: 0}\n", "robot.yaml:8:41: error: 'bot/base/arm'"),
        (
            "  - {path: bot/base/Visuals/unnamed/Cube, primitive: plane}\n",
            "robot.yaml:8:54: error: 'bot/base/Visuals/unnamed/Cube'",
        ),
    ],
)
def test_an_object_entry_cannot_move_or_reshape_what_a_robot_imports(
    project: Path, entry: str, where: str
) -> None:
    """Else the import and the entry each put their own value back on every apply."""
    run = apply_refused(project, HEADER + "objects:\n" + entry)
    assert f"{where} belongs to robot bot, whose `robots` entry and URDF set its" in run.err


def test_an_object_entry_adds_to_a_robots_link_and_places_its_own_children(
    project: Path,
) -> None:
    body = (
        "objects:\n  - {path: bot/base/Plane, primitive: plane, position: [0, 1, 0]}\n"
        "  - {path: bot/base, components: [{type: BoxCollider}]}\n"
    )
    assert apply_robot(project, body).code == 0
    again = apply_robot(project, body)
    assert again.code == 0 and "wrote 0 files" in again.out, again.out
    assert not [line for line in again.out.splitlines() if line.startswith("  update")]


WITHOUT_ARM = BOT_URDF.split('  <link name="arm">')[0] + "</robot>\n"


def test_a_link_gone_from_the_urdf_is_removed_with_everything_apply_made_under_it(
    project: Path,
) -> None:
    assert apply_robot(project).code == 0
    (project / "ros/bot.urdf").write_text(WITHOUT_ARM)
    run = apply_robot(project)
    assert run.code == 0, run.err
    assert "remove bot/base/arm (robot bot)" in run.out
    assert _tree(project)[:9] == TREE[:9]
    assert "arm" not in run_cli("scene", "ls", str(project / SCENE)).out
    apply_writes_nothing(project)


def test_a_link_gone_from_the_urdf_stays_while_the_user_has_something_on_it(
    project: Path,
) -> None:
    user = "components:\n  - {script: JointStateWriter, gameobject: bot/base/arm}\n"
    assert apply_robot(project, user).code == 0
    (project / "ros/bot.urdf").write_text(WITHOUT_ARM)
    run = apply_robot(project, user)
    assert run.code == 0, run.err
    assert "note: kept bot/base/arm (robot bot), which the URDF no longer has" in run.out
    listed = run_cli("scene", "ls", str(project / SCENE)).out
    assert "arm  [Transform, JointStateWriter]" in listed
    # once the user's component goes, so does the link
    run = apply_robot(project)
    assert run.code == 0, run.err
    assert "arm" not in run_cli("scene", "ls", str(project / SCENE)).out


def test_a_robot_dropped_from_the_manifest_leaves_the_scene_as_it_was(project: Path) -> None:
    assert apply_manifest(project, NO_ROBOTS).code == 0
    scene = (project / SCENE).read_text()
    assert apply_robot(project).code == 0
    run = apply_manifest(project, NO_ROBOTS)
    assert run.code == 0, run.err
    assert (project / SCENE).read_text() == scene
    assert not (project / "Assets/Urdf/bot/Materials/blue.mat").exists()
    assert not (project / "Assets/Urdf/bot/Materials/blue.mat.meta").exists()


def test_a_material_gone_from_the_urdf_is_pruned_with_its_meta(project: Path) -> None:
    assert apply_robot(project).code == 0
    (project / "ros/bot.urdf").write_text(
        BOT_URDF.replace('<material name="blue"><color rgba="0 0 0.8 1"/></material>', "").replace(
            '<material name="blue"/>', ""
        )
    )
    run = apply_robot(project)
    assert run.code == 0, run.err
    assert not (project / "Assets/Urdf/bot/Materials/blue.mat").exists()
    assert not (project / "Assets/Urdf/bot/Materials/blue.mat.meta").exists()
    assert (project / "Assets/Urdf/bot/Materials/Default.mat").exists()


def test_what_unity_recomputes_and_fields_the_import_leaves_alone_are_kept(
    project: Path,
) -> None:
    """The connected anchor Unity computes when physics runs, and a drag the user set."""
    assert apply_robot(project).code == 0
    path = project / SCENE
    text = path.read_text()
    assert text.count("  m_ConnectedAnchor: {x: 0, y: 0, z: 0}\n") == 1
    edited = text.replace(
        "  m_ConnectedAnchor: {x: 0, y: 0, z: 0}\n",
        "  m_ConnectedAnchor: {x: -0.01, y: 0.000000014901161, z: 0.19999999}\n",
    ).replace("  m_Drag: 0\n", "  m_Drag: 0.5\n", 1)
    path.write_text(edited)
    assert apply_robot(project, "", "--check").code == 0
    assert apply_robot(project).code == 0
    assert path.read_text() == edited


def test_an_import_from_clean_gives_the_same_bytes_again(project: Path) -> None:
    """fileIDs and GUIDs derive from names: a robot imported anew is the robot imported
    before, scene and assets byte for byte."""
    scene = (project / SCENE).read_bytes()
    assert apply_robot(project).code == 0
    first = snapshot(project)
    (project / SCENE).write_bytes(scene)
    (project / "robot.lock.json").unlink()
    shutil.rmtree(project / "Assets/Urdf")
    (project / "Assets/Urdf.meta").unlink()
    assert apply_robot(project).code == 0
    assert snapshot(project) == first


def test_a_robot_goes_under_the_parent_its_path_names(project: Path) -> None:
    run = apply_robot(project, "    gameobject: World/bot\n")
    assert run.code == 0, run.err
    listed = run_cli("scene", "ls", str(project / SCENE)).out.splitlines()
    assert "World  [Transform]" in listed
    assert "  bot  [Transform, UrdfRobot]" in listed
    assert (
        "      arm  [Transform, UrdfLink, Rigidbody, UrdfInertial, UrdfJointRevolute, "
        "HingeJoint, HingeJointLimitsManager, HingeJointAngleCalculator]" in listed
    )
    apply_writes_nothing(project)
