"""The plane normal to a rotation axis, in which circles about the axis are fitted."""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import ArrayLike, NDArray

from tautwire.errors import InvalidArgumentError

FloatArray = NDArray[np.float64]


def axis_plane(axis: ArrayLike) -> tuple[FloatArray, FloatArray]:
    """The unit axis and an orthonormal basis of the plane normal to it.

    Args:
        axis: A non-zero direction.  # (3,)

    Returns:
        (a, B): the unit axis and the (2, 3) basis whose rows e1, e2 make
        (e1, e2, a) right-handed, so angles in plane coordinates turn
        right-handed about ``a``.  # (3,), (2, 3)

    Raises:
        InvalidArgumentError: for a zero or non-finite ``axis``.
    """
    a = np.asarray(axis, dtype=float).reshape(3)
    n = float(np.linalg.norm(a))
    if not (n > 0.0 and math.isfinite(n)):
        raise InvalidArgumentError(f"axis must be a non-zero vector, got {a.tolist()}")
    a = a / n
    helper = np.array([1.0, 0.0, 0.0]) if abs(a[0]) < 0.9 else np.array([0.0, 1.0, 0.0])
    e1 = np.cross(a, helper)
    e1 /= float(np.linalg.norm(e1))
    basis: FloatArray = np.stack([e1, np.cross(a, e1)])
    return a, basis
