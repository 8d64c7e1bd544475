"""One contact-point observation: the paper's equ:ls_observation_model.

A taut cable between the gripper at p_g and a contact at p_c lies along the
measured force, so p_c - p_g is parallel to f and

    G_j p_g_j = G_j p_c,     G_j = (f_j . f_j) I_3 - f_j f_j^T.     (equ:ls_observation_model)

G_j is the *unnormalised* projector onto the plane normal to f_j; it has rank
2 and scales with |f_j|^2. tautwire normalises the direction,
f_hat = f / |f|, so that G_j / |f_j|^2 = I - f_hat f_hat^T = H_j^T H_j, and
uses the two rows of H_j, an orthonormal basis of the plane normal to f_hat,
as a 2-D measurement:

    z_j = H_j p_g_j = H_j p_c + v_j,     v_j ~ N(0, R_j),
    R_j = r_j^2 I_2,    r_j^2 = (d_j sigma_f / |f_j|)^2 + sigma_p^2.

The noise is that of a line through the gripper whose direction is disturbed
by force noise: an isotropic force noise sigma_f [N] per axis turns the
direction by sigma_f / |f_j| [rad] per perpendicular axis, which moves the
line by d_j sigma_f / |f_j| [m] at the distance d_j of the contact;
sigma_p [m] is the gripper's position noise (the paper disregarded it). The
weight 1 / r_j^2 given to H_j^T H_j equals G_j / (d_j sigma_f)^2 when
sigma_p = 0: the same information as the unnormalised G_j with noise that
scales the same way. d_j is floored at ``min_distance`` so that a contact
estimate near the gripper does not claim an exact line.
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np
from numpy.typing import ArrayLike, NDArray

FloatArray = NDArray[np.float64]

#: Default floor [m] of the gripper-contact distance used in the noise r_j.
MIN_DISTANCE = 0.02


class ContactObservation(NamedTuple):
    """A contact-point measurement in filterpy's notation.

    Attributes:
        z: H p_gripper [m], the measured line's offset in the plane normal
            to the force.  # (2,)
        H: Orthonormal basis of the plane normal to the force (rows).  # (2, 3)
        R: Measurement noise covariance [m^2].  # (2, 2)
    """

    z: FloatArray
    H: FloatArray
    R: FloatArray


def normal_plane_basis(direction: ArrayLike) -> FloatArray:
    """Orthonormal basis of the plane normal to a direction.

    Branchless construction of Duff et al. (2017), continuous except at the
    direction (0, 0, -1) exactly, where it is still orthonormal.

    Args:
        direction: Any non-zero vector (need not be unit length).  # (3,)

    Returns:
        H, two orthonormal rows, both orthogonal to ``direction``.  # (2, 3)
    """
    fx, fy, fz = (float(c) for c in np.asarray(direction, dtype=float).reshape(3))
    n = math.sqrt(fx * fx + fy * fy + fz * fz)
    x, y, z = fx / n, fy / n, fz / n
    sign = math.copysign(1.0, z)
    a = -1.0 / (sign + z)
    b = x * y * a
    return np.array(
        [
            [1.0 + sign * x * x * a, sign * b, -sign * x],
            [b, sign + y * y * a, -y],
        ]
    )


def line_noise_variance(
    distance: float,
    force_norm: float,
    force_noise: float,
    position_noise: float = 0.0,
    min_distance: float = MIN_DISTANCE,
) -> float:
    """Variance r^2 [m^2] of a measured line's offset, per axis of the normal plane.

    Args:
        distance: d, distance [m] from the gripper to the contact (estimate
            or known edge length); floored at ``min_distance``.
        force_norm: |f| [N].
        force_noise: sigma_f, force noise [N], std per axis.
        position_noise: sigma_p, gripper position noise [m], std per axis.
        min_distance: Floor [m] of ``distance``.

    Returns:
        r^2 = (max(d, d_min) sigma_f / |f|)^2 + sigma_p^2 [m^2].
    """
    d = max(distance, min_distance)
    r = d * force_noise / force_norm
    return r * r + position_noise * position_noise


def contact_observation(
    p_gripper: ArrayLike,
    f_sens: ArrayLike,
    distance: float,
    force_noise: float,
    position_noise: float = 0.0,
    min_distance: float = MIN_DISTANCE,
) -> ContactObservation:
    """Build z, H and R of one sample (equ:ls_observation_model, normalised).

    This is what a textbook Kalman filter (e.g. filterpy's ``KalmanFilter``
    with ``dim_x=3, dim_z=2``, ``F = I``) needs to perform the same update
    as :class:`~tautwire.estimation.ContactPointFilter`.

    Args:
        p_gripper: Gripper position [m], world frame.  # (3,)
        f_sens: Force [N] the cable exerts on the gripper (weight
            compensated if wanted), world frame.  # (3,)
        distance: d [m] used for the noise (see :func:`line_noise_variance`).
        force_noise: sigma_f [N], std per axis.
        position_noise: sigma_p [m], std per axis.
        min_distance: Floor [m] of ``distance``.

    Returns:
        The measurement z, the observation matrix H and the noise R.
    """
    f = np.asarray(f_sens, dtype=float).reshape(3)
    H = normal_plane_basis(f)  # (2, 3)
    z = H @ np.asarray(p_gripper, dtype=float).reshape(3)  # (2,)
    r2 = line_noise_variance(
        distance, float(np.linalg.norm(f)), force_noise, position_noise, min_distance
    )
    return ContactObservation(z, H, r2 * np.eye(2))
