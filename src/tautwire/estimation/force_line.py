"""The cable's line of action from the whole wrench (an addition to the paper).

The paper's observation model (equ:ls_observation_model) assumes that the
taut cable's straight segment passes through the gripper's tool centre point
(TCP). A real cable leaves the fingers where it leaves them: through the
fingertip that faces the fixture, a few millimetres to the side when it
bends over a pad edge, or behind the TCP after a regrip. Its pull on the
gripper is then a force f whose line of action misses the TCP, and the
measured torque about the TCP, tau = r x f, tells by how much. The line of
action is the set of points

    p_tcp + (f x tau) / |f|^2 + lambda f,      lambda in R,

and ``o = (f x tau) / |f|^2`` is the point of that line nearest the TCP,
relative to it (its component along f is zero): for any r on the line,
f x (r x f) = r |f|^2 - f (f . r), so o is r minus its part along f.

Noise: to first order, with isotropic force noise sigma_f [N] and torque
noise sigma_tau [N m] per axis, the offset's noise normal to f has the
variance

    var(o) = (sigma_tau^2 + |o|^2 sigma_f^2) / |f|^2     [m^2] per normal axis,

(the torque's part normal to f moves the line by sigma_tau / |f|; the
force's noise scales the offset's length by sigma_f / |f|). It adds to the
line's direction noise of
:func:`~tautwire.estimation.contact_observation.line_noise_variance`.
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import ArrayLike, NDArray

FloatArray = NDArray[np.float64]

#: Forces weaker than this [N] give no line offset (the torque says nothing).
MIN_FORCE = 1e-6


def line_offset(force: ArrayLike, torque: ArrayLike) -> FloatArray:
    """Offset [m] from the TCP to the nearest point of the force's line of action.

    Args:
        force: Force f [N] the cable exerts on the gripper, world frame.  # (3,)
        torque: Torque tau [N m] about the TCP, world frame.  # (3,)

    Returns:
        o = (f x tau) / |f|^2, normal to f; zero for a vanishing or
        non-finite force.  # (3,)
    """
    fx, fy, fz = (float(v) for v in np.asarray(force, dtype=float).reshape(3))
    tx, ty, tz = (float(v) for v in np.asarray(torque, dtype=float).reshape(3))
    f2 = fx * fx + fy * fy + fz * fz
    if not (f2 > MIN_FORCE * MIN_FORCE and math.isfinite(f2)):
        return np.zeros(3)
    return np.array([fy * tz - fz * ty, fz * tx - fx * tz, fx * ty - fy * tx]) / f2


def line_point(p_tcp: ArrayLike, force: ArrayLike, torque: ArrayLike | None) -> FloatArray:
    """The point of the cable's line of action nearest the TCP [m].

    Args:
        p_tcp: Tool centre point [m], world frame.  # (3,)
        force: Force [N] on the gripper, world frame.  # (3,)
        torque: Torque [N m] about the TCP, world frame; None (no torque
            measured) assumes the line passes through the TCP.  # (3,)

    Returns:
        p_tcp + (f x tau) / |f|^2.  # (3,)
    """
    p = np.asarray(p_tcp, dtype=float).reshape(3)
    if torque is None:
        return p.copy()
    out: FloatArray = p + line_offset(force, torque)
    return out


def line_offset_variance(
    force_norm: float, offset_norm: float, force_noise: float, torque_noise: float
) -> float:
    """Variance [m^2] of the line offset per axis normal to the force (see module).

    Args:
        force_norm: |f| [N].
        offset_norm: |o| [m].
        force_noise: sigma_f [N], std per axis.
        torque_noise: sigma_tau [N m], std per axis.

    Returns:
        (sigma_tau^2 + |o|^2 sigma_f^2) / |f|^2; 0 for a vanishing force.
    """
    if not force_norm > MIN_FORCE:
        return 0.0
    s = torque_noise * torque_noise + (offset_norm * force_noise) ** 2
    return s / (force_norm * force_norm)
