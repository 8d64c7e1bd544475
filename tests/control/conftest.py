"""Shared strategies and helpers for the control tests."""

from __future__ import annotations

import numpy as np
from hypothesis import strategies as st
from numpy.typing import NDArray

from tautwire.model.quaternion import multiply, quaternion_exp

FloatArray = NDArray[np.float64]


def random_quaternion(rng: np.random.Generator) -> FloatArray:
    """Uniform random unit quaternion [w, x, y, z] with w >= 0."""
    q = rng.normal(size=4)
    q /= np.linalg.norm(q)
    return q if q[0] >= 0.0 else -q


def same_rotation(q1: FloatArray, q2: FloatArray, atol: float = 1e-9) -> bool:
    """Whether two unit quaternions are the same rotation (q or -q)."""
    return bool(np.allclose(q1, q2, atol=atol) or np.allclose(q1, -q2, atol=atol))


def integrate_orientation(q: FloatArray, omega: FloatArray, dt: float) -> FloatArray:
    """Exact step of dQ/dt = 1/2 [0, omega] Q for a constant world angular velocity."""
    return multiply(quaternion_exp(omega * dt), q)


finite = st.floats(-10.0, 10.0, allow_nan=False, allow_infinity=False)
vectors = st.tuples(finite, finite, finite).map(np.array)
quaternions = (
    st.tuples(finite, finite, finite, finite)
    .filter(lambda t: float(np.linalg.norm(t)) > 1e-3)
    .map(lambda t: np.array(t) / np.linalg.norm(t))
)
