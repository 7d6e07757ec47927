"""ROS → Unity rules: axes, rpy → quaternion, shape sizes, all in float32."""

from __future__ import annotations

import math

import pytest

from unityscaffold.urdf.model import Box, Cylinder, Mesh, Origin, Sphere
from unityscaffold.urdf.transforms import (
    ALIGNED,
    IDENTITY,
    RAD2DEG,
    f32,
    geometry_scale,
    origin_position,
    origin_rotation,
    unity_axis,
    unity_position,
    unity_scale,
)

HALF = math.sqrt(0.5)


def test_ros_axes_map_to_unitys_forward_left_up_as_rossharp_does() -> None:
    # ROS x (forward) → Unity z, ROS y (left) → Unity -x, ROS z (up) → Unity y
    assert unity_position((1, 2, 3)) == (-2, 3, 1)
    assert unity_scale((1, 2, 3)) == (2, 3, 1)


def test_numbers_are_cast_to_float32_first() -> None:
    assert unity_position((0.1, 0, 0)) == (-0.0, 0.0, f32(0.1)) and f32(0.1) != 0.1
    assert f32(57.29578) == RAD2DEG


def test_a_joint_without_axis_gets_rossharps_default_not_urdfs() -> None:
    assert unity_axis(None) == (-1, 0, 0)
    assert unity_axis((1, 0, 0)) == (-0.0, 0, 1)


def test_an_origin_position_has_no_negative_zero() -> None:
    position = origin_position(Origin((1, 0, 0)))
    assert position == (0, 0, 1) and math.copysign(1, position[0]) == 1


@pytest.mark.parametrize(
    ("rpy", "quaternion"),
    [
        ((math.pi / 2, 0, 0), (0, 0, -HALF, HALF)),  # roll about ROS x = about Unity -z
        (
            (0, math.pi / 2, 0),
            (HALF, 0, 0, HALF),
        ),  # pitch about ROS y = about Unity -x, left-handed
        ((0, 0, math.pi / 2), (0, -HALF, 0, HALF)),  # yaw about ROS z = about Unity -y
    ],
)
def test_rpy_turns_about_unitys_axes(
    rpy: tuple[float, float, float], quaternion: tuple[float, ...]
) -> None:
    assert origin_rotation(Origin(rpy=rpy)) == pytest.approx(quaternion, abs=1e-6)


def test_roll_pitch_yaw_compose_as_fixed_axes_in_that_order() -> None:
    # ROS: R = Rz(yaw) Ry(pitch) Rx(roll); the x axis of the rotated frame must point where
    # R sends (1, 0, 0), converted to Unity's axes
    roll, pitch, yaw = 0.3, -0.7, 1.1
    x, y, z, w = origin_rotation(Origin(rpy=(roll, pitch, yaw)))
    ros_x = (
        math.cos(yaw) * math.cos(pitch),
        math.sin(yaw) * math.cos(pitch),
        -math.sin(pitch),
    )
    expected = unity_position(ros_x)
    v = (0.0, 0.0, 1.0)  # ROS x in Unity's axes
    # rotate v by the quaternion (x, y, z, w)
    tx, ty, tz = 2 * (y * v[2] - z * v[1]), 2 * (z * v[0] - x * v[2]), 2 * (x * v[1] - y * v[0])
    rotated = (
        v[0] + w * tx + (y * tz - z * ty),
        v[1] + w * ty + (z * tx - x * tz),
        v[2] + w * tz + (x * ty - y * tx),
    )
    assert rotated == pytest.approx(expected, abs=1e-6)


def test_no_origin_leaves_rossharps_alignment_and_an_origin_without_rpy_the_identity() -> None:
    assert [math.copysign(1, v) for v in origin_rotation(None)] == [-1, -1, -1, 1]
    assert origin_rotation(None) == ALIGNED
    assert origin_rotation(Origin(xyz=(1, 2, 3))) == IDENTITY
    assert all(math.copysign(1, v) == 1 for v in origin_rotation(Origin(rpy=(0, 0, 0))))


def test_shapes_scale_unitys_unit_primitives() -> None:
    assert geometry_scale(Box((0.6, 0.1, 0.2))) == (f32(0.1), f32(0.2), f32(0.6))
    assert geometry_scale(Cylinder(0.2, 0.6)) == (f32(0.4), f32(0.3), f32(0.4))
    assert geometry_scale(Sphere(0.25)) == (0.5, 0.5, 0.5)
    assert geometry_scale(Mesh("package://p/m.stl")) == (1, 1, 1)
    assert geometry_scale(Mesh("package://p/m.stl", (1, 2, 3))) == (2, 3, 1)
