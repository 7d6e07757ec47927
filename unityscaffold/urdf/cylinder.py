"""The Mesh of a cylinder collider, as ROS#'s importer makes it in code.

Unity has no cylinder collider, so ROS# gives a ``<cylinder>`` collision a convex MeshCollider
with a mesh of its own: ``UrdfGeometry.CreateCylinderMesh`` for Unity's unit cylinder (radius
0.5, height 2), 30 sides, saved inside the scene (one copy per collider). Its quirks are kept,
as the scene holds them: the side loop runs on past one turn (900 pairs of side vertices where
30 are meant), the top cap's UVs use the vertex number where the ring number is meant, and the
363 indices reach vertices 0 to 123 only.

Angles are ``(float)i / 30 * 2π`` computed in double and stored as float32, as Unity's Mono
runs the C#; sines and cosines are float32 (``Mathf.Sin``).
"""

from __future__ import annotations

import math
import struct

from unityscaffold.unity.mesh import MeshData
from unityscaffold.urdf.transforms import f32 as _f32

__all__ = ["cylinder_collider_mesh"]

_SIDES = 30
_RING = _SIDES + 1  # a cap: its centre and the ring
_VERTICES = 2 * _RING + _SIDES * _SIDES * 2 + 2
_RADIUS, _HALF_HEIGHT = 0.5, 1.0


_TWO_PI = _f32(_f32(math.pi) * 2)


def _angle(step: int) -> float:
    return _f32(step / _SIDES * _TWO_PI)


def _cos(step: int) -> float:
    return _f32(math.cos(_angle(step)))


def _sin(step: int) -> float:
    return _f32(math.sin(_angle(step)))


def _point(step: int, y: float) -> tuple[float, float, float]:
    return (_f32(_cos(step) * _RADIUS), y, _f32(_sin(step) * _RADIUS))


def _uv(step: int) -> tuple[float, float]:
    return (_f32(_cos(step) * 0.5 + 0.5), _f32(_sin(step) * 0.5 + 0.5))


def cylinder_collider_mesh() -> MeshData:
    """The vertices (with normals and UVs) and indices of ROS#'s cylinder collider mesh."""
    down, up = -_HALF_HEIGHT, _HALF_HEIGHT
    points = [(0.0, down, 0.0)] + [_point(i, down) for i in range(1, _RING)]
    points += [(0.0, up, 0.0)] + [_point(i, up) for i in range(1, _RING)]
    normals = [(0.0, -1.0, 0.0)] * _RING + [(0.0, 1.0, 0.0)] * _RING
    uvs = [(0.5, 0.5)] + [_uv(i) for i in range(1, _RING)]
    uvs += [(0.5, 0.5)] + [_uv(i) for i in range(_RING + 1, 2 * _RING)]
    pairs = (_VERTICES - 2 * _RING - 2) // 2
    for step in range(pairs):
        points += [_point(step, up), _point(step, down)]
        side = (_cos(step), 0.0, _sin(step))
        normals += [side, side]
        u = _f32(step / _SIDES)
        uvs += [(u, 1.0), (u, 0.0)]
    # the seam repeats the first side pair, with UVs at the end of the texture
    points += points[2 * _RING : 2 * _RING + 2]
    normals += normals[2 * _RING : 2 * _RING + 2]
    uvs += [(1.0, 1.0), (1.0, 0.0)]
    values = [v for p, n, uv in zip(points, normals, uvs, strict=True) for v in (*p, *n, *uv)]
    vertices = struct.pack(f"<{len(values)}f", *values)
    return MeshData(vertices, _triangles(), uv=True)


def _triangles() -> list[int]:
    """``CreateCylinderMesh``'s index loops, counter for counter."""
    triangles = 2 * _SIDES + 2 * _SIDES
    out: list[int] = []
    for tri in range(_SIDES - 1):  # bottom cap
        out += [0, tri + 1, tri + 2]
    out += [0, _SIDES, 1]
    for tri in range(_SIDES, 2 * _SIDES):  # top cap
        out += [tri + 2, tri + 1, _RING]
    out += [_RING + 1, 2 * _SIDES + 1, _RING]
    tri = 2 * _SIDES + 2
    while tri <= triangles:  # sides
        out += [tri + 2, tri + 1, tri, tri + 2, tri + 3, tri + 1]
        tri += 2
    return out
