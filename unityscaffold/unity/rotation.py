"""Euler angles in degrees (as Unity's Inspector shows them) to the quaternion a scene stores.

Unity applies the Euler angles of a Transform in the order Z, then X, then Y (``Quaternion.Euler``),
so the rotation is ``qy * qx * qz``. Half-angles that are multiples of 45° use exact sines and
cosines (0, ±1, ±√½), so right angles give clean quaternions whatever the platform's libm; the
rest is computed in double precision and written, like every float, as the nearest float32.
"""

from __future__ import annotations

import math

__all__ = ["euler_to_quaternion"]

_SQRT_HALF = math.sqrt(0.5)
# sin and cos of k·45° for k = 0..7
_EXACT = tuple(
    (
        (0.0, _SQRT_HALF, 1.0, _SQRT_HALF, 0.0, -_SQRT_HALF, -1.0, -_SQRT_HALF)[k],
        (1.0, _SQRT_HALF, 0.0, -_SQRT_HALF, -1.0, -_SQRT_HALF, 0.0, _SQRT_HALF)[k],
    )
    for k in range(8)
)


def _half_sin_cos(degrees: float) -> tuple[float, float]:
    half = (degrees / 2.0) % 360.0
    steps = half / 45.0
    if steps == int(steps):
        return _EXACT[int(steps) % 8]
    radians = math.radians(half)
    return math.sin(radians), math.cos(radians)


def euler_to_quaternion(x: float, y: float, z: float) -> tuple[float, float, float, float]:
    """``Quaternion.Euler(x, y, z)`` as ``(x, y, z, w)``; angles in degrees."""
    sx, cx = _half_sin_cos(x)
    sy, cy = _half_sin_cos(y)
    sz, cz = _half_sin_cos(z)
    return (
        cy * sx * cz + sy * cx * sz,
        sy * cx * cz - cy * sx * sz,
        cy * cx * sz - sy * sx * cz,
        cy * cx * cz + sy * sx * sz,
    )
