"""Joints that would need a ConfigurableJoint: refused at the joint, all of them at once."""

from __future__ import annotations

from pathlib import Path

import pytest

from unityscaffold.errors import LocatedError
from unityscaffold.urdf import import_robot

INERTIAL = (
    '<inertial><mass value="1"/>'
    '<inertia ixx="1" ixy="0" ixz="0" iyy="1" iyz="0" izz="1"/></inertial>'
)


def robot(tmp_path: Path, joints: str, *, child_inertial: bool = True) -> Path:
    child = INERTIAL if child_inertial else ""
    urdf = tmp_path / "r.urdf"
    urdf.write_text(
        f'<robot name="r">\n<link name="p">{INERTIAL}</link>\n'
        f'<link name="a">{child}</link>\n<link name="b">{child}</link>\n{joints}</robot>\n',
        encoding="utf-8",
    )
    return urdf


def joint(name: str, kind: str, child: str) -> str:
    return (
        f'  <joint name="{name}" type="{kind}"><parent link="p"/><child link="{child}"/>'
        '<limit effort="1" velocity="1"/></joint>\n'
    )


def test_prismatic_planar_and_floating_joints_are_each_refused_at_their_joint(
    tmp_path: Path,
) -> None:
    urdf = robot(tmp_path, joint("slide", "prismatic", "a") + joint("free", "floating", "b"))
    with pytest.raises(LocatedError) as caught:
        import_robot(urdf, packages={}, project=tmp_path)
    first, second = caught.value.diagnostics
    assert str(first.location) == f"{urdf}:5:3" and str(second.location) == f"{urdf}:6:3"
    assert first.message.startswith("prismatic joint 'slide' needs a ConfigurableJoint")
    assert second.message.startswith("floating joint 'free' needs a ConfigurableJoint")
    assert first.hint and "revolute, continuous or fixed" in first.hint


@pytest.mark.parametrize("kind", ["prismatic", "planar", "floating"])
def test_such_a_joint_without_a_rigidbody_on_its_child_is_imported(
    tmp_path: Path, kind: str
) -> None:
    """ROS# adds no Unity joint then: nothing needs the unchecked layout."""
    urdf = robot(tmp_path, joint("j", kind, "a") + joint("k", "fixed", "b"), child_inertial=False)
    result = import_robot(urdf, packages={}, project=tmp_path)
    link = result.objects.children[1].children[2]
    assert link.name == "a" and "ConfigurableJoint" not in link.component_names
