"""ROS → Unity, as ROS#'s importer converts poses and sizes, in float32 as Unity stores them.

ROS is right-handed with x forward, y left, z up; Unity is left-handed with x right, y up,
z forward. ROS#'s importer maps a point ``(x, y, z)`` to ``(-y, z, x)``, a scale to
``(y, z, x)``, and an origin's ``rpy`` to the Unity Euler angles ``(pitch, -yaw, -roll)`` in
degrees (Unity applies Z, then X, then Y: after the axis swap, ROS's fixed-axis roll, pitch,
yaw). Numbers are cast to float32 first, as ROS# does, and the results are float32 values.
"""

from __future__ import annotations

import math
import struct

from unityscaffold.urdf.model import Box, Cylinder, Geometry, Mesh, Origin, Sphere, Vector3

__all__ = [
    "ALIGNED",
    "IDENTITY",
    "Quaternion",
    "f32",
    "geometry_scale",
    "origin_position",
    "origin_rotation",
    "unity_axis",
    "unity_position",
    "unity_scale",
]

Quaternion = tuple[float, float, float, float]  # x, y, z, w as a scene stores them
IDENTITY: Quaternion = (0.0, 0.0, 0.0, 1.0)
#: The rotation of an object ROS# parents with its ``SetParentAndAlign`` and does not rotate
#: after: the identity with negative zeros (the product of the parent's rotation and its
#: inverse), as Unity saves it.
ALIGNED: Quaternion = (-0.0, -0.0, -0.0, 1.0)


def f32(value: float) -> float:
    """``value`` rounded to the nearest float32 (C#'s ``(float)`` cast), ±Infinity past its
    range as C#'s is (a model's unit or a node's place can be that large)."""
    try:
        result: float = struct.unpack("<f", struct.pack("<f", value))[0]
    except OverflowError:
        return math.copysign(math.inf, value)
    return result


_PI = f32(math.pi)  # Mathf.PI
DEG2RAD = f32(_PI * 2.0 / 360.0)  # Mathf.Deg2Rad
# Mathf.Rad2Deg is 1 / Deg2Rad in float32: 57.29578018…, not the float32 nearest 180/π (the
# scene's quaternions of rpy 1.57075 and -3.1415 match Unity's bit for bit only with this one)
RAD2DEG = f32(1.0 / DEG2RAD)


def unity_position(xyz: Vector3) -> Vector3:
    """A ROS point or direction in Unity's axes: ``(-y, z, x)``."""
    x, y, z = (f32(v) for v in xyz)
    return (-y, z, x)


def unity_scale(xyz: Vector3) -> Vector3:
    """A ROS scale in Unity's axes: ``(y, z, x)`` (no sign: a scale has no direction)."""
    x, y, z = (f32(v) for v in xyz)
    return (y, z, x)


def unity_axis(axis: Vector3 | None) -> Vector3:
    """A joint's axis for a Unity joint; ROS#'s default when ``<axis>`` is absent is
    ``(-1, 0, 0)`` (Unity's -x, ROS's y), not URDF's default x axis."""
    return (-1.0, 0.0, 0.0) if axis is None else unity_position(axis)


def origin_position(origin: Origin | None) -> Vector3:
    """Where an ``<origin>`` puts an object, in its parent's Unity axes."""
    if origin is None or origin.xyz is None:
        return (0.0, 0.0, 0.0)
    x, y, z = unity_position(origin.xyz)
    return (x + 0.0, y + 0.0, z + 0.0)  # Unity's Translate adds: a -0 comes out as 0


def origin_rotation(origin: Origin | None) -> Quaternion:
    """The local rotation an ``<origin rpy>`` gives, as ``Quaternion.Euler(p, -y, -r)``.

    Without ``<origin>`` ROS# does not rotate the object (``ALIGNED``); with one it rotates
    ``ALIGNED`` by the Euler angles (zero without ``rpy``), which leaves no negative zero.
    """
    if origin is None:
        return ALIGNED
    if origin.rpy is None:
        return IDENTITY
    roll, pitch, yaw = origin.rpy
    # (float)x * Mathf.Rad2Deg in ROS#, then Quaternion.Euler's degrees → radians in Unity
    degrees = (f32(f32(pitch) * RAD2DEG), f32(f32(-yaw) * RAD2DEG), f32(f32(-roll) * RAD2DEG))
    return _euler_radians(*(f32(d * DEG2RAD) for d in degrees))


def _euler_radians(x: float, y: float, z: float) -> Quaternion:
    """Unity's Euler rotation (Z, then X, then Y: ``qy * qx * qz``) of angles in radians."""
    sx, cx = math.sin(x / 2), math.cos(x / 2)
    sy, cy = math.sin(y / 2), math.cos(y / 2)
    sz, cz = math.sin(z / 2), math.cos(z / 2)
    return (
        f32(cy * sx * cz + sy * cx * sz) + 0.0,
        f32(sy * cx * cz - cy * sx * sz) + 0.0,
        f32(cy * cx * sz - sy * sx * cz) + 0.0,
        f32(cy * cx * cz + sy * sx * sz) + 0.0,
    )


def geometry_scale(geometry: Geometry) -> Vector3:
    """The scale ROS#'s importer gives the object holding a visual or collision: Unity's unit
    primitives (a 1 m cube, a cylinder 2 m high and 1 m across, a sphere 1 m across) sized to
    the shape; a mesh's own ``scale``, or 1."""
    if isinstance(geometry, Box):
        return unity_scale(geometry.size)
    if isinstance(geometry, Cylinder):
        diameter = f32(f32(geometry.radius) * 2)
        return (diameter, f32(f32(geometry.length) / 2), diameter)
    if isinstance(geometry, Sphere):
        diameter = f32(f32(geometry.radius) * 2)
        return (diameter, diameter, diameter)
    assert isinstance(geometry, Mesh)
    return (1.0, 1.0, 1.0) if geometry.scale is None else unity_scale(geometry.scale)
