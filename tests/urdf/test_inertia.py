"""Principal moments and axes of an inertia tensor, as ROS#'s Matrix3x3 finds them."""

from __future__ import annotations

import pytest

from unityscaffold.urdf._inertia import principal_axes

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
