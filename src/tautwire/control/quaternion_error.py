"""Orientation error of the motion controller (the paper's equ:quaternion_error).

With Q_d = [q_d0, q_d] the desired and Q_c = [q_c0, q_c] the current
orientation (unit quaternions [w, x, y, z]),

    e = q_c0 q_d - q_d0 q_c - q_d x q_c,

which is the vector part of the error quaternion Q_e = Q_d Q_c^-1, the
rotation that takes the current orientation onto the desired one, in the
frame in which both are expressed (the world frame for a gripper). With
Q_e = [cos(theta/2), sin(theta/2) n], e = sin(theta/2) n: for small angles
half the rotation vector theta n.

Shortest path: Q and -Q are the same rotation. If the scalar part of Q_e,
q_d0 q_c0 + q_d . q_c, is negative, e is negated, so that the controller
always turns through the shorter way (theta <= pi); at exactly a half turn
both ways are equally short and the sign is that of the formula. Under the P controller
omega = k_o e (world frame), the angle obeys theta_dot = -k_o sin(theta/2)
about a fixed axis, and converges to 0 from any theta < pi.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

FloatArray = NDArray[np.float64]


def quaternion_error(q_desired: ArrayLike, q_current: ArrayLike) -> FloatArray:
    """Quaternion error e = vec(Q_d Q_c^-1) along the shortest path (equ:quaternion_error).

    Args:
        q_desired: Desired orientation Q_d, unit quaternion [w, x, y, z].  # (4,)
        q_current: Current orientation Q_c, unit quaternion [w, x, y, z].  # (4,)

    Returns:
        e = sin(theta/2) n, in the frame of the two quaternions; zero iff
        Q_d = +-Q_c.  # (3,)
    """
    d0, d1, d2, d3 = (float(c) for c in np.asarray(q_desired, dtype=float))
    c0, c1, c2, c3 = (float(c) for c in np.asarray(q_current, dtype=float))
    # q_c0 q_d - q_d0 q_c - q_d x q_c
    e1 = c0 * d1 - d0 * c1 - (d2 * c3 - d3 * c2)
    e2 = c0 * d2 - d0 * c2 - (d3 * c1 - d1 * c3)
    e3 = c0 * d3 - d0 * c3 - (d1 * c2 - d2 * c1)
    if d0 * c0 + d1 * c1 + d2 * c2 + d3 * c3 < 0.0:  # scalar part of Q_d Q_c^-1
        return np.array([-e1, -e2, -e3])
    return np.array([e1, e2, e3])
