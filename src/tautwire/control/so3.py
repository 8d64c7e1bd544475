"""Rotation-vector algebra on SO(3) for the coordinated task space.

Small, allocation-light helpers in the project's [w, x, y, z] quaternion
convention: the exponential and logarithm between unit quaternions and
rotation vectors, the quaternion power used by the Slerp midpoint, and the
left Jacobian J_l of SO(3) with its inverse.

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


def quaternion_log(q: ArrayLike) -> FloatArray:
    """Rotation vector phi [rad] of the unit quaternion ``q`` = [w, x, y, z].

    The sign of ``q`` is chosen so that w >= 0: the result is the shortest
    rotation, |phi| <= pi.

    Args:
        q: Unit quaternion [w, x, y, z].  # (4,)

    Returns:
        Rotation vector (axis times angle) [rad].  # (3,)
    """
    w, x, y, z = (float(c) for c in np.asarray(q, dtype=float))
    if w < 0.0:
        w, x, y, z = -w, -x, -y, -z
    s = math.sqrt(x * x + y * y + z * z)
    if s < _SMALL_ANGLE:
        scale = 2.0 / w if w > 0.0 else 0.0  # theta = 2 asin(s) ~ 2 s / w
        return np.array([scale * x, scale * y, scale * z])
    theta = 2.0 * math.atan2(s, w)
    scale = theta / s
    return np.array([scale * x, scale * y, scale * z])


def quaternion_exp(phi: ArrayLike) -> FloatArray:
    """Unit quaternion [w, x, y, z] of the rotation vector ``phi`` [rad].

    Args:
        phi: Rotation vector (axis times angle) [rad].  # (3,)

    Returns:
        Unit quaternion [w, x, y, z].  # (4,)
    """
    px, py, pz = (float(c) for c in np.asarray(phi, dtype=float))
    theta = math.sqrt(px * px + py * py + pz * pz)
    if theta < _SMALL_ANGLE:
        half = 0.5 - theta * theta / 48.0  # sin(theta/2)/theta
        return np.array([math.cos(0.5 * theta), half * px, half * py, half * pz])
    half = math.sin(0.5 * theta) / theta
    return np.array([math.cos(0.5 * theta), half * px, half * py, half * pz])


def quaternion_sqrt(q: ArrayLike) -> FloatArray:
    """Square root ``q^(1/2)`` along the shortest arc (half the rotation).

    Args:
        q: Unit quaternion [w, x, y, z].  # (4,)

    Returns:
        Unit quaternion [w, x, y, z] with w > 0 whose square is +-q.  # (4,)
    """
    w, x, y, z = (float(c) for c in np.asarray(q, dtype=float))
    if w < 0.0:
        w, x, y, z = -w, -x, -y, -z
    # half-angle formula: cos(theta/4) = sqrt((1 + cos(theta/2)) / 2)
    c = math.sqrt(max(0.5 * (1.0 + w), 0.0))
    scale = 0.5 / c  # sin(theta/2) / sin(theta/4) = 2 cos(theta/4)
    return np.array([c, scale * x, scale * y, scale * z])


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
