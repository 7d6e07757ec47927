"""An inertia tensor's principal moments and axes, as ROS#'s ``Matrix3x3`` computes them.

ROS# (``UrdfInertial.ImportInertiaData``) diagonalizes the tensor in float32 with closed forms:
the eigenvalues by Smith's method for symmetric 3×3 matrices (in the order that method gives
them), the eigenvectors by cross products of the rows of ``A - λI`` and an orthogonal
complement, and turns the eigenvectors (as the columns of a rotation) into a quaternion. A
diagonal tensor, or one with two equal eigenvalues, keeps the identity axes. Each statement
is computed in double and stored as float32, as Unity's Mono runs float arithmetic.

C#'s float arithmetic never throws, and neither does this: a division by zero is ±Infinity (NaN
for 0/0), the square root of a negative NaN, a cast past float32's range ±Infinity, and NaN
passes through ``Mathf.Clamp``, ``Mathf.Max`` and comparisons as in C#. So a tensor ROS#
cannot diagonalize gives what ROS# gives: a tiny one (entries of 1e-8, whose products vanish in
float32) has eigenvector cross products of length 0 and a NaN rotation; a non-diagonal one
whose off-diagonal squares vanish has p = 0 and NaN eigenvalues (see docs/unity-yaml.md).
"""

from __future__ import annotations

import math

from unityscaffold.urdf.transforms import Quaternion, f32

__all__ = ["principal_axes"]

Vec = tuple[float, float, float]
Matrix = tuple[Vec, Vec, Vec]
_IDENTITY_AXES: tuple[Vec, Vec, Vec] = ((1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, 1.0))


def _div(a: float, b: float) -> float:
    """IEEE division, as C#'s: ±Infinity for a nonzero over zero, NaN for 0/0."""
    if b != 0 or math.isnan(b):
        return a / b
    if a == 0 or math.isnan(a):
        return math.nan
    return math.copysign(math.inf, a) * math.copysign(1.0, b)


def _sqrt(x: float) -> float:
    """``Mathf.Sqrt``: NaN below zero."""
    return math.nan if x < 0 else math.sqrt(x)


def _cos(x: float) -> float:
    """``Mathf.Cos``: NaN for ±Infinity."""
    return math.nan if math.isinf(x) else math.cos(x)


def _clamp(value: float, low: float, high: float) -> float:
    """``Mathf.Clamp``: NaN stays NaN."""
    if value < low:
        return low
    return high if value > high else value


def _max(a: float, b: float) -> float:
    """``Mathf.Max``: ``a > b ? a : b``, so NaN loses to ``b`` only when it is ``a``."""
    return a if a > b else b


def _sorted(values: Vec) -> list[float]:
    """``Array.Sort`` of floats: NaN first."""
    return sorted(values, key=lambda v: (not math.isnan(v), v))


def principal_axes(tensor: Matrix) -> tuple[Vec, Quaternion]:
    """The eigenvalues (ROS#'s order) and the rotation to the eigenvectors, in ROS's axes."""
    if all(tensor[i][j] == 0 for i in range(3) for j in range(3) if i != j):
        values: Vec = (tensor[0][0], tensor[1][1], tensor[2][2])
        return values, _quaternion(_IDENTITY_AXES)
    values = _eigenvalues(tensor)
    return values, _quaternion(_eigenvectors(tensor, values))


def _eigenvalues(a: Matrix) -> Vec:
    q = f32(f32(a[0][0] + a[1][1] + a[2][2]) / 3)
    p1 = f32(a[0][1] * a[0][1] + a[0][2] * a[0][2] + a[1][2] * a[1][2])
    p2 = f32(sum((a[i][i] - q) * (a[i][i] - q) for i in range(3)) + 2 * p1)
    p = f32(_sqrt(f32(p2 / 6)))
    scale, shift = f32(_div(1, p)), f32(_div(-q, p))
    b = tuple(
        tuple(f32(f32(a[i][j] * scale) + (shift if i == j else 0.0)) for j in range(3))
        for i in range(3)
    )
    det = f32(
        sum(
            b[0][i]
            * (b[1][(i + 1) % 3] * b[2][(i + 2) % 3] - b[1][(i + 2) % 3] * b[2][(i + 1) % 3])
            for i in range(3)
        )
    )
    theta = f32(f32(math.acos(_clamp(f32(det / 2), -1.0, 1.0))) / 3)
    pi = f32(math.pi)
    alpha = [f32(p * f32(2 * f32(_cos(f32(theta + (2 * pi * k) / 3)))) + q) for k in range(3)]
    return (alpha[0], alpha[1], alpha[2])


def _minor(b: list[list[float]], i: int) -> float:
    return f32(b[1][(i + 1) % 3] * b[2][(i + 2) % 3] - b[1][(i + 2) % 3] * b[2][(i + 1) % 3])


def _eigenvectors(a: Matrix, unsorted: Vec) -> tuple[Vec, Vec, Vec]:
    ordered = _sorted(unsorted)
    if ordered[0] == ordered[1] or ordered[1] == ordered[2]:
        return _IDENTITY_AXES
    first = _eigenvector0(a, ordered[0])
    second = _eigenvector1(a, ordered[1], first)
    vectors = [first, second, _cross(first, second)]
    # back to the eigenvalues' own order (first match, as List.IndexOf finds it)
    values, found = list(ordered), []
    for value in unsorted:
        # List.IndexOf compares with float.Equals, for which NaN equals NaN
        index = next(i for i, v in enumerate(values) if v == value or (v != v and value != value))
        found.append(vectors.pop(index))
        values.pop(index)
    return (found[0], found[1], found[2])


def _eigenvector0(a: Matrix, value: float) -> Vec:
    rows = [_row(a, i, value) for i in range(3)]
    crosses = [_cross(rows[0], rows[1]), _cross(rows[0], rows[2]), _cross(rows[1], rows[2])]
    dots = [_dot(c, c) for c in crosses]
    best = 0
    if dots[1] > dots[best]:
        best = 1
    if dots[2] > dots[best]:
        best = 2
    root = f32(_sqrt(dots[best]))
    x, y, z = (f32(_div(c, root)) for c in crosses[best])
    return (x, y, z)


def _row(a: Matrix, i: int, value: float) -> Vec:
    """Row ``i`` of ``a - value·I``."""
    x, y, z = (f32(a[i][j] - (value if i == j else 0.0)) for j in range(3))
    return (x, y, z)


def _eigenvector1(a: Matrix, value: float, w: Vec) -> Vec:
    u, v = _complement(w)
    au, av = _apply(a, u), _apply(a, v)
    m00, m01, m11 = f32(_dot(u, au) - value), _dot(u, av), f32(_dot(v, av) - value)
    if abs(m00) > abs(m11):
        if not _max(abs(m00), abs(m01)) > 0:
            return u
        if abs(m00) >= abs(m01):
            m01 = f32(_div(m01, m00))
            m00 = f32(_div(1, f32(_sqrt(f32(1 + m01 * m01)))))
            m01 = f32(m01 * m00)
        else:
            m00 = f32(_div(m00, m01))
            m01 = f32(_div(1, f32(_sqrt(f32(1 + m00 * m00)))))
            m00 = f32(m00 * m01)
        return _add(_scale(u, m01), _scale(v, -m00))
    if not _max(abs(m11), abs(m01)) > 0:
        return u
    if abs(m11) >= abs(m01):
        m01 = f32(_div(m01, m11))
        m11 = f32(_div(1, f32(_sqrt(f32(1 + m01 * m01)))))
        m01 = f32(m01 * m11)
    else:
        m11 = f32(_div(m11, m01))
        m01 = f32(_div(1, f32(_sqrt(f32(1 + m11 * m11)))))
        m11 = f32(m11 * m01)
    return _add(_scale(u, m11), _scale(v, -m00))  # ROS#'s: m00, not m01, on this branch


def _complement(w: Vec) -> tuple[Vec, Vec]:
    if abs(w[0]) > abs(w[1]):
        inverse = f32(_div(1, f32(_sqrt(f32(w[0] * w[0] + w[2] * w[2])))))
        u = (f32(-w[2] * inverse), 0.0, f32(w[0] * inverse))
    else:
        inverse = f32(_div(1, f32(_sqrt(f32(w[1] * w[1] + w[2] * w[2])))))
        u = (0.0, f32(w[2] * inverse), f32(-w[1] * inverse))
    return u, _cross(w, u)


def _quaternion(axes: tuple[Vec, Vec, Vec]) -> Quaternion:
    """The rotation whose columns are ``axes`` (ROS#'s ``UrdfInertial.ToQuaternion``)."""
    (m00, m10, m20), (m01, m11, m21), (m02, m12, m22) = axes
    trace = f32(m00 + m11 + m22)
    if trace > 0:
        s = f32(f32(_sqrt(f32(trace + 1))) * 2)
        w, x, y, z = f32(0.25 * s), _over(m21 - m12, s), _over(m02 - m20, s), _over(m10 - m01, s)
    elif m00 > m11 and m00 > m22:
        s = f32(f32(_sqrt(f32(1 + m00 - m11 - m22))) * 2)
        w, x, y, z = _over(m21 - m12, s), f32(0.25 * s), _over(m01 + m10, s), _over(m02 + m20, s)
    elif m11 > m22:
        s = f32(f32(_sqrt(f32(1 + m11 - m00 - m22))) * 2)
        w, x, y, z = _over(m02 - m20, s), _over(m01 + m10, s), f32(0.25 * s), _over(m12 + m21, s)
    else:
        s = f32(f32(_sqrt(f32(1 + m22 - m00 - m11))) * 2)
        w, x, y, z = _over(m10 - m01, s), _over(m02 + m20, s), _over(m12 + m21, s), f32(0.25 * s)
    return (x, y, z, w)


def _over(a: float, s: float) -> float:
    return f32(_div(a, s))


def _cross(a: Vec, b: Vec) -> Vec:
    return (
        f32(a[1] * b[2] - a[2] * b[1]),
        f32(a[2] * b[0] - a[0] * b[2]),
        f32(a[0] * b[1] - a[1] * b[0]),
    )


def _dot(a: Vec, b: Vec) -> float:
    return f32(a[0] * b[0] + a[1] * b[1] + a[2] * b[2])


def _apply(m: Matrix, v: Vec) -> Vec:
    return (_dot(m[0], v), _dot(m[1], v), _dot(m[2], v))


def _scale(v: Vec, k: float) -> Vec:
    return (f32(v[0] * k), f32(v[1] * k), f32(v[2] * k))


def _add(a: Vec, b: Vec) -> Vec:
    return (f32(a[0] + b[0]), f32(a[1] + b[1]), f32(a[2] + b[2]))
