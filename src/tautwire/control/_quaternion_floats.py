"""Quaternion arithmetic on plain Python floats for the 4 ms control hot path.

NumPy calls on 4-vectors cost about a microsecond each; these helpers work on
tuples of floats ([w, x, y, z], like everywhere in tautwire) and are used by
the task-space maps that run every control period. They are checked against
:mod:`tautwire.model.quaternion` in the tests.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np
from numpy.typing import NDArray

Quat = tuple[float, float, float, float]
Vec = tuple[float, float, float]


def quat(q: NDArray[np.float64] | Sequence[float]) -> Quat:
    """A quaternion [w, x, y, z] (array or sequence) as a tuple of floats."""
    return (float(q[0]), float(q[1]), float(q[2]), float(q[3]))


def vec(v: NDArray[np.float64] | Sequence[float]) -> Vec:
    """A 3-vector (array or sequence) as a tuple of floats."""
    return (float(v[0]), float(v[1]), float(v[2]))


def mul(a: Quat, b: Quat) -> Quat:
    """Hamilton product a b."""
    aw, ax, ay, az = a
    bw, bx, by, bz = b
    return (
        aw * bw - ax * bx - ay * by - az * bz,
        aw * bx + ax * bw + ay * bz - az * by,
        aw * by - ax * bz + ay * bw + az * bx,
        aw * bz + ax * by - ay * bx + az * bw,
    )


def conj(q: Quat) -> Quat:
    """Conjugate [w, -x, -y, -z] (the inverse of a unit quaternion)."""
    return (q[0], -q[1], -q[2], -q[3])


def positive(q: Quat) -> Quat:
    """The sign of q with w >= 0, renormalised to unit length."""
    w, x, y, z = q
    n = math.sqrt(w * w + x * x + y * y + z * z)
    if w < 0.0:
        n = -n
    return (w / n, x / n, y / n, z / n)


def sqrt_q(q: Quat) -> Quat:
    """Half the rotation of the unit quaternion q, along the shortest arc (w > 0)."""
    w, x, y, z = q
    if w < 0.0:
        w, x, y, z = -w, -x, -y, -z
    c = math.sqrt(max(0.5 * (1.0 + w), 0.0))
    s = 0.5 / c
    return (c, s * x, s * y, s * z)


def log_q(q: Quat) -> Vec:
    """Rotation vector [rad] of the unit quaternion q (shortest, |phi| <= pi)."""
    w, x, y, z = q
    if w < 0.0:
        w, x, y, z = -w, -x, -y, -z
    s = math.sqrt(x * x + y * y + z * z)
    if s < 1e-6:  # theta = 2 asin(s) ~ 2 s / w
        return (2.0 * x / w, 2.0 * y / w, 2.0 * z / w)
    scale = 2.0 * math.atan2(s, w) / s
    return (scale * x, scale * y, scale * z)


def rotate_v(q: Quat, v: Vec) -> Vec:
    """R(q) v for a unit quaternion q: v + 2 w (u x v) + 2 u x (u x v)."""
    w, ux, uy, uz = q
    vx, vy, vz = v
    tx = 2.0 * (uy * vz - uz * vy)
    ty = 2.0 * (uz * vx - ux * vz)
    tz = 2.0 * (ux * vy - uy * vx)
    return (
        vx + w * tx + (uy * tz - uz * ty),
        vy + w * ty + (uz * tx - ux * tz),
        vz + w * tz + (ux * ty - uy * tx),
    )
