"""A changed URDF updates its robot in place (issue 27): a link inserted between two others or a
middle link removed is applied, each link that is still there keeps its GameObject, fileIDs and
what the user put on it, and a joint of another type gets new joint components. Any sequence of
such edits: test_apply_robot_edits_properties.py. A scene apply's own edits left inconsistent is
apply's bug, reported as one."""

from __future__ import annotations

from pathlib import Path

import pytest
from robot_helpers import (
    SCENE,
    apply_robot,
    apply_writes_nothing,
    field,
    inertial,
    init_project,
)

from unityscaffold.apply._scenes import _check_own_edits
from unityscaffold.errors import InternalError
from unityscaffold.unity.builtins import builtin_class
from unityscaffold.unity.scene import SceneDocument


def urdf(tree: str, joint: str = "fixed") -> str:
    """A robot of boxes from ``tree``, each link as ``name`` or ``name:parent``, joints in
    that order (all of type ``joint``)."""
    links, joints = [], []
    for item in tree.split():
        name, _, parent = item.partition(":")
        box = '<visual><geometry><box size="1 1 1"/></geometry></visual>'
        links.append(f'<link name="{name}">{inertial()}{box}</link>')
        if parent:
            joints.append(
                f'<joint name="{name}_joint" type="{joint}"><parent link="{parent}"/>'
                f'<child link="{name}"/><axis xyz="0 1 0"/>'
                '<limit effort="1" velocity="1" lower="-1" upper="1"/></joint>'
            )
    return f'<robot name="bot">{"".join(links)}{"".join(joints)}</robot>\n'


@pytest.fixture
def project(tmp_path: Path) -> Path:
    return init_project(tmp_path, {"ros/bot.urdf": urdf("a b:a c:a d:b")})


def _add_a_box_collider(project: Path, path: str) -> int:
    """A BoxCollider added to ``path`` in the scene, as in Unity's editor; its fileID."""
    scene = SceneDocument.load(project / SCENE)
    box = builtin_class("BoxCollider")
    assert box is not None
    added = scene.ensure_builtin(path, box, None).file_id
    scene.write()
    return added


def _ids(project: Path) -> dict[str, int]:
    return {go.path: go.file_id for _, go in SceneDocument.load(project / SCENE).tree()}


def _changed_to(project: Path, tree: str, joint: str = "fixed") -> None:
    (project / "ros/bot.urdf").write_text(urdf(tree, joint))
    run = apply_robot(project)
    assert run.code == 0, run.out + run.err
    assert apply_robot(project, "", "--check").code == 0
    apply_writes_nothing(project)


def test_a_link_inserted_between_two_moves_the_lower_one_and_all_it_holds(project: Path) -> None:
    assert apply_robot(project).code == 0
    before = _ids(project)
    box = _add_a_box_collider(project, "bot/a/b")
    _changed_to(project, "a x:a b:x c:a d:b")
    after = _ids(project)
    assert after["bot/a/x/b"] == before["bot/a/b"]
    assert after["bot/a/x/b/d"] == before["bot/a/b/d"]
    assert after["bot/a/c"] == before["bot/a/c"]
    scene = SceneDocument.load(project / SCENE)
    assert scene.component(box).gameobject_id == before["bot/a/b"]


def test_a_middle_link_removed_leaves_its_children_to_its_parent(project: Path) -> None:
    assert apply_robot(project).code == 0
    before = _ids(project)
    box = _add_a_box_collider(project, "bot/a/b/d")
    _changed_to(project, "a c:a d:a")
    after = _ids(project)
    assert "bot/a/b" not in after
    assert after["bot/a/d"] == before["bot/a/b/d"]
    assert after["bot/a/c"] == before["bot/a/c"]
    scene = SceneDocument.load(project / SCENE)
    assert box in scene.gameobject(after["bot/a/d"]).component_ids


def test_a_renamed_link_is_another_link(project: Path) -> None:
    assert apply_robot(project).code == 0
    before = _ids(project)
    _changed_to(project, "a b:a e:a d:b")
    after = _ids(project)
    assert "bot/a/c" not in after
    assert after["bot/a/e"] not in before.values()
    assert after["bot/a/b/d"] == before["bot/a/b/d"]


def test_a_joint_of_another_type_has_new_joint_components_as_rossharps_change_makes(
    tmp_path: Path,
) -> None:
    """A revolute joint's HingeJoint uses limits (±1 rad: ``m_Limits`` ±57.29578°); a
    continuous joint's is a new one, which leaves ``m_UseLimits`` at 0 as a fresh import does.
    ROS#'s ``UrdfJoint.ChangeJointType`` (Runtime/Urdf/UrdfComponents/UrdfJoints/UrdfJoint.cs)
    destroys the UrdfJoint, limits managers and Unity joint and adds the new type's."""
    project = init_project(tmp_path, {"ros/bot.urdf": urdf("a b:a", "revolute")})
    assert apply_robot(project).code == 0
    assert field(project, "bot/a/b", "HingeJoint", "m_UseLimits") == "1"
    _changed_to(project, "a b:a", "continuous")
    assert field(project, "bot/a/b", "HingeJoint", "m_UseLimits") == "0"
    assert field(project, "bot/a/b", "HingeJoint", "m_Limits")["max"] == "0"  # type: ignore[index]


def test_a_scene_apply_itself_left_inconsistent_is_an_internal_error_named_by_object(
    project: Path,
) -> None:
    """The scene was whole before apply edited it, so a problem after is apply's bug: said
    as one, by object, never at a line of the planned text (which was never written)."""
    assert apply_robot(project).code == 0
    scene = SceneDocument.load(project / SCENE)
    d, c = scene.find_gameobject("bot/a/b/d"), scene.find_gameobject("bot/a/c")
    document = scene.document(d.transform_id or 0)
    assert document is not None
    moved = document.text.replace(
        f"m_Father: {{fileID: {scene.find_gameobject('bot/a/b').transform_id}}}",
        f"m_Father: {{fileID: {c.transform_id}}}",
    )
    broken = SceneDocument.parse(scene.text().replace(document.text, moved))
    with pytest.raises(InternalError) as raised:
        _check_own_edits(broken, SCENE)
    message = str(raised.value)
    assert message.startswith(
        f"internal error: apply's edits would leave {SCENE} inconsistent, which is a bug"
    )
    assert f"m_Children: lists --- !u!4 &{d.transform_id}, whose m_Father" in message
    assert "Main.unity:" not in message  # no line of a text never written
