import numpy as np

from tautwire.control import _quaternion_floats as qf
from tautwire.control.so3 import quaternion_log, quaternion_sqrt
from tautwire.model.quaternion import as_quaternion, conjugate, multiply, rotate

from .conftest import random_quaternion


def test_float_helpers_match_the_model_helpers() -> None:
    rng = np.random.default_rng(41)
    for _ in range(50):
        a = rng.normal(size=4)  # not normalised: positive() must normalise
        q1, q2 = random_quaternion(rng), random_quaternion(rng)
        v = rng.normal(size=3)
        np.testing.assert_allclose(qf.mul(qf.quat(q1), qf.quat(q2)), multiply(q1, q2), atol=1e-14)
        np.testing.assert_allclose(qf.conj(qf.quat(q1)), conjugate(q1))
        np.testing.assert_allclose(qf.positive(qf.quat(a)), as_quaternion(a), atol=1e-14)
        np.testing.assert_allclose(qf.rotate_v(qf.quat(q1), qf.vec(v)), rotate(q1, v), atol=1e-12)
        np.testing.assert_allclose(qf.log_q(qf.quat(-q1)), quaternion_log(q1), atol=1e-12)
        np.testing.assert_allclose(qf.sqrt_q(qf.quat(-q1)), quaternion_sqrt(q1), atol=1e-14)


def test_log_of_a_tiny_rotation() -> None:
    q = (np.cos(1e-8), np.sin(1e-8), 0.0, 0.0)
    np.testing.assert_allclose(qf.log_q(q), [2e-8, 0.0, 0.0], rtol=1e-9)
