"""Small 3-vector helpers for the 4 ms control loop.

``numpy.cross`` and ``numpy.linalg.norm`` cost tens of microseconds on a
3-vector (axis normalisation, broadcasting); these do the same arithmetic
on floats.
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import ArrayLike, NDArray

FloatArray = NDArray[np.float64]


def cross3(a: ArrayLike, b: ArrayLike) -> FloatArray:
    """Cross product ``a x b`` of two 3-vectors."""
    ax, ay, az = np.asarray(a, dtype=float).reshape(3).tolist()
    bx, by, bz = np.asarray(b, dtype=float).reshape(3).tolist()
    return np.array([ay * bz - az * by, az * bx - ax * bz, ax * by - ay * bx])


def norm3(a: ArrayLike) -> float:
    """Euclidean norm of a 3-vector."""
    x, y, z = np.asarray(a, dtype=float).reshape(3).tolist()
    return math.sqrt(x * x + y * y + z * z)


def nearest_on_segment(p: ArrayLike, a: ArrayLike, b: ArrayLike) -> FloatArray:
    """The point of the segment from ``a`` to ``b`` nearest ``p`` (any dimension).

    Args:
        p: The point.  # (n,)
        a: The segment's start.  # (n,)
        b: The segment's end.  # (n,)

    Returns:
        The nearest point; ``a`` for a segment shorter than 1e-9 (units of
        the inputs).  # (n,)
    """
    pa = np.asarray(p, dtype=float)
    aa = np.asarray(a, dtype=float)
    ab = np.asarray(b, dtype=float) - aa
    n2 = float(ab @ ab)
    t = 0.0 if n2 < 1e-18 else min(1.0, max(0.0, float((pa - aa) @ ab) / n2))
    out: FloatArray = aa + t * ab
    return out
