import numpy as np
import pytest

from tautwire.control.so3 import (
    inverse_left_jacobian,
    left_jacobian,
    quaternion_exp,
    quaternion_log,
    quaternion_sqrt,
    skew,
)
from tautwire.model.quaternion import conjugate, multiply

from .conftest import random_quaternion, same_rotation


def test_skew_is_cross_product() -> None:
    rng = np.random.default_rng(0)
    a, b = rng.normal(size=3), rng.normal(size=3)
    np.testing.assert_allclose(skew(a) @ b, np.cross(a, b))


def test_exp_of_quarter_turn_about_z() -> None:
    q = quaternion_exp([0.0, 0.0, np.pi / 2])
    np.testing.assert_allclose(q, [np.cos(np.pi / 4), 0.0, 0.0, np.sin(np.pi / 4)])


@pytest.mark.parametrize("scale", [0.0, 1e-9, 1e-3, 1.0, 3.0])
def test_log_inverts_exp(scale: float) -> None:
    rng = np.random.default_rng(1)
    for _ in range(20):
        axis = rng.normal(size=3)
        phi = scale * axis / np.linalg.norm(axis)
        np.testing.assert_allclose(quaternion_log(quaternion_exp(phi)), phi, atol=1e-12)


def test_log_takes_the_shorter_way() -> None:
    rng = np.random.default_rng(2)
    for _ in range(20):
        q = random_quaternion(rng)
        np.testing.assert_allclose(quaternion_log(-q), quaternion_log(q), atol=1e-12)
        assert np.linalg.norm(quaternion_log(q)) <= np.pi + 1e-12


def test_sqrt_squares_back() -> None:
    rng = np.random.default_rng(3)
    for _ in range(50):
        q = random_quaternion(rng)
        h = quaternion_sqrt(q)
        assert same_rotation(multiply(h, h), q, atol=1e-12)
        assert abs(np.linalg.norm(h) - 1.0) < 1e-12


def test_left_jacobian_against_finite_differences() -> None:
    # d/dt Exp(phi) = [J_l phi_dot]x Exp(phi): compare the left increment
    rng = np.random.default_rng(4)
    h = 1e-6
    for _ in range(20):
        phi = rng.normal(size=3)
        phi *= rng.uniform(0.0, 3.0) / np.linalg.norm(phi)
        phi_dot = rng.normal(size=3)
        q0 = quaternion_exp(phi)
        q1 = quaternion_exp(phi + h * phi_dot)
        omega = quaternion_log(multiply(q1, conjugate(q0))) / h
        np.testing.assert_allclose(omega, left_jacobian(phi) @ phi_dot, atol=1e-5)


def test_inverse_left_jacobian_is_the_inverse() -> None:
    rng = np.random.default_rng(5)
    for theta in (0.0, 1e-8, 0.5, 2.0, 3.1, 4.0):
        axis = rng.normal(size=3)
        phi = theta * axis / np.linalg.norm(axis)
        np.testing.assert_allclose(
            inverse_left_jacobian(phi) @ left_jacobian(phi), np.eye(3), atol=1e-12
        )
