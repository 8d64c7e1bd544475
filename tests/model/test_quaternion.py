import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.spatial.transform import Rotation

from tautwire.errors import InvalidArgumentError
from tautwire.model.quaternion import (
    as_quaternion,
    conjugate,
    from_rotation,
    multiply,
    orientation_along,
    rotate,
    to_rotation,
)

vectors = st.lists(st.floats(-1, 1), min_size=3, max_size=3).filter(
    lambda v: np.linalg.norm(v) > 1e-3
)


@settings(max_examples=100, deadline=None)
@given(vectors)
def test_orientation_along_points_x_along_the_direction(v: list[float]) -> None:
    q = orientation_along(v)
    x_axis = rotate(q, [1.0, 0.0, 0.0])
    assert x_axis == pytest.approx(np.asarray(v) / np.linalg.norm(v), abs=1e-9)


def test_multiply_matches_scipy() -> None:
    rng = np.random.default_rng(0)
    a, b = as_quaternion(rng.normal(size=4)), as_quaternion(rng.normal(size=4))
    x, y, z, w = (to_rotation(a) * to_rotation(b)).as_quat()  # SciPy's order
    expected = np.array([w, x, y, z])
    product = multiply(a, b)
    assert abs(abs(np.dot(product, expected)) - 1.0) < 1e-12
    assert multiply(a, conjugate(a)) == pytest.approx([1, 0, 0, 0])


def test_rejects_bad_quaternions() -> None:
    with pytest.raises(InvalidArgumentError):
        as_quaternion([0, 0, 0, 0])
    with pytest.raises(InvalidArgumentError):
        as_quaternion([1, 0, 0])


def test_orientation_along_nearly_minus_x() -> None:
    for v in (
        [-1.0, 0.0, 5.960464477539063e-08],
        [-1.0, 1e-9, 0.0],
        [-1.0, 0.0, 0.0],
        [-0.3, 0.01, 0.0],
    ):
        x_axis = rotate(orientation_along(v), [1.0, 0.0, 0.0])
        assert x_axis == pytest.approx(np.asarray(v) / np.linalg.norm(v), abs=1e-12)


def test_turn_x_onto_takes_the_tool_x_axis_onto_a_direction() -> None:
    import numpy as np

    from tautwire.model.quaternion import rotate, turn_x_onto

    rng = np.random.default_rng(3)
    for _ in range(50):
        q = rng.normal(size=4)
        q /= np.linalg.norm(q)
        d = rng.normal(size=3)
        turned = turn_x_onto(q, d)
        assert np.allclose(rotate(turned, [1.0, 0.0, 0.0]), d / np.linalg.norm(d))


@pytest.mark.parametrize("angle", [0.3, -1.2, 2.9])
def test_scipy_rotations_keep_the_scalar_first_convention(angle: float) -> None:
    # [w, x, y, z] about z by angle; SciPy's own order is [x, y, z, w] (any SciPy >= 1.11)
    q = np.array([np.cos(angle / 2), 0.0, 0.0, np.sin(angle / 2)])
    rotated = to_rotation(q).apply([1.0, 0.0, 0.0])
    np.testing.assert_allclose(rotated, [np.cos(angle), np.sin(angle), 0.0], atol=1e-12)
    np.testing.assert_allclose(from_rotation(Rotation.from_rotvec([0, 0, angle])), q, atol=1e-12)
