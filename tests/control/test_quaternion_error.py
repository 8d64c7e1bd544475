import numpy as np
from hypothesis import assume, given, settings

from tautwire.control.quaternion_error import quaternion_error
from tautwire.model.quaternion import conjugate, multiply, quaternion_exp, quaternion_log

from .conftest import integrate_orientation, quaternions, random_quaternion, same_rotation, vectors


@settings(max_examples=200, deadline=None)
@given(quaternions, quaternions)
def test_is_the_vector_part_of_the_error_quaternion(q_d: np.ndarray, q_c: np.ndarray) -> None:
    q_e = multiply(q_d, conjugate(q_c))
    expected = q_e[1:] if q_e[0] >= 0.0 else -q_e[1:]
    np.testing.assert_allclose(quaternion_error(q_d, q_c), expected, atol=1e-12)


@settings(max_examples=200, deadline=None)
@given(quaternions, quaternions)
def test_does_not_depend_on_the_signs(q_d: np.ndarray, q_c: np.ndarray) -> None:
    # at exactly a half turn both ways are equally short: no sign to keep
    assume(abs(float(q_d @ q_c)) > 1e-9)
    e = quaternion_error(q_d, q_c)
    np.testing.assert_allclose(quaternion_error(-q_d, q_c), e, atol=1e-12)
    np.testing.assert_allclose(quaternion_error(q_d, -q_c), e, atol=1e-12)
    np.testing.assert_allclose(quaternion_error(-q_d, -q_c), e, atol=1e-12)


@settings(max_examples=200, deadline=None)
@given(quaternions, quaternions)
def test_zero_iff_equal_up_to_sign(q_d: np.ndarray, q_c: np.ndarray) -> None:
    np.testing.assert_allclose(quaternion_error(q_d, q_d), 0.0, atol=1e-12)
    np.testing.assert_allclose(quaternion_error(q_d, -q_d), 0.0, atol=1e-12)
    angle = np.linalg.norm(quaternion_log(multiply(q_d, conjugate(q_c))))
    # |e| = sin(theta / 2): zero exactly when the rotations agree
    np.testing.assert_allclose(
        np.linalg.norm(quaternion_error(q_d, q_c)), np.sin(angle / 2), atol=1e-9
    )
    if angle > 1e-6:
        assert np.linalg.norm(quaternion_error(q_d, q_c)) > 0.0


@settings(max_examples=200, deadline=None)
@given(quaternions, vectors)
def test_small_angle_is_half_the_rotation_vector(q_c: np.ndarray, axis: np.ndarray) -> None:
    if np.linalg.norm(axis) < 1e-6:
        return
    phi = 1e-4 * axis / np.linalg.norm(axis)  # world-frame rotation vector
    q_d = multiply(quaternion_exp(phi), q_c)
    np.testing.assert_allclose(quaternion_error(q_d, q_c), phi / 2, atol=1e-12)


def test_quarter_turn() -> None:
    q_d = quaternion_exp([0.0, 0.0, np.pi / 2])
    e = quaternion_error(q_d, [1.0, 0.0, 0.0, 0.0])
    np.testing.assert_allclose(e, [0.0, 0.0, np.sin(np.pi / 4)])


def test_shortest_path_near_a_half_turn() -> None:
    # 200 degrees about z one way is 160 degrees the other way: turn through -z
    q_d = quaternion_exp([0.0, 0.0, np.deg2rad(200.0)])
    e = quaternion_error(q_d, [1.0, 0.0, 0.0, 0.0])
    assert e[2] < 0.0
    np.testing.assert_allclose(np.linalg.norm(e), np.sin(np.deg2rad(80.0)))


def test_p_control_converges_along_the_closed_form() -> None:
    # omega = k_o e turns about a fixed axis with theta_dot = -k_o sin(theta / 2),
    # so tan(theta / 4) = tan(theta_0 / 4) exp(-k_o t / 2).
    rng = np.random.default_rng(7)
    k_o, dt, steps = 4.0, 2e-3, 3000
    for _ in range(5):
        q_d = random_quaternion(rng)
        q_c = random_quaternion(rng)
        theta_0 = np.linalg.norm(quaternion_log(multiply(q_d, conjugate(q_c))))
        for n in range(1, steps + 1):
            # midpoint rule: the axis is fixed, so the error rate is what matters
            w = k_o * quaternion_error(q_d, q_c)
            q_half = integrate_orientation(q_c, w, dt / 2)
            q_c = integrate_orientation(q_c, k_o * quaternion_error(q_d, q_half), dt)
            if n % 600 == 0:
                theta = np.linalg.norm(quaternion_log(multiply(q_d, conjugate(q_c))))
                expected = 4 * np.arctan(np.tan(theta_0 / 4) * np.exp(-k_o * n * dt / 2))
                np.testing.assert_allclose(theta, expected, atol=1e-6)
        assert same_rotation(q_c, q_d, atol=1e-4)  # theta < 4 exp(-12)
