"""Quaternions in the project's [w, x, y, z] convention: the one module.

Three layers, each formula written once:

- **The float fast path** (``*_floats``): Hamilton product, conjugate, sign
  fix, square root, logarithm and vector rotation on tuples of plain
  Python floats, for the task-space maps that run every 4 ms control
  period. A NumPy call on a 4-vector costs about a microsecond;
  ``bench/quaternion.py`` measures the fast path against the same formulas
  on NumPy arrays.
- **The array API** on NumPy 4-vectors (``multiply``, ``conjugate``,
  ``quaternion_log``, ``quaternion_exp``, ``quaternion_sqrt``, ``rotate``,
  ``orientation_along``, ...), the interface everywhere else; where a float
  formula exists, the array function is it (the same operations in the
  same order, so the same bits).
- **SciPy**: :class:`~scipy.spatial.transform.Rotation` (interpolation)
  through :func:`to_rotation` and :func:`from_rotation`. Its quaternions are
  [x, y, z, w], reordered here so that [w, x, y, z] is kept at every
  interface (not with ``scalar_first=True``: SciPy has it only since 1.14,
  and the floor is 1.11).
"""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy.spatial.transform import Rotation

from tautwire.errors import InvalidArgumentError
from tautwire.model.vector3 import cross3, norm3

FloatArray = NDArray[np.float64]

IDENTITY: FloatArray = np.array([1.0, 0.0, 0.0, 0.0])

Quat = tuple[float, float, float, float]
"""A quaternion [w, x, y, z] as plain floats (the fast path)."""
Vec = tuple[float, float, float]
"""A 3-vector as plain floats (the fast path)."""

#: Below this |(x, y, z)| the logarithm uses its series (theta = 2 asin(s) ~ 2 s / w).
_SMALL_ANGLE = 1e-6


# ------------------------------------------------------------ float fast path


def quat_floats(q: FloatArray | Sequence[float]) -> Quat:
    """A quaternion [w, x, y, z] (array or sequence) as a tuple of floats."""
    return (float(q[0]), float(q[1]), float(q[2]), float(q[3]))


def vec_floats(v: FloatArray | Sequence[float]) -> Vec:
    """A 3-vector (array or sequence) as a tuple of floats."""
    return (float(v[0]), float(v[1]), float(v[2]))


def multiply_floats(a: Quat, b: Quat) -> Quat:
    """Hamilton product a b."""
    aw, ax, ay, az = a
    bw, bx, by, bz = b
    return (
        aw * bw - ax * bx - ay * by - az * bz,
        aw * bx + ax * bw + ay * bz - az * by,
        aw * by - ax * bz + ay * bw + az * bx,
        aw * bz + ax * by - ay * bx + az * bw,
    )


def conjugate_floats(q: Quat) -> Quat:
    """Conjugate [w, -x, -y, -z] (the inverse of a unit quaternion)."""
    return (q[0], -q[1], -q[2], -q[3])


def positive_floats(q: Quat) -> Quat:
    """The sign of q with w >= 0, renormalised to unit length."""
    w, x, y, z = q
    n = math.sqrt(w * w + x * x + y * y + z * z)
    if w < 0.0:
        n = -n
    return (w / n, x / n, y / n, z / n)


def sqrt_floats(q: Quat) -> Quat:
    """Half the rotation of the unit quaternion q, along the shortest arc (w > 0)."""
    w, x, y, z = q
    if w < 0.0:
        w, x, y, z = -w, -x, -y, -z
    # half-angle formula: cos(theta/4) = sqrt((1 + cos(theta/2)) / 2)
    c = math.sqrt(max(0.5 * (1.0 + w), 0.0))
    s = 0.5 / c  # sin(theta/2) / sin(theta/4) = 2 cos(theta/4)
    return (c, s * x, s * y, s * z)


def log_floats(q: Quat) -> Vec:
    """Rotation vector [rad] of the unit quaternion q (shortest, |phi| <= pi)."""
    w, x, y, z = q
    if w < 0.0:
        w, x, y, z = -w, -x, -y, -z
    s = math.sqrt(x * x + y * y + z * z)
    if s < _SMALL_ANGLE:
        scale = 2.0 / w if w > 0.0 else 0.0  # theta = 2 asin(s) ~ 2 s / w
        return (scale * x, scale * y, scale * z)
    scale = 2.0 * math.atan2(s, w) / s
    return (scale * x, scale * y, scale * z)


def rotate_floats(q: Quat, v: Vec) -> Vec:
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


# ------------------------------------------------------------------ array API


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
    a = np.asarray(q1, dtype=float).reshape(4)
    b = np.asarray(q2, dtype=float).reshape(4)
    return np.array(multiply_floats(quat_floats(a), quat_floats(b)))


def conjugate(q: ArrayLike) -> FloatArray:
    """Conjugate (the inverse of a unit quaternion) [w, -x, -y, -z]."""
    arr = np.asarray(q, dtype=float)
    return np.array([arr[0], -arr[1], -arr[2], -arr[3]])


def quaternion_log(q: ArrayLike) -> FloatArray:
    """Rotation vector phi [rad] of the unit quaternion ``q`` = [w, x, y, z].

    The sign of ``q`` is chosen so that w >= 0: the result is the shortest
    rotation, |phi| <= pi.

    Args:
        q: Unit quaternion [w, x, y, z].  # (4,)

    Returns:
        Rotation vector (axis times angle) [rad].  # (3,)
    """
    return np.array(log_floats(quat_floats(np.asarray(q, dtype=float).reshape(4))))


def quaternion_exp(phi: ArrayLike) -> FloatArray:
    """Unit quaternion [w, x, y, z] of the rotation vector ``phi`` [rad].

    Args:
        phi: Rotation vector (axis times angle) [rad].  # (3,)

    Returns:
        Unit quaternion [w, x, y, z].  # (4,)
    """
    px, py, pz = vec_floats(np.asarray(phi, dtype=float).reshape(3))
    theta = math.sqrt(px * px + py * py + pz * pz)
    # sin(theta/2)/theta, by its series near 0
    half = 0.5 - theta * theta / 48.0 if theta < _SMALL_ANGLE else math.sin(0.5 * theta) / theta
    return np.array([math.cos(0.5 * theta), half * px, half * py, half * pz])


def quaternion_sqrt(q: ArrayLike) -> FloatArray:
    """Square root ``q^(1/2)`` along the shortest arc (half the rotation).

    Args:
        q: Unit quaternion [w, x, y, z].  # (4,)

    Returns:
        Unit quaternion [w, x, y, z] with w > 0 whose square is +-q.  # (4,)
    """
    return np.array(sqrt_floats(quat_floats(np.asarray(q, dtype=float).reshape(4))))


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


def turn_x_onto_level(q: ArrayLike, direction: ArrayLike) -> FloatArray:
    """``q`` turned so that its x-axis lies along ``direction`` and its y-axis is level.

    :func:`turn_x_onto` applied period after period while the direction
    sweeps a cone (a cable that slopes down to a peg the gripper winds it
    round) adds a roll about x of the cone's solid angle per turn: random
    board 1652323633's I, 670 deg round a peg, left the tool z-axis 62 deg
    from vertical, and H then grasped the other cable with that roll. Here
    the shortest arc is followed by the roll about the new x that lays y
    horizontal, z staying on the side of the horizontal plane it is on (the
    grasp's own up or down): how H lays a new grasp (:func:`turn_x_onto_line`).

    Args:
        q: Current orientation [w, x, y, z].  # (4,)
        direction: Desired direction of the x-axis (any length).  # (3,)

    Returns:
        The turned orientation [w, x, y, z]; the shortest arc alone where
        ``direction`` is within 0.1 deg of vertical (no level y there).  # (4,)
    """
    turned = turn_x_onto(q, direction)
    x = rotate(turned, [1.0, 0.0, 0.0])
    y = rotate(turned, [0.0, 1.0, 0.0])
    up = 1.0 if float(rotate(turned, [0.0, 0.0, 1.0])[2]) >= 0.0 else -1.0
    level = np.array([-up * float(x[1]), up * float(x[0]), 0.0])  # up e_z cross x
    size = norm3(level)
    if size < 2e-3:
        return turned
    level /= size
    roll = math.atan2(float(cross3(y, level) @ x), float(y @ level))
    half = 0.5 * roll
    about_x = np.array([math.cos(half), *(math.sin(half) * x)])
    out = multiply(about_x, turned)
    return out


def turn_x_onto_line(q: ArrayLike, direction: ArrayLike) -> FloatArray:
    """``q`` turned to lay its x-axis along the line of ``direction``, its y-axis level.

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
    return turn_x_onto_level(q, d)
