"""The URDF reader follows URDF's grammar into the frozen model, keeping ROS#'s distinctions."""

from __future__ import annotations

import math
from pathlib import Path

import pytest
from robot_helpers import inertial

from unityscaffold.urdf import parse_urdf, read_urdf
from unityscaffold.urdf.model import (
    Box,
    Cylinder,
    Dynamics,
    Inertia,
    JointType,
    Limit,
    Material,
    Mesh,
    Mimic,
    Origin,
    SafetyController,
    Sphere,
)

INERTIAL = inertial(2, (1, 2, 3))


def robot(body: str, name: str = "bot") -> bytes:
    return f'<?xml version="1.0"?>\n<robot name="{name}">\n{body}\n</robot>\n'.encode()


def one_link(inner: str) -> bytes:
    return robot(f'<link name="base">{inner}</link>')


@pytest.mark.parametrize(
    ("shape", "geometry"),
    [
        ('<box size="0.6 0.1 0.2"/>', Box((0.6, 0.1, 0.2))),
        ('<cylinder radius="0.2" length="0.6"/>', Cylinder(0.2, 0.6)),
        ('<sphere radius="0.25"/>', Sphere(0.25)),
        ('<mesh filename="package://p/m.stl"/>', Mesh("package://p/m.stl")),
        (
            '<mesh filename="package://p/m.dae" scale="1 2 3"/>',
            Mesh("package://p/m.dae", (1, 2, 3)),
        ),
    ],
)
def test_every_geometry_is_read_into_its_type(shape: str, geometry: object) -> None:
    link = parse_urdf(one_link(f"<visual><geometry>{shape}</geometry></visual>")).links[0]
    assert link.visuals[0].geometry == geometry


def test_the_first_shape_in_rossharps_order_wins_when_a_geometry_has_two() -> None:
    body = '<collision><geometry><sphere radius="1"/><box size="1 1 1"/></geometry></collision>'
    assert parse_urdf(one_link(body)).links[0].collisions[0].geometry == Box((1, 1, 1))


def test_an_origin_keeps_which_of_its_attributes_were_written() -> None:
    body = (
        '<visual name="v"><origin rpy="0 1.57075 0 " xyz="0 0 -0.3"/>'
        '<geometry><sphere radius="1"/></geometry></visual>'
        '<visual><origin xyz="1 2 3"/><geometry><sphere radius="1"/></geometry></visual>'
        '<visual><geometry><sphere radius="1"/></geometry></visual>'
    )
    first, second, third = parse_urdf(one_link(body)).links[0].visuals
    assert first.name == "v" and first.origin == Origin((0, 0, -0.3), (0, 1.57075, 0))
    assert second.name is None and second.origin == Origin((1, 2, 3), None)
    assert third.origin is None


def test_numbers_may_be_separated_by_any_xml_whitespace() -> None:
    body = '<visual><origin xyz="1\t2  3"/><geometry><sphere radius=" 1e-1 "/></geometry></visual>'
    visual = parse_urdf(one_link(body)).links[0].visuals[0]
    assert visual.origin == Origin((1, 2, 3)) and visual.geometry == Sphere(0.1)


def test_a_link_without_inertial_has_none_and_one_with_it_keeps_mass_inertia_and_origin() -> None:
    bare = parse_urdf(one_link("")).links[0]
    assert bare.inertial is None and bare.visuals == () and bare.collisions == ()
    body = INERTIAL.replace("<mass", '<origin xyz="0 0 0.1" rpy="0 0 1"/><mass')
    inertial = parse_urdf(one_link(body)).links[0].inertial
    assert inertial is not None
    assert inertial.mass == 2 and inertial.inertia == Inertia(1, 0, 0, 2, 0, 3)
    assert inertial.origin == Origin((0, 0, 0.1), (0, 0, 1))


def test_materials_are_read_by_name_inline_with_colour_or_texture_or_not_at_all() -> None:
    geometry = '<geometry><sphere radius="1"/></geometry>'
    body = (
        f'<visual>{geometry}<material name="blue"/></visual>'
        f'<visual>{geometry}<material name="red"><color rgba="1 0 0 1"/></material></visual>'
        f'<visual>{geometry}<material name=""><texture filename="package://p/t.png"/></material></visual>'
        f"<visual>{geometry}</visual>"
    )
    urdf = robot(
        f'<material name="blue"><color rgba="0 0 0.8 1"/></material><link name="l">{body}</link>'
    )
    parsed = parse_urdf(urdf)
    assert parsed.materials == (Material("blue", (0, 0, 0.8, 1)),)
    assert [v.material for v in parsed.links[0].visuals] == [
        Material("blue"),
        Material("red", (1, 0, 0, 1)),
        Material("", texture="package://p/t.png"),
        None,
    ]
    assert parsed.material("blue") == Material("blue", (0, 0, 0.8, 1))


@pytest.mark.parametrize("kind", list(JointType))
def test_every_joint_type_is_read(kind: JointType) -> None:
    limit = '<limit effort="10" velocity="2" lower="-1" upper="1"/>'
    urdf = robot(
        f'<link name="a"/><link name="b"/><joint name="j" type="{kind.value}">'
        f'<parent link="a"/><child link="b"/>{limit}</joint>'
    )
    joint = parse_urdf(urdf).joints[0]
    assert (joint.type, joint.parent, joint.child) == (kind, "a", "b")
    assert joint.limit == Limit(10, 2, -1, 1)


def test_a_joint_keeps_axis_dynamics_mimic_and_safety_controller() -> None:
    urdf = robot(
        '<link name="a"/><link name="b"/><link name="c"/>'
        '<joint name="j" type="revolute"><parent link="a"/><child link="b"/>'
        '<origin xyz="0 0 1" rpy="0 0 3.14"/><axis xyz="0 1 0"/>'
        '<limit effort="1" velocity="1"/><dynamics damping="0.5" friction="0.1"/>'
        '<safety_controller k_velocity="10" soft_lower_limit="-1"/></joint>'
        '<joint name="k" type="continuous"><parent link="b"/><child link="c"/>'
        '<mimic joint="j" multiplier="2"/></joint>'
    )
    j, k = parse_urdf(urdf).joints
    assert j.origin == Origin((0, 0, 1), (0, 0, 3.14)) and j.axis == (0, 1, 0)
    assert j.dynamics == Dynamics(0.5, 0.1)
    assert j.safety_controller is not None and j.safety_controller.k_velocity == 10
    assert j.safety_controller.soft_lower_limit == -1
    assert math.isnan(j.safety_controller.soft_upper_limit)
    assert isinstance(j.safety_controller, SafetyController)
    assert k.mimic is not None and (k.mimic.joint, k.mimic.multiplier) == ("j", 2)
    assert math.isnan(k.mimic.offset) and isinstance(k.mimic, Mimic)


def test_absent_optional_numbers_are_nan_as_rossharp_reads_them() -> None:
    urdf = robot(
        '<link name="a"/><link name="b"/><joint name="j" type="revolute"><parent link="a"/>'
        '<child link="b"/><limit effort="1" velocity="2"/><dynamics damping="0.1"/></joint>'
    )
    joint = parse_urdf(urdf).joints[0]
    assert joint.limit is not None and joint.dynamics is not None
    assert math.isnan(joint.limit.lower) and math.isnan(joint.limit.upper)
    assert joint.dynamics.damping == 0.1 and math.isnan(joint.dynamics.friction)


def test_a_joint_without_axis_has_none_for_the_importer_to_default() -> None:
    urdf = robot(
        '<link name="a"/><link name="b"/><joint name="j" type="continuous">'
        '<parent link="a"/><child link="b"/></joint>'
    )
    assert parse_urdf(urdf).joints[0].axis is None


def test_plugins_keep_their_text_as_xelement_writes_it() -> None:
    urdf = robot(
        '<link name="a"/>\n'
        '<gazebo reference="a">\n  <!-- a comment -->\n  <empty/>\n  <spaced>  \n  </spaced>\n'
        "    <deep><x>1 &amp; 2</x></deep>\n<mixed>text <b/> <c>d</c></mixed></gazebo>\n"
        '<transmission name="t"><type>simple</type></transmission>'
    )
    gazebo, transmission = parse_urdf(urdf).plugins
    assert (gazebo.tag, transmission.tag) == ("gazebo", "transmission")
    assert gazebo.text == (
        '<gazebo reference="a">\n'
        "  <!-- a comment -->\n"
        "  <empty />\n"
        "  <spaced></spaced>\n"
        "  <deep>\n"
        "    <x>1 &amp; 2</x>\n"
        "  </deep>\n"
        "  <mixed>text <b /><c>d</c></mixed>\n"
        "</gazebo>"
    )
    assert transmission.text == '<transmission name="t">\n  <type>simple</type>\n</transmission>'
    assert gazebo.location.line == 4


def test_the_r2d2_the_sample_scene_was_imported_from_is_read_whole(r2d2_urdf: Path) -> None:
    r2d2 = read_urdf(r2d2_urdf)
    assert (r2d2.name, len(r2d2.links), len(r2d2.joints), r2d2.root.name) == (
        "r2d2",
        16,
        15,
        "base_link",
    )
    assert [m.name for m in r2d2.materials] == ["blue", "black", "white"]
    assert [p.tag for p in r2d2.plugins] == ["gazebo"] * 4
    head = next(j for j in r2d2.joints if j.name == "head_swivel")
    assert head.dynamics == Dynamics(0.1, 0.1) and head.axis == (0, 0, 1)
    assert [j.name for j in r2d2.child_joints("base_link")] == [
        "base_to_right_leg",
        "base_to_left_leg",
        "gripper_extension",
        "head_swivel",
    ]
    pole = r2d2.link("gripper_pole").visuals[0]
    assert pole.material is None and pole.origin == Origin((0.1, 0, 0), (0, 1.57075, 0))
    assert r2d2.plugins[3].text == (
        '<gazebo>\n  <plugin filename="ignition-gazebo-joint-state-publisher-system" '
        'name="ignition::gazebo::systems::JointStatePublisher" />\n</gazebo>'
    )
