import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from tautwire.estimation import contact_observation, line_noise_variance, normal_plane_basis

comp = st.floats(-10.0, 10.0)


@settings(max_examples=60, deadline=None)
@given(st.tuples(comp, comp, comp).filter(lambda v: np.linalg.norm(v) > 1e-3))
def test_basis_is_orthonormal_and_normal_to_the_force(f):
    H = normal_plane_basis(f)
    np.testing.assert_allclose(H @ H.T, np.eye(2), atol=1e-12)
    np.testing.assert_allclose(H @ np.asarray(f) / np.linalg.norm(f), 0.0, atol=1e-12)
    # H'H is the normalised G of equ:ls_observation_model
    u = np.asarray(f) / np.linalg.norm(f)
    np.testing.assert_allclose(H.T @ H, np.eye(3) - np.outer(u, u), atol=1e-12)


def test_basis_at_straight_down():
    H = normal_plane_basis([0.0, 0.0, -2.0])
    np.testing.assert_allclose(H @ H.T, np.eye(2), atol=1e-15)
    np.testing.assert_allclose(H[:, 2], 0.0, atol=1e-15)


def test_line_noise_variance_closed_form():
    assert line_noise_variance(0.2, 4.0, 0.05) == pytest.approx((0.2 * 0.05 / 4.0) ** 2)
    assert line_noise_variance(0.0, 4.0, 0.05, min_distance=0.02) == pytest.approx(
        (0.02 * 0.05 / 4.0) ** 2
    )
    assert line_noise_variance(0.2, 4.0, 0.05, 1e-3) == pytest.approx(
        (0.2 * 0.05 / 4.0) ** 2 + 1e-6
    )


def test_observation_of_a_line_through_the_contact_has_zero_innovation():
    contact = np.array([0.3, -0.1, 0.5])
    p = np.array([0.1, 0.2, 0.4])
    z, H, R = contact_observation(p, 3.0 * (contact - p), 0.3, 0.05)
    np.testing.assert_allclose(z - H @ contact, 0.0, atol=1e-15)
    assert R.shape == (2, 2) and R[0, 1] == 0.0 and R[0, 0] > 0.0


def test_perpendicular_line_noise_matches_monte_carlo():
    # the offset of a noisy line at the contact has std d sigma / |f| per axis
    rng = np.random.default_rng(7)
    contact = np.zeros(3)
    p = np.array([0.25, 0.0, 0.0])
    f_true = 4.0 * (contact - p) / 0.25
    offsets = []
    for _ in range(4000):
        z, H, _ = contact_observation(p, f_true + rng.normal(0, 0.05, 3), 0.25, 0.05)
        offsets.append(z - H @ contact)
    # H turns with the noisy force, so compare the 2-D offset's mean square: 2 r^2
    mean_sq = np.mean(np.sum(np.array(offsets) ** 2, axis=1))
    assert mean_sq == pytest.approx(2.0 * (0.25 * 0.05 / 4.0) ** 2, rel=0.06)
