"""Principal moments and axes of an inertia tensor, as ROS#'s Matrix3x3 finds them (Runtime/Urdf/
Math/Matrix3x3.cs, in float32), for every valid tensor: where ROS#'s arithmetic divides by zero
the values are its NaN and Infinity, never an exception."""

from __future__ import annotations

import itertools
import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from unityscaffold.urdf._inertia import principal_axes
from unityscaffold.urdf.transforms import f32

Tensor = tuple[tuple[float, float, float], ...]


def _rotation(q: tuple[float, float, float, float]) -> list[list[float]]:
    x, y, z, w = q
    return [
        [1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
        [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
        [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)],
    ]


@pytest.mark.parametrize(
    "tensor",
    [
        ((2.0, 1.0, 0.0), (1.0, 2.0, 0.0), (0.0, 0.0, 5.0)),
        ((4.0, 0.5, 0.2), (0.5, 3.0, 0.1), (0.2, 0.1, 1.0)),
        ((1.0, 0.1, 0.0), (0.1, 1.0, 0.0), (0.0, 0.0, 1.0)),
        # two equal moments: any axes of their plane will do
        ((2.0, 0.0, 0.0), (0.0, 1.5, 0.5), (0.0, 0.5, 1.5)),
    ],
)
def test_the_axes_turn_the_moments_back_into_the_tensor(tensor: Tensor) -> None:
    """R · diag(moments) · Rᵀ is the tensor again, within float32 precision."""
    moments, quaternion = principal_axes(tensor)  # type: ignore[arg-type]
    r = _rotation(quaternion)
    rebuilt = [
        [sum(r[i][k] * moments[k] * r[j][k] for k in range(3)) for j in range(3)] for i in range(3)
    ]
    assert rebuilt == [pytest.approx(list(row), abs=2e-6) for row in tensor]
    assert sum(c * c for c in quaternion) == pytest.approx(1, abs=1e-6)


def test_a_diagonal_tensor_keeps_its_moments_in_order_and_the_identity() -> None:
    assert principal_axes(((3.0, 0, 0), (0, 1.0, 0), (0, 0, 2.0))) == ((3, 1, 2), (0, 0, 0, 1))


def _tensor(xx: float, xy: float, xz: float, yy: float, yz: float, zz: float) -> Tensor:
    """The tensor as ROS#'s ``UrdfInertial.ToMatrix3x3`` builds it: each entry cast to float."""
    a, b, c, d, e, f = (f32(v) for v in (xx, xy, xz, yy, yz, zz))
    return ((a, b, c), (b, d, e), (c, e, f))


def _all_nan(values: tuple[float, ...]) -> bool:
    return all(math.isnan(v) for v in values)


def test_a_tensor_of_tiny_entries_has_rossharps_nan_axes_and_finite_moments() -> None:
    """Every entry 1e-8 (a robot description seen in the wild). By hand from Matrix3x3.cs: the
    eigenvalues are finite (≈3e-8 and two of order 1e-15, unequal, so IsTwoEigenvaluesEqual is
    false); the rows of A − λ₀I differ by about one float32 step of 1e-8 (≈9e-16), so their cross
    products are of order 1e-8 · 9e-16 ≈ 1e-23 and their squared lengths (≈1e-46) fall below
    float32's smallest subnormal (1.4e-45): every ``dot`` is 0, GetEigenvector0 divides by
    Mathf.Sqrt(0) (±Infinity, or NaN for a zero component), and Infinity − Infinity and
    0 · Infinity make every later value NaN, down to all four of ToQuaternion's components."""
    moments, rotation = principal_axes(_tensor(1e-8, 1e-8, 1e-8, 1e-8, 1e-8, 1e-8))
    assert moments[0] == pytest.approx(3e-8, rel=1e-6)
    assert all(abs(m) < 1e-14 for m in moments[1:]) and moments[1] != moments[2]
    assert _all_nan(rotation)


# The pair of Unity-Robotics-Hub issue 343 (https://github.com/Unity-Technologies/
# Unity-Robotics-Hub/issues/343, repository cedricgoubard/DemoBugURDF, line 183 of its two
# URDFs): Unity's URDF-Importer, whose Runtime/Math/Matrix3x3.cs is ROS#'s, shows NaN in the
# link's "URDF Inertia Tensor Rotation" for the second and finite values for the first.
WORKING = (0.0024847, 8.549e-18, 3.8142e-20, 0.0045217, -3.8877e-20, 0.0024847)
NOT_WORKING = (0.0024847, 8.549e-18, 1.0955e-20, 0.0045217, -3.8877e-20, 0.0024847)


def test_the_tensors_of_the_urdf_importers_nan_report_give_its_finite_and_nan_rotations() -> None:
    moments, rotation = principal_axes(_tensor(*WORKING))
    assert all(math.isfinite(v) for v in (*moments, *rotation))
    moments, rotation = principal_axes(_tensor(*NOT_WORKING))
    assert moments == pytest.approx((0.0045217, 0.0024847, 0.0024847), rel=1e-6)
    assert _all_nan(rotation)


def test_off_diagonals_whose_squares_vanish_in_float32_give_nan_everywhere() -> None:
    """ixy = 1e-30 with equal moments: p1 = (1e-30)² is 0 in float32 and the diagonal's
    deviations from q are 0, so p = Mathf.Sqrt(0) = 0; B = A·(1/p) + diag(−q/p) holds
    1·Infinity − Infinity = NaN on its diagonal, its determinant is NaN, Mathf.Clamp keeps NaN,
    Mathf.Acos(NaN) is NaN, and so is every α = p·β + q; the eigenvectors follow (NaN == NaN is
    false, so no two eigenvalues count as equal)."""
    moments, rotation = principal_axes(_tensor(1, 1e-30, 0, 1, 0, 1))
    assert _all_nan(moments) and _all_nan(rotation)


def test_a_zero_tensor_is_diagonal_and_keeps_the_identity() -> None:
    """IsDiagonal() is true for all zeros: the moments are the zero diagonal, the axes the
    identity (UrdfInertial's FixMinInertia then raises the moments to 1e-6)."""
    assert principal_axes(_tensor(0, 0, 0, 0, 0, 0)) == ((0, 0, 0), (0, 0, 0, 1))


def _rotated(moments: tuple[float, float, float], q: tuple[float, float, float, float]) -> Tensor:
    r = _rotation(q)
    return tuple(  # type: ignore[return-value]
        tuple(sum(r[i][k] * moments[k] * r[j][k] for k in range(3)) for j in range(3))
        for i in range(3)
    )


finite = st.floats(-1, 1, allow_nan=False, allow_infinity=False)
scales = st.sampled_from([1e-12, 1e-8, 1e-6, 1e-3, 1.0, 1e3, 1e6])


@st.composite
def tensors(draw: st.DrawFn) -> Tensor:
    """Physically valid tensors of every shape: any moments (equal, zero, tiny, large) turned
    by any rotation, diagonal ones, all-equal entries, and rank-one ones (a point's)."""
    scale = draw(scales)
    kind = draw(st.sampled_from(["rotated", "diagonal", "equal", "rank one"]))
    if kind == "diagonal":
        a, b, c = (abs(draw(finite)) * scale for _ in range(3))
        return _tensor(a, 0, 0, b, 0, c)
    if kind == "equal":
        v = abs(draw(finite)) * scale
        return _tensor(v, v, v, v, v, v)
    if kind == "rank one":
        x, y, z = draw(finite), draw(finite), draw(finite)
        return _tensor(
            x * x * scale, x * y * scale, x * z * scale, y * y * scale, y * z * scale, z * z * scale
        )
    q = [draw(finite) for _ in range(4)]
    norm = math.sqrt(sum(c * c for c in q)) or 1.0
    moments = tuple(abs(draw(finite)) * scale for _ in range(3))
    (a, b, c), (_, d, e), (_, _, f) = _rotated(moments, tuple(c / norm for c in q))  # type: ignore[arg-type]
    return _tensor(a, b, c, d, e, f)


@settings(max_examples=150, deadline=None)
@given(tensor=tensors())
def test_any_valid_tensor_gives_float32_values_without_an_exception(tensor: Tensor) -> None:
    """No tensor raises (C#'s float arithmetic never throws); every value is a float32 (or
    NaN/±Infinity, where ROS#'s arithmetic makes them); and where the moments are far apart
    for float32 (relative gaps above 1e-3) the values are finite and the moments, Smith's
    closed form, add up to the trace. (The axes are not checked against the tensor: ROS#'s
    GetEigenvector1 takes m00 where m01 belongs on one branch, and this keeps its result.)"""
    moments, rotation = principal_axes(tensor)
    for value in (*moments, *rotation):
        assert math.isnan(value) or f32(value) == value
    values = sorted(abs(v) for v in moments if math.isfinite(v))
    largest = max(abs(v) for row in tensor for v in row)
    gaps = [b - a for a, b in itertools.pairwise(values)]
    if len(values) == 3 and largest > 1e-3 and min(values[0], *gaps) > 1e-3 * largest:
        assert all(math.isfinite(v) for v in rotation)
        trace = tensor[0][0] + tensor[1][1] + tensor[2][2]
        assert sum(moments) == pytest.approx(trace, abs=1e-5 * largest)
