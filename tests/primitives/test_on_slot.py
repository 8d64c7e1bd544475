"""A clip's contact estimate moved onto its slot (model_estimator.on_slot)."""

import math

import numpy as np
from hypothesis import given
from hypothesis import strategies as st

from tautwire.primitives.model_estimator import SLOT_STD, on_slot

SEAT = np.array([0.3, 0.1, 0.08])
HALF = 0.015


def _slot(yaw: float) -> np.ndarray:
    return np.array([math.cos(yaw), math.sin(yaw), 0.0])


coordinate = st.floats(-0.03, 0.03)


@given(
    st.floats(-math.pi, math.pi),
    st.tuples(coordinate, coordinate, coordinate),
    st.sampled_from([-1.0, 1.0]),
    st.floats(0.0005, 0.01),
    st.floats(-0.9, 0.9),
)
def test_no_error_grows_and_the_slot_fixes_the_cross_axes(
    yaw: float, offset: tuple[float, float, float], end: float, std: float, rho: float
) -> None:
    u = _slot(yaw)
    truth = SEAT + end * HALF * u  # the cable leaves by an end of the slot
    x = SEAT + np.array(offset)
    a = np.array([[1.0, rho, 0.0], [rho, 1.0, rho / 2], [0.0, rho / 2, 1.0]])
    P = std**2 * (a @ a.T)
    on, covariance = on_slot(x, P, SEAT, u, HALF)
    assert np.linalg.norm(on - truth) <= np.linalg.norm(x - truth) + 1e-12
    assert abs(float((on - SEAT) @ u)) <= HALF + 1e-12
    n = np.array([-u[1], u[0], 0.0])
    assert abs(float((on - SEAT) @ n)) < 1e-12 and abs(float(on[2] - SEAT[2])) < 1e-12
    assert float(n @ covariance @ n) <= SLOT_STD**2 * (1 + 1e-9)
    assert float(covariance[2, 2]) <= SLOT_STD**2 * (1 + 1e-9)
    # along the slot the lines alone say where: that variance stays
    assert math.isclose(float(u @ covariance @ u), float(u @ P @ u), rel_tol=1e-9)
    assert np.all(np.linalg.eigvalsh(0.5 * (covariance + covariance.T)) >= -1e-15)


def test_an_estimate_past_the_exit_comes_onto_it() -> None:
    # random board 1652323633's F2: 2.3 mm on past the slot's end, 1.9 mm across
    u = _slot(-0.928)
    n = np.array([-u[1], u[0], 0.0])
    exit_point = SEAT + HALF * u
    x = exit_point + 0.0023 * u + 0.0019 * n - np.array([0.0, 0.0, 0.0001])
    on, _ = on_slot(x, 1e-6 * np.eye(3), SEAT, u, HALF)
    assert np.allclose(on, exit_point, atol=1e-12)
