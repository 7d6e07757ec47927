"""Prismatic, planar and floating joints: the ConfigurableJoint (and a prismatic joint's
PrismaticJointLimitsManager) ROS#'s importer makes, field by field as its
``UrdfJointPrismatic/Planar/Floating`` and ``PrismaticJointLimitsManager`` set them; planar
joints whose axes Unity would compute in a way nothing here checks are refused at the joint."""

from __future__ import annotations

from pathlib import Path

import pytest
from robot_helpers import inertial

from unityscaffold.errors import LocatedError
from unityscaffold.unity.values import InlineMap
from unityscaffold.urdf import import_robot, parse_urdf
from unityscaffold.urdf.objects import ComponentRef, ImportedComponent, importer_tree

INERTIAL = inertial()


def robot(tmp_path: Path, joints: str, *, child_inertial: bool = True) -> Path:
    child = INERTIAL if child_inertial else ""
    urdf = tmp_path / "r.urdf"
    urdf.write_text(
        f'<robot name="r">\n<link name="p">{INERTIAL}</link>\n'
        f'<link name="a">{child}</link>\n<link name="b">{child}</link>\n{joints}</robot>\n',
        encoding="utf-8",
    )
    return urdf


def joint(name: str, kind: str, child: str, inner: str = '<limit effort="1" velocity="1"/>') -> str:
    return (
        f'  <joint name="{name}" type="{kind}"><parent link="p"/><child link="{child}"/>'
        f"{inner}</joint>\n"
    )


def components(kind: str, inner: str) -> dict[str, ImportedComponent]:
    tree = importer_tree(
        parse_urdf(
            f'<robot name="r"><link name="p">{INERTIAL}</link><link name="c">{INERTIAL}</link>'
            f'<joint name="j" type="{kind}"><parent link="p"/><child link="c"/>{inner}</joint>'
            "</robot>".encode()
        )
    )
    link = tree.children[1].children[2]
    assert link.name == "c"
    return {c.name: c for c in link.components}


def vector(x: float, y: float, z: float) -> InlineMap:
    return InlineMap.of(x=x, y=y, z=z)


CONNECTED = (
    ("m_ConnectedBody", ComponentRef("link[0]", "Rigidbody")),
    ("m_AutoConfigureConnectedAnchor", True),
)
LOCKED = 0  # ConfigurableJointMotion.Locked; Limited 1, Free 2


def test_a_prismatic_joint_with_limits_and_dynamics_is_what_rossharp_sets() -> None:
    found = components(
        "prismatic",
        '<axis xyz="0 1 0"/><limit effort="3" velocity="2" lower="-0.05" upper="0.3"/>'
        '<dynamics damping="0.7" friction="0.2"/>',
    )
    script = found["UrdfJointPrismatic"]
    assert script.field("_jointType").value == 4  # type: ignore[union-attr]
    assert script.field("EffortLimit") == 1000.0  # ROS#'s defaults, not the URDF's <limit>
    joint = found["ConfigurableJoint"]
    assert joint.fields == (
        *CONNECTED,
        ("m_Axis", vector(-1.0, 0.0, 0.0)),  # ROS's y is Unity's -x
        ("m_XMotion", 1),  # Limited: the only degree of freedom
        ("m_YMotion", LOCKED),
        ("m_ZMotion", LOCKED),
        ("m_AngularXMotion", LOCKED),
        ("m_AngularYMotion", LOCKED),
        ("m_AngularZMotion", LOCKED),
        (
            "m_XDrive",
            {
                "serializedVersion": 4,
                "positionSpring": pytest.approx(0.2),  # friction, as ROS# maps it
                "positionDamper": pytest.approx(0.7),
                "maximumForce": 3.4028234663852886e38,  # float.MaxValue
                "useAcceleration": False,
            },
        ),
    )
    manager = found["PrismaticJointLimitsManager"]
    assert manager.fields == (
        ("PositionLimitMin", pytest.approx(-0.05)),
        ("PositionLimitMax", pytest.approx(0.3)),
        ("Tolerance", pytest.approx(0.01)),
    )
    # the limits are float32 as ROS# casts them
    assert manager.field("PositionLimitMax") == 0.30000001192092896


def test_a_prismatic_joint_without_axis_dynamics_or_limit_keeps_rossharps_defaults() -> None:
    found = components("prismatic", "")
    joint = found["ConfigurableJoint"]
    assert joint.field("m_Axis") == vector(-1.0, 0.0, 0.0)  # GetDefaultAxis
    assert joint.field("m_XDrive") is None
    assert joint.field("m_LinearLimit") is None  # the manager limits it at run time
    assert found["PrismaticJointLimitsManager"].fields == (("Tolerance", pytest.approx(0.01)),)


def test_a_floating_joint_gets_a_configurable_joint_free_in_every_direction() -> None:
    found = components("floating", '<axis xyz="0 0 1"/><dynamics damping="1"/>')
    assert list(found) == [
        "UrdfLink",
        "Rigidbody",
        "UrdfInertial",
        "UrdfJointFloating",
        "ConfigurableJoint",
    ]
    assert found["ConfigurableJoint"].fields == CONNECTED  # motions stay a new joint's Free
    assert found["UrdfJointFloating"].field("_jointType").value == 3  # type: ignore[union-attr]


def test_a_planar_joint_about_z_moves_in_unitys_forward_and_left_plane() -> None:
    found = components(
        "planar",
        '<axis xyz="0 0 1"/><limit effort="1" velocity="1" upper="0.5"/>'
        '<dynamics damping="2" friction="1"/>',
    )
    joint = found["ConfigurableJoint"]
    drive = {
        "serializedVersion": 4,
        "positionSpring": 1.0,
        "positionDamper": 2.0,
        "maximumForce": 3.4028234663852886e38,
        "useAcceleration": False,
    }
    assert joint.fields == (
        *CONNECTED,
        ("m_Axis", vector(0.0, 0.0, 1.0)),  # Vector3.forward
        ("m_SecondaryAxis", vector(-1.0, 0.0, 0.0)),  # Vector3.left
        ("m_XMotion", 2),
        ("m_YMotion", 2),
        ("m_ZMotion", LOCKED),
        ("m_AngularXMotion", LOCKED),
        ("m_AngularYMotion", LOCKED),
        ("m_AngularZMotion", LOCKED),
        ("m_LinearLimit", {"limit": 0.5, "bounciness": 0.0, "contactDistance": 0.0}),
        ("m_XDrive", drive),
        ("m_YDrive", drive),
    )
    assert "PrismaticJointLimitsManager" not in found


@pytest.mark.parametrize(
    ("axis", "shown"),
    [
        ("", "none: ROS#'s default"),
        ('<axis xyz="1 0 0"/>', "1 0 0"),
        ('<axis xyz="0 1 1"/>', "0 1 1"),
    ],
)
def test_a_planar_joint_with_another_normal_is_refused_at_its_joint(
    tmp_path: Path, axis: str, shown: str
) -> None:
    urdf = robot(
        tmp_path,
        joint("plane", "planar", "a", axis) + joint("ok", "planar", "b", '<axis xyz="0 0 -1"/>'),
    )
    with pytest.raises(LocatedError) as caught:
        import_robot(urdf, packages={}, project=tmp_path)
    (only,) = caught.value.diagnostics
    assert str(only.location) == f"{urdf}:5:3"
    assert only.message.startswith(f"planar joint 'plane' has a normal ({shown}) that is not")
    assert only.hint and '<axis xyz="0 0 1"/>' in only.hint


@pytest.mark.parametrize("kind", ["prismatic", "planar", "floating"])
def test_such_a_joint_without_a_rigidbody_on_its_child_gets_no_unity_joint(
    tmp_path: Path, kind: str
) -> None:
    """ROS# adds no Unity joint then (a planar one is not refused either)."""
    urdf = robot(
        tmp_path, joint("j", kind, "a", "") + joint("k", "fixed", "b"), child_inertial=False
    )
    result = import_robot(urdf, packages={}, project=tmp_path)
    link = result.objects.children[1].children[2]
    assert link.name == "a" and "ConfigurableJoint" not in link.component_names


def test_prismatic_and_floating_joints_of_one_robot_are_both_imported(tmp_path: Path) -> None:
    urdf = robot(tmp_path, joint("slide", "prismatic", "a") + joint("free", "floating", "b"))
    result = import_robot(urdf, packages={}, project=tmp_path)
    slide, free = result.objects.children[1].children[2:]
    assert slide.component_names[-3:] == [
        "UrdfJointPrismatic",
        "ConfigurableJoint",
        "PrismaticJointLimitsManager",
    ]
    assert free.component_names[-2:] == ["UrdfJointFloating", "ConfigurableJoint"]
