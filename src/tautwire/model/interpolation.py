"""Interpolated goal points: linear position and Slerp orientation.

The paper adds a feature point v_k between its neighbours v_{k-1} and v_{k+1}
with one fraction delta in [0, 1]:

    p_k = p_{k-1} + delta (p_{k+1} - p_{k-1})
    Q_k = Q_{k-1} (Q_{k-1}^-1 Q_{k+1})^delta          (Slerp)
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy.spatial.transform import Rotation, Slerp

from tautwire.errors import InvalidArgumentError
from tautwire.model.quaternion import from_rotation, to_rotation

FloatArray = NDArray[np.float64]


def _check_delta(delta: float) -> float:
    if not np.isfinite(delta) or not 0.0 <= delta <= 1.0:
        raise InvalidArgumentError(f"delta must be in [0, 1], got {delta}")
    return float(delta)


def lerp(p_a: ArrayLike, p_b: ArrayLike, delta: float) -> FloatArray:
    """Linear interpolation ``p_a + delta (p_b - p_a)`` of two positions [m]."""
    delta = _check_delta(delta)
    a = np.asarray(p_a, dtype=float)
    b = np.asarray(p_b, dtype=float)
    out: FloatArray = a + delta * (b - a)
    return out


def slerp(q_a: ArrayLike, q_b: ArrayLike, delta: float) -> FloatArray:
    """Spherical linear interpolation of two [w, x, y, z] orientations.

    Returns ``Q_a (Q_a^-1 Q_b)^delta`` along the shorter arc, as [w, x, y, z].
    """
    delta = _check_delta(delta)
    rotations = Rotation.concatenate([to_rotation(q_a), to_rotation(q_b)])
    return from_rotation(Slerp([0.0, 1.0], rotations)([delta])[0])
