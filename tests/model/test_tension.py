import math

import numpy as np
import pytest
from scipy.optimize import brentq

from tautwire.model.mass import point_masses
from tautwire.model.tension import GRAVITY, edge_tension, hanging_end_tension

G = 9.81


def test_straight_taut_cable_without_weight() -> None:
    f = np.array([3.0, -4.0, 0.0])
    result = edge_tension(f, 0.0)
    assert result.tension == pytest.approx(5.0)
    assert result.direction == pytest.approx([0.6, -0.8, 0.0])


def test_symmetric_catenary_gives_back_the_horizontal_tension() -> None:
    """A cable between gripper and anchor at the same height: exact catenary."""
    rho, a, d = 0.03, 0.4, 0.41
    c = brentq(lambda c: 2 * c * math.sinh(a / (2 * c)) - d, 1e-3, 1e3)
    H = rho * G * c  # horizontal tension
    V = rho * G * d / 2  # each end carries half the weight
    # the cable pulls the gripper (at x = 0) towards the anchor (+x) and down
    f_sens = np.array([H, 0.0, -V])
    m_gripper = point_masses([d], rho)[0]
    result = edge_tension(f_sens, m_gripper)
    assert result.tension == pytest.approx(H, rel=1e-12)
    assert result.direction == pytest.approx([1.0, 0.0, 0.0], abs=1e-12)


def test_gripper_with_a_hanging_end_below() -> None:
    """One sensor: the preceding edge is a freely hanging end (the paper's f_{i-1})."""
    rho, d_hang, d_span, T = 0.03, 0.2, 0.3, 2.5
    chord = np.array([0.6, 0.0, -0.8])  # from the gripper to the contact
    # the gripper carries the whole hanging end and half of the straight span
    f_sens = T * chord + (rho * d_hang + rho * d_span / 2) * GRAVITY
    m = point_masses([d_hang, d_span], rho)  # v_1 hanging end, v_2 gripper, v_3 contact
    result = edge_tension(
        f_sens,
        m[1],
        previous_direction=[0.0, 0.0, 1.0],  # from the hanging end up to the gripper
        previous_tension=hanging_end_tension(m[0]),
    )
    assert result.tension == pytest.approx(T, rel=1e-12)
    assert result.direction == pytest.approx(chord, abs=1e-12)


def test_two_sensors_both_neighbouring_tensions() -> None:
    """A gripper between two taut edges: the preceding tension is measured too."""
    T_prev, T = 1.5, 4.0
    p_hat_prev = np.array([1.0, 0.0, 0.0])  # from v_{i-1} towards the gripper
    p_hat = np.array([0.0, 1.0, 0.0])
    m = 0.004
    f_sens = T * p_hat - T_prev * p_hat_prev + m * GRAVITY
    result = edge_tension(f_sens, m, p_hat_prev, T_prev)
    assert result.tension == pytest.approx(T)
    assert result.direction == pytest.approx(p_hat)


def test_zero_force_gives_zero_tension_not_nan() -> None:
    result = edge_tension(np.zeros(3), 0.0)
    assert result.tension == 0.0
    assert np.all(np.isfinite(result.direction))
