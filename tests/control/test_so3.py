import numpy as np

from tautwire.control.so3 import inverse_left_jacobian, left_jacobian, skew
from tautwire.model.quaternion import conjugate, multiply, quaternion_exp, quaternion_log


def test_skew_is_cross_product() -> None:
    rng = np.random.default_rng(0)
    a, b = rng.normal(size=3), rng.normal(size=3)
    np.testing.assert_allclose(skew(a) @ b, np.cross(a, b))


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
