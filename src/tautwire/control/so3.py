"""The left Jacobian of SO(3) for the coordinated task space.

The skew matrix and the left Jacobian J_l of SO(3) with its inverse. The
quaternion exponential, logarithm and square root (the Slerp midpoint) are
in :mod:`tautwire.model.quaternion`, the one quaternion module.

The left Jacobian relates the rate of a rotation vector phi to the spatial
(left) angular velocity Omega of R = Exp(phi):

    d/dt Exp(phi) = [Omega]x Exp(phi),   Omega = J_l(phi) phi_dot.

With theta = |phi| and K = [phi / theta]x (so K^3 = -K),

    J_l(phi)    = I + (1 - cos theta) / theta K + (theta - sin theta) / theta K^2
    J_l(phi)^-1 = I - theta / 2 K + (1 - theta / 2 cot(theta / 2)) K^2,

the inverse existing for theta < 2 pi.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np
from numpy.typing import ArrayLike, NDArray

FloatArray = NDArray[np.float64]

#: Below this angle [rad] the series expansions are used.
_SMALL_ANGLE = 1e-6


def skew(v: ArrayLike) -> FloatArray:
    """Cross-product matrix [v]x, so that ``skew(v) @ u == cross(v, u)``.

    Args:
        v: Vector.  # (3,)

    Returns:
        Skew-symmetric matrix.  # (3, 3)
    """
    x, y, z = np.asarray(v, dtype=float)
    return np.array([[0.0, -z, y], [z, 0.0, -x], [-y, x, 0.0]])


def left_jacobian_coefficients(theta: float) -> tuple[float, float]:
    """Coefficients (a, b) with J_l = I + a K + b K^2 for the unit axis K.

    Args:
        theta: Rotation angle [rad], >= 0.

    Returns:
        a = (1 - cos theta) / theta and b = (theta - sin theta) / theta.
    """
    if theta < _SMALL_ANGLE:
        return 0.5 * theta, theta * theta / 6.0
    return (1.0 - math.cos(theta)) / theta, (theta - math.sin(theta)) / theta


def inverse_left_jacobian_coefficients(theta: float) -> tuple[float, float]:
    """Coefficients (a, b) with J_l^-1 = I + a K + b K^2 for the unit axis K.

    Args:
        theta: Rotation angle [rad], 0 <= theta < 2 pi.

    Returns:
        a = -theta / 2 and b = 1 - theta / 2 cot(theta / 2).
    """
    if theta < _SMALL_ANGLE:
        return -0.5 * theta, theta * theta / 12.0
    half = 0.5 * theta
    return -half, 1.0 - half * math.cos(half) / math.sin(half)


def left_jacobian(phi: ArrayLike) -> FloatArray:
    """Left Jacobian J_l(phi) of SO(3).

    Args:
        phi: Rotation vector [rad].  # (3,)

    Returns:
        J_l with Omega = J_l(phi) phi_dot.  # (3, 3)
    """
    return _axis_polynomial(phi, left_jacobian_coefficients)


def inverse_left_jacobian(phi: ArrayLike) -> FloatArray:
    """Inverse J_l(phi)^-1 of the left Jacobian of SO(3) (|phi| < 2 pi).

    Args:
        phi: Rotation vector [rad].  # (3,)

    Returns:
        J_l^-1 with phi_dot = J_l(phi)^-1 Omega.  # (3, 3)
    """
    return _axis_polynomial(phi, inverse_left_jacobian_coefficients)


def _axis_polynomial(
    phi: ArrayLike, coefficients: Callable[[float], tuple[float, float]]
) -> FloatArray:
    vec = np.asarray(phi, dtype=float)
    theta = float(np.linalg.norm(vec))
    if theta == 0.0:
        return np.eye(3)
    a, b = coefficients(theta)
    K = skew(vec / theta)  # (3, 3)
    return np.eye(3) + a * K + b * (K @ K)
