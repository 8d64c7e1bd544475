"""Quaternion helpers in the project's [w, x, y, z] convention.

SciPy's :class:`~scipy.spatial.transform.Rotation` is used for the algebra;
its quaternions are [x, y, z, w], reordered here so that [w, x, y, z] is kept
at every interface (not with ``scalar_first=True``: SciPy has it only since
1.14, and the floor is 1.11).
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy.spatial.transform import Rotation

from tautwire.errors import InvalidArgumentError
from tautwire.model.vector3 import cross3, norm3

FloatArray = NDArray[np.float64]

IDENTITY: FloatArray = np.array([1.0, 0.0, 0.0, 0.0])


def as_quaternion(q: ArrayLike) -> FloatArray:
    """Return ``q`` as a unit quaternion [w, x, y, z] with w >= 0.

    Raises:
        InvalidArgumentError: if ``q`` is not a finite, non-zero 4-vector.
    """
    arr = np.asarray(q, dtype=float).reshape(-1)
    if arr.shape != (4,) or not np.all(np.isfinite(arr)):
        raise InvalidArgumentError(f"a quaternion is 4 finite numbers [w, x, y, z], got {q!r}")
    norm = float(np.linalg.norm(arr))
    if norm < 1e-12:
        raise InvalidArgumentError("a quaternion must not be zero")
    arr = arr / norm
    return -arr if arr[0] < 0.0 else arr


def to_rotation(q: ArrayLike) -> Rotation:
    """SciPy rotation of the quaternion ``q`` = [w, x, y, z]."""
    w, x, y, z = as_quaternion(q)
    return Rotation.from_quat([x, y, z, w])


def from_rotation(rotation: Rotation) -> FloatArray:
    """Quaternion [w, x, y, z] (w >= 0) of a SciPy rotation."""
    x, y, z, w = rotation.as_quat()
    return as_quaternion([w, x, y, z])


def multiply(q1: ArrayLike, q2: ArrayLike) -> FloatArray:
    """Hamilton product ``q1 q2`` of two [w, x, y, z] quaternions."""
    w1, x1, y1, z1 = np.asarray(q1, dtype=float)
    w2, x2, y2, z2 = np.asarray(q2, dtype=float)
    return np.array(
        [
            w1 * w2 - x1 * x2 - y1 * y2 - z1 * z2,
            w1 * x2 + x1 * w2 + y1 * z2 - z1 * y2,
            w1 * y2 - x1 * z2 + y1 * w2 + z1 * x2,
            w1 * z2 + x1 * y2 - y1 * x2 + z1 * w2,
        ]
    )


def conjugate(q: ArrayLike) -> FloatArray:
    """Conjugate (the inverse of a unit quaternion) [w, -x, -y, -z]."""
    arr = np.asarray(q, dtype=float)
    return np.array([arr[0], -arr[1], -arr[2], -arr[3]])


def rotate(q: ArrayLike, v: ArrayLike) -> FloatArray:
    """Rotate the vector ``v`` by the unit quaternion ``q``."""
    qv = np.concatenate(([0.0], np.asarray(v, dtype=float)))
    return multiply(multiply(q, qv), conjugate(q))[1:]


def orientation_along(direction: ArrayLike) -> FloatArray:
    """Orientation whose x-axis points along ``direction``, without twist.

    The rotation is the smallest one that takes the world x-axis onto
    ``direction`` (this is how the paper orients estimated feature points:
    x along the cable, no twist).

    Args:
        direction: Vector along the cable; its length does not matter.  # (3,)

    Returns:
        Unit quaternion [w, x, y, z].  # (4,)
    """
    dx, dy, dz = (float(v) for v in np.asarray(direction, dtype=float).reshape(3))
    n = math.sqrt(dx * dx + dy * dy + dz * dz)
    if n < 1e-12 or not math.isfinite(n):
        return IDENTITY.copy()
    c = dx / n  # cos of the angle between x and the direction
    if c >= 0.0:
        # q = [1 + c, x cross d] normalised: the half-angle rotation from x to d
        w, y, z = 1.0 + c, -dz / n, dy / n
        m = math.sqrt(w * w + y * y + z * z)
        return np.array([w / m, 0.0, y / m, z / m])
    # near -x the formula loses precision: turn half about z (x -> -x), then
    # the small rotation from -x to d; q = q_small q_z = [-z1, y1, 0, w1]
    w1, y1, z1 = 1.0 - c, dz / n, -dy / n
    m = math.sqrt(w1 * w1 + y1 * y1 + z1 * z1)
    q = np.array([-z1 / m, y1 / m, 0.0, w1 / m])
    return -q if q[0] < 0.0 else q


def shortest_arc(a: ArrayLike, b: ArrayLike) -> FloatArray:
    """The smallest rotation [w, x, y, z] that turns direction ``a`` onto ``b``.

    Float arithmetic (no numpy.cross): it runs in the control loop.

    Args:
        a: Non-zero direction.  # (3,)
        b: Non-zero direction.  # (3,)

    Returns:
        Unit quaternion q with rotate(q, a / |a|) = b / |b|; for opposite
        directions a half turn about an axis normal to ``a``.
    """
    u = np.asarray(a, dtype=float)
    v = np.asarray(b, dtype=float)
    u = u / norm3(u)
    v = v / norm3(v)
    c = float(u @ v)
    if c < -1.0 + 1e-9:  # opposite: half turn about any axis normal to a
        n = cross3(u, [1.0, 0.0, 0.0] if abs(u[0]) < 0.9 else [0.0, 1.0, 0.0])
        n /= norm3(n)
        return np.array([0.0, *n])
    q = np.array([1.0 + c, *cross3(u, v)])
    out: FloatArray = q / math.sqrt(float(q @ q))
    return out


def turn_x_onto(q: ArrayLike, direction: ArrayLike) -> FloatArray:
    """``q`` turned by the shortest arc that takes its x-axis onto ``direction``.

    How a gripper keeps its tool x-axis along the cable: the smallest change
    of orientation, no twist added.

    Args:
        q: Current orientation [w, x, y, z].  # (4,)
        direction: Desired direction of the x-axis (any length).  # (3,)

    Returns:
        The turned orientation [w, x, y, z].  # (4,)
    """
    return multiply(shortest_arc(rotate(q, [1.0, 0.0, 0.0]), direction), q)


def turn_x_onto_line(q: ArrayLike, direction: ArrayLike) -> FloatArray:
    """``q`` turned by the shortest arc that lays its x-axis along the line of ``direction``.

    A parallel gripper holds a cable between its fingers along its tool
    x-axis, and it holds it as well with +x as with -x along the cable:
    whichever of ``direction`` and ``-direction`` the x-axis is nearer is the
    goal, so no half turn is ever commanded (one would wrap the cable round
    a fingertip).

    Args:
        q: Current orientation [w, x, y, z].  # (4,)
        direction: The line's direction (either sense, any length).  # (3,)

    Returns:
        The turned orientation [w, x, y, z].  # (4,)
    """
    d = np.asarray(direction, dtype=float).reshape(3)
    if float(rotate(q, [1.0, 0.0, 0.0]) @ d) < 0.0:
        d = -d
    return turn_x_onto(q, d)
