"""The gripper's pose integration: the float path gives the numpy path's numbers, bit for bit."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from tautwire.errors import InvalidArgumentError
from tautwire.model.quaternion import as_quaternion, multiply
from tautwire.sim.gripper_state import integrate_pose

_component = st.floats(-3.0, 3.0, allow_nan=False)


def _reference(
    position: np.ndarray,
    orientation: np.ndarray,
    linear: np.ndarray,
    angular: np.ndarray,
    dt: float,
) -> tuple[np.ndarray, np.ndarray]:
    """The pose integration as written with numpy (before it ran on floats)."""
    angle = float(np.linalg.norm(angular)) * dt
    if angle > 0.0:
        axis = angular / np.linalg.norm(angular)
        dq = np.concatenate(([np.cos(0.5 * angle)], np.sin(0.5 * angle) * axis))
        orientation = as_quaternion(multiply(dq, orientation))
    return position + linear * dt, orientation


@settings(max_examples=300, deadline=None)
@given(
    st.lists(_component, min_size=3, max_size=3),
    st.lists(_component, min_size=4, max_size=4).filter(lambda q: sum(c * c for c in q) > 0.01),
    st.lists(_component, min_size=3, max_size=3),
    st.lists(_component, min_size=3, max_size=3),
    st.sampled_from([0.001, 0.003, 0.004, 0.1]),
)
def test_integrate_pose_equals_the_numpy_formula_exactly(
    p: list[float], q: list[float], v: list[float], w: list[float], dt: float
) -> None:
    position, linear, angular = np.array(p), np.array(v), np.array(w)
    orientation = as_quaternion(q)
    got = integrate_pose(position, orientation, linear, angular, dt)
    want = _reference(position, orientation, linear, angular, dt)
    assert np.array_equal(got[0], want[0])
    assert np.array_equal(got[1], want[1])


def test_integrate_pose_keeps_the_orientation_without_rotation() -> None:
    q = as_quaternion([0.9, 0.1, -0.2, 0.3])
    p, out = integrate_pose(np.zeros(3), q, np.array([0.1, 0.0, 0.0]), np.zeros(3), 0.5)
    assert out is q
    assert np.allclose(p, [0.05, 0.0, 0.0])


def test_integrate_pose_refuses_a_non_finite_rotation() -> None:
    q = np.array([np.nan, 0.0, 0.0, 0.0])
    with pytest.raises(InvalidArgumentError, match="not a rotation"):
        integrate_pose(np.zeros(3), q, np.zeros(3), np.array([0.0, 0.0, 1.0]), 0.1)
