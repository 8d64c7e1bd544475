"""Individual and coordinated (absolute/relative) task space of the two arms.

The robot takes the **individual** 12-D task-space velocity
[v_left, w_left, v_right, w_right] [m/s, rad/s], world frame. Coordinated
primitives (A, B, C) control instead the **absolute** and **relative** pose
of the two grippers [Gabriel]. The frames are defined once, here:

Poses (``p`` position [m], ``Q`` unit quaternion [w, x, y, z]):

    p_abs = (p_left + p_right) / 2                  world frame
    Q_rel = Q_right^-1 Q_left                       left tool frame seen from
                                                    the right tool frame
    Q_abs = Q_right Q_rel^(1/2)                     Slerp midpoint of Q_right
          = Slerp(Q_right, Q_left, 1/2)             and Q_left (shortest arc)
    p_rel = p_left - p_right                        world frame

so that the inverse is

    p_left  = p_abs + p_rel / 2,    Q_left  = Q_abs Q_rel^(1/2)
    p_right = p_abs - p_rel / 2,    Q_right = Q_abs Q_rel^(-1/2).

Velocities (all world frame):

    v_abs = (v_left + v_right) / 2
    v_rel = v_left - v_right                        = d/dt p_rel
    w_rel = w_left - w_right                        (Q_rel evolves as
                                                    dQ_rel/dt = 1/2 (R_right^T w_rel) Q_rel)
    w_abs = w_right + M w_rel                       = angular velocity of Q_abs

with M = 1/2 J_l(phi/2) J_l(phi)^-1 and phi = R_right log(Q_rel) the relative
rotation vector in the world frame (J_l: left Jacobian of SO(3), see
:mod:`tautwire.control.so3`). M = I/2 at phi = 0, so for nearly parallel
grippers w_abs is the familiar mean (w_left + w_right) / 2; the exact M keeps
the absolute angular velocity equal to the rate of the Slerp midpoint for any
relative rotation below a half turn. The velocity maps are 12x12 matrices that
depend on the current pose only through M; each is the exact inverse of the
other, so individual -> coordinated -> individual is a round trip.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
from numpy.typing import ArrayLike, NDArray

from tautwire.control.so3 import (
    inverse_left_jacobian_coefficients,
    left_jacobian_coefficients,
    quaternion_log,
    quaternion_sqrt,
)
from tautwire.errors import InvalidArgumentError
from tautwire.model.quaternion import as_quaternion, conjugate, multiply, rotate

FloatArray = NDArray[np.float64]


class Pose(NamedTuple):
    """Pose of one frame.

    Attributes:
        position: Position [m].  # (3,)
        orientation: Unit quaternion [w, x, y, z].  # (4,)
    """

    position: FloatArray
    orientation: FloatArray


class DualPose(NamedTuple):
    """Individual task-space pose: both grippers in the world frame.

    Attributes:
        left: Pose of the left tool centre point.
        right: Pose of the right tool centre point.
    """

    left: Pose
    right: Pose


class CoordinatedPose(NamedTuple):
    """Coordinated task-space pose (see the module docstring for the frames).

    Attributes:
        absolute: p_abs (world) and Q_abs (Slerp midpoint, world).
        relative: p_rel = p_left - p_right (world) and
            Q_rel = Q_right^-1 Q_left (in the right tool frame).
    """

    absolute: Pose
    relative: Pose


def make_pose(position: ArrayLike, orientation: ArrayLike) -> Pose:
    """Validated :class:`Pose` from a position [m] and a quaternion [w, x, y, z].

    Raises:
        InvalidArgumentError: if the position is not 3 finite numbers or the
            quaternion is not 4 finite numbers with a non-zero norm.
    """
    p = np.asarray(position, dtype=float).reshape(-1)
    if p.shape != (3,) or not np.all(np.isfinite(p)):
        raise InvalidArgumentError(f"a position is 3 finite numbers [m], got {position!r}")
    return Pose(p, as_quaternion(orientation))


def coordinated_pose(pose: DualPose) -> CoordinatedPose:
    """Absolute and relative pose of the two grippers.

    Args:
        pose: Individual pose of both grippers.

    Returns:
        The coordinated pose (quaternions with w >= 0).
    """
    q_right = pose.right.orientation
    q_rel = as_quaternion(multiply(conjugate(q_right), pose.left.orientation))
    q_abs = as_quaternion(multiply(q_right, quaternion_sqrt(q_rel)))
    p_left = np.asarray(pose.left.position, dtype=float)
    p_right = np.asarray(pose.right.position, dtype=float)
    return CoordinatedPose(
        absolute=Pose(0.5 * (p_left + p_right), q_abs),
        relative=Pose(p_left - p_right, q_rel),
    )


def individual_pose(pose: CoordinatedPose) -> DualPose:
    """Poses of both grippers from the absolute and relative pose.

    Args:
        pose: Coordinated pose.

    Returns:
        The individual pose (quaternions with w >= 0).
    """
    half = quaternion_sqrt(pose.relative.orientation)
    q_abs = pose.absolute.orientation
    p_abs = np.asarray(pose.absolute.position, dtype=float)
    p_rel = np.asarray(pose.relative.position, dtype=float)
    return DualPose(
        left=Pose(p_abs + 0.5 * p_rel, as_quaternion(multiply(q_abs, half))),
        right=Pose(p_abs - 0.5 * p_rel, as_quaternion(multiply(q_abs, conjugate(half)))),
    )


def relative_rotation_vector(pose: DualPose) -> FloatArray:
    """Relative rotation vector phi = R_right log(Q_right^-1 Q_left), world frame [rad].

    Args:
        pose: Individual pose of both grippers.

    Returns:
        Rotation vector taking the right tool frame onto the left one,
        expressed in the world frame, |phi| <= pi.  # (3,)
    """
    q_right = pose.right.orientation
    q_rel = multiply(conjugate(q_right), pose.left.orientation)
    return rotate(q_right, quaternion_log(q_rel))


def absolute_rate_matrix(pose: DualPose) -> FloatArray:
    """The matrix M with w_abs = w_right + M w_rel, M = 1/2 J_l(phi/2) J_l(phi)^-1.

    Args:
        pose: Individual pose of both grippers.

    Returns:
        M, equal to I/2 when the grippers are parallel.  # (3, 3)
    """
    phi = relative_rotation_vector(pose)  # (3,)
    theta = float(np.linalg.norm(phi))
    if theta == 0.0:
        return 0.5 * np.eye(3)
    a1, b1 = left_jacobian_coefficients(0.5 * theta)
    a2, b2 = inverse_left_jacobian_coefficients(theta)
    # (I + a1 K + b1 K^2)(I + a2 K + b2 K^2) with K^3 = -K, K^4 = -K^2
    a = a1 + a2 - a1 * b2 - b1 * a2
    b = b1 + b2 + a1 * a2 - b1 * b2
    x, y, z = phi / theta
    K = np.array([[0.0, -z, y], [z, 0.0, -x], [-y, x, 0.0]])  # (3, 3)
    M: FloatArray = 0.5 * (np.eye(3) + a * K + b * (K @ K))
    return M


def coordinated_velocity_matrix(pose: DualPose) -> FloatArray:
    """Matrix that maps the individual twist onto the coordinated twist.

    [v_abs, w_abs, v_rel, w_rel] = C [v_left, w_left, v_right, w_right].

    Args:
        pose: Current individual pose of both grippers (C depends on the
            relative orientation only).

    Returns:
        C.  # (12, 12)
    """
    M = absolute_rate_matrix(pose)  # (3, 3)
    eye = np.eye(3)
    C = np.zeros((12, 12))
    C[0:3, 0:3] = 0.5 * eye  # v_abs
    C[0:3, 6:9] = 0.5 * eye
    C[3:6, 3:6] = M  # w_abs = (I - M) w_right + M w_left
    C[3:6, 9:12] = eye - M
    C[6:9, 0:3] = eye  # v_rel
    C[6:9, 6:9] = -eye
    C[9:12, 3:6] = eye  # w_rel
    C[9:12, 9:12] = -eye
    return C


def individual_velocity_matrix(pose: DualPose) -> FloatArray:
    """Matrix that maps the coordinated twist onto the individual twist.

    [v_left, w_left, v_right, w_right] = C^-1 [v_abs, w_abs, v_rel, w_rel],
    the exact inverse of :func:`coordinated_velocity_matrix`.

    Args:
        pose: Current individual pose of both grippers.

    Returns:
        C^-1.  # (12, 12)
    """
    M = absolute_rate_matrix(pose)  # (3, 3)
    eye = np.eye(3)
    C_inv = np.zeros((12, 12))
    C_inv[0:3, 0:3] = eye  # v_left = v_abs + v_rel / 2
    C_inv[0:3, 6:9] = 0.5 * eye
    C_inv[3:6, 3:6] = eye  # w_left = w_abs + (I - M) w_rel
    C_inv[3:6, 9:12] = eye - M
    C_inv[6:9, 0:3] = eye  # v_right = v_abs - v_rel / 2
    C_inv[6:9, 6:9] = -0.5 * eye
    C_inv[9:12, 3:6] = eye  # w_right = w_abs - M w_rel
    C_inv[9:12, 9:12] = -M
    return C_inv


def coordinated_twist(twist: ArrayLike, pose: DualPose) -> FloatArray:
    """Coordinated twist [v_abs, w_abs, v_rel, w_rel] of an individual twist.

    Args:
        twist: [v_left, w_left, v_right, w_right] [m/s, rad/s].  # (12,)
        pose: Current individual pose of both grippers.

    Returns:
        [v_abs, w_abs, v_rel, w_rel] [m/s, rad/s], world frame.  # (12,)
    """
    return _apply(twist, pose, coordinated=True)


def individual_twist(twist: ArrayLike, pose: DualPose) -> FloatArray:
    """Individual twist [v_left, w_left, v_right, w_right] of a coordinated twist.

    Args:
        twist: [v_abs, w_abs, v_rel, w_rel] [m/s, rad/s], world frame.  # (12,)
        pose: Current individual pose of both grippers.

    Returns:
        [v_left, w_left, v_right, w_right] [m/s, rad/s], world frame.  # (12,)
    """
    return _apply(twist, pose, coordinated=False)


def _apply(twist: ArrayLike, pose: DualPose, *, coordinated: bool) -> FloatArray:
    t = np.asarray(twist, dtype=float)
    if t.shape != (12,):
        raise InvalidArgumentError(f"a task-space twist has shape (12,), got {t.shape}")
    M = absolute_rate_matrix(pose)  # (3, 3)
    a, b, c, d = t[0:3], t[3:6], t[6:9], t[9:12]
    if coordinated:  # a, b, c, d = v_left, w_left, v_right, w_right
        return np.concatenate((0.5 * (a + c), d + M @ (b - d), a - c, b - d))
    # a, b, c, d = v_abs, w_abs, v_rel, w_rel
    w_right = b - M @ d
    return np.concatenate((a + 0.5 * c, w_right + d, a - 0.5 * c, w_right))
