"""Individual and coordinated (absolute/relative) task space of the two arms.

The robot takes the **individual** 12-D task-space velocity
[v_left, w_left, v_right, w_right] in [m/s, rad/s], world frame. Coordinated
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

import math
from typing import NamedTuple

import numpy as np
from numpy.typing import ArrayLike, NDArray

from tautwire.control.so3 import (
    inverse_left_jacobian_coefficients,
    left_jacobian_coefficients,
)
from tautwire.errors import InvalidArgumentError
from tautwire.model import quaternion as qf
from tautwire.model.quaternion import as_quaternion

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
    q_right, q_rel = _right_and_relative(pose)
    q_abs = qf.positive_floats(qf.multiply_floats(q_right, qf.sqrt_floats(q_rel)))
    p_left = np.asarray(pose.left.position, dtype=float)
    p_right = np.asarray(pose.right.position, dtype=float)
    return CoordinatedPose(
        absolute=Pose(0.5 * (p_left + p_right), np.array(q_abs)),
        relative=Pose(p_left - p_right, np.array(q_rel)),
    )


def individual_pose(pose: CoordinatedPose) -> DualPose:
    """Poses of both grippers from the absolute and relative pose.

    Args:
        pose: Coordinated pose.

    Returns:
        The individual pose (quaternions with w >= 0).
    """
    half = qf.sqrt_floats(qf.quat_floats(pose.relative.orientation))
    q_abs = qf.quat_floats(pose.absolute.orientation)
    p_abs = np.asarray(pose.absolute.position, dtype=float)
    p_rel = np.asarray(pose.relative.position, dtype=float)
    return DualPose(
        left=Pose(
            p_abs + 0.5 * p_rel, np.array(qf.positive_floats(qf.multiply_floats(q_abs, half)))
        ),
        right=Pose(
            p_abs - 0.5 * p_rel,
            np.array(qf.positive_floats(qf.multiply_floats(q_abs, qf.conjugate_floats(half)))),
        ),
    )


def relative_rotation_vector(pose: DualPose) -> FloatArray:
    """Relative rotation vector phi = R_right log(Q_right^-1 Q_left), world frame [rad].

    Args:
        pose: Individual pose of both grippers.

    Returns:
        Rotation vector taking the right tool frame onto the left one,
        expressed in the world frame, |phi| <= pi.  # (3,)
    """
    q_right, q_rel = _right_and_relative(pose)
    return np.array(qf.rotate_floats(q_right, qf.log_floats(q_rel)))


def absolute_rate_matrix(pose: DualPose) -> FloatArray:
    """The matrix M with w_abs = w_right + M w_rel, M = 1/2 J_l(phi/2) J_l(phi)^-1.

    Args:
        pose: Individual pose of both grippers.

    Returns:
        M, equal to I/2 when the grippers are parallel.  # (3, 3)
    """
    (x, y, z), a, b = _rate_coefficients(pose)
    K = np.array([[0.0, -z, y], [z, 0.0, -x], [-y, x, 0.0]])  # (3, 3)
    M: FloatArray = 0.5 * (np.eye(3) + a * K + b * (K @ K))
    return M


def _right_and_relative(pose: DualPose) -> tuple[qf.Quat, qf.Quat]:
    """Q_right and Q_rel = Q_right^-1 Q_left (w >= 0) as float tuples."""
    q_right = qf.quat_floats(pose.right.orientation)
    q_rel = qf.positive_floats(
        qf.multiply_floats(qf.conjugate_floats(q_right), qf.quat_floats(pose.left.orientation))
    )
    return q_right, q_rel


def _rate_coefficients(pose: DualPose) -> tuple[qf.Vec, float, float]:
    """Unit axis n of phi (world frame) and (a, b) with M = 1/2 (I + a K + b K^2), K = [n]x."""
    q_right, q_rel = _right_and_relative(pose)
    px, py, pz = qf.rotate_floats(q_right, qf.log_floats(q_rel))
    theta = math.sqrt(px * px + py * py + pz * pz)
    if theta == 0.0:
        return (1.0, 0.0, 0.0), 0.0, 0.0
    a1, b1 = left_jacobian_coefficients(0.5 * theta)
    a2, b2 = inverse_left_jacobian_coefficients(theta)
    # (I + a1 K + b1 K^2)(I + a2 K + b2 K^2) with K^3 = -K, K^4 = -K^2
    a = a1 + a2 - a1 * b2 - b1 * a2
    b = b1 + b2 + a1 * a2 - b1 * b2
    return (px / theta, py / theta, pz / theta), a, b


def _apply_rate(coefficients: tuple[qf.Vec, float, float], d: qf.Vec) -> qf.Vec:
    """M d = 1/2 (d + a n x d + b n x (n x d))."""
    (nx, ny, nz), a, b = coefficients
    dx, dy, dz = d
    cx, cy, cz = ny * dz - nz * dy, nz * dx - nx * dz, nx * dy - ny * dx  # n x d
    ccx, ccy, ccz = ny * cz - nz * cy, nz * cx - nx * cz, nx * cy - ny * cx  # n x (n x d)
    return (
        0.5 * (dx + a * cx + b * ccx),
        0.5 * (dy + a * cy + b * ccy),
        0.5 * (dz + a * cz + b * ccz),
    )


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
        twist: [v_left, w_left, v_right, w_right] in [m/s, rad/s].  # (12,)
        pose: Current individual pose of both grippers.

    Returns:
        [v_abs, w_abs, v_rel, w_rel] in [m/s, rad/s], world frame.  # (12,)
    """
    return _apply(twist, pose, coordinated=True)


def individual_twist(twist: ArrayLike, pose: DualPose) -> FloatArray:
    """Individual twist [v_left, w_left, v_right, w_right] of a coordinated twist.

    Args:
        twist: [v_abs, w_abs, v_rel, w_rel] in [m/s, rad/s], world frame.  # (12,)
        pose: Current individual pose of both grippers.

    Returns:
        [v_left, w_left, v_right, w_right] in [m/s, rad/s], world frame.  # (12,)
    """
    return _apply(twist, pose, coordinated=False)


def _apply(twist: ArrayLike, pose: DualPose, *, coordinated: bool) -> FloatArray:
    t = np.asarray(twist, dtype=float)
    if t.shape != (12,):
        raise InvalidArgumentError(f"a task-space twist has shape (12,), got {t.shape}")
    coefficients = _rate_coefficients(pose)
    a0, a1, a2, b0, b1, b2, c0, c1, c2, d0, d1, d2 = t.tolist()
    if coordinated:  # a, b, c, d = v_left, w_left, v_right, w_right
        m0, m1, m2 = _apply_rate(coefficients, (b0 - d0, b1 - d1, b2 - d2))
        return np.array(
            [
                *(0.5 * (a0 + c0), 0.5 * (a1 + c1), 0.5 * (a2 + c2)),
                *(d0 + m0, d1 + m1, d2 + m2),
                *(a0 - c0, a1 - c1, a2 - c2),
                *(b0 - d0, b1 - d1, b2 - d2),
            ]
        )
    # a, b, c, d = v_abs, w_abs, v_rel, w_rel; w_right = w_abs - M w_rel
    m0, m1, m2 = _apply_rate(coefficients, (d0, d1, d2))
    r0, r1, r2 = b0 - m0, b1 - m1, b2 - m2
    return np.array(
        [
            *(a0 + 0.5 * c0, a1 + 0.5 * c1, a2 + 0.5 * c2),
            *(r0 + d0, r1 + d1, r2 + d2),
            *(a0 - 0.5 * c0, a1 - 0.5 * c1, a2 - 0.5 * c2),
            *(r0, r1, r2),
        ]
    )
