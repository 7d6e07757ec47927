"""A link whose inertia ROS# cannot diagonalize is imported as ROS# imports it, never refused
and never a traceback (issue 27: a robot whose inertia entries are all 1e-08 ended in exit 3).

What the scene holds, derived from ROS#'s code (Runtime/Urdf/UrdfComponents/UrdfInertial.cs
and Runtime/Urdf/Math/Matrix3x3.cs; the derivation is in tests/urdf/test_inertia.py): the
moments are finite and below ``MinInertia``, so ``FixMinInertia`` raises each to 1e-6; the
rotation is NaN in all four components, and ``UpdateRigidBodyData`` hands the same values to
the Rigidbody. Unity writes a float NaN as ``NaN`` (docs/unity-yaml.md). Apply says so in a
note, since Unity's physics cannot simulate such a link."""

from __future__ import annotations

from pathlib import Path

from robot_helpers import SCENE, apply_robot, apply_writes_nothing, init_project

TINY = (
    '<robot name="bot"><link name="base"><inertial><mass value="1"/>'
    '<inertia ixx="1e-08" ixy="1e-08" ixz="1e-08" iyy="1e-08" iyz="1e-08" izz="1e-08"/>'
    "</inertial></link></robot>\n"
)
NAN = "{x: NaN, y: NaN, z: NaN, w: NaN}"


def test_a_tensor_of_tiny_entries_imports_with_rossharps_minimum_moments_and_nan_axes(
    tmp_path: Path,
) -> None:
    project = init_project(tmp_path, {"ros/bot.urdf": TINY})
    run = apply_robot(project)
    assert run.code == 0, run.err
    scene = (project / SCENE).read_text()
    assert "  m_InertiaTensor: {x: 0.000001, y: 0.000001, z: 0.000001}\n" in scene
    assert f"  m_InertiaRotation: {NAN}\n" in scene  # the Rigidbody
    assert f"  UrdfInertiaTensorRotation: {NAN}\n" in scene  # UrdfInertial
    assert f"  InertiaTensorRotation: {NAN}\n" in scene
    assert (
        "note: robot bot: link base's inertia tensor gives ROS#'s importer NaN or infinite "
        "inertia values, as in Unity's editor" in run.out.replace("\n  ", " ")
    )
    apply_writes_nothing(project)
    assert apply_robot(project, "", "--check").code == 0
