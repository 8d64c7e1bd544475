"""Where a taut cable leaves a peg: the tangent point, not the peg's axis.

A cable wrapped round a peg leaves it tangentially, a peg radius plus a
cable radius beside the axis (SCENARIO.md: a peg's estimate is its axis
point). A primitive that aims the cable from the peg at a goal (a clip's
slot) aims from that tangent point, on the side the cable wraps the peg.
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import NDArray

FloatArray = NDArray[np.float64]


def wrap_side(axis_point: FloatArray, p_gripper: FloatArray, direction: FloatArray) -> float:
    """On which side of the cable the peg's axis lies, seen from the peg towards the gripper.

    Args:
        axis_point: A point [m] of the peg's (vertical) axis.  # (3,)
        p_gripper: Gripper position [m].  # (3,)
        direction: Unit tension direction from the gripper towards the peg.  # (3,)

    Returns:
        +1 if the axis is on the cable's left (seen from above, heading from
        the peg to the gripper), -1 on its right, 0 if the line passes
        through the axis (no side).
    """
    offset = axis_offset(axis_point, p_gripper, direction)
    return 0.0 if abs(offset) < 1e-12 else math.copysign(1.0, offset)


def axis_offset(axis_point: FloatArray, p_gripper: FloatArray, direction: FloatArray) -> float:
    """Signed horizontal distance [m] of the peg's axis from the force's line.

    Positive on the cable's left, as :func:`wrap_side`; the line of a cable
    leaving the peg tangentially passes a peg radius plus a cable radius
    beside the axis.

    Args:
        axis_point: A point [m] of the peg's (vertical) axis.  # (3,)
        p_gripper: Gripper position [m].  # (3,)
        direction: Unit tension direction from the gripper towards the peg.  # (3,)
    """
    heading = -np.asarray(direction, dtype=float)[:2]  # from the peg towards the gripper
    n = float(np.hypot(heading[0], heading[1]))
    if n < 1e-9:
        return 0.0
    r = (np.asarray(axis_point, dtype=float) - np.asarray(p_gripper, dtype=float))[:2]
    return float(heading[0] * r[1] - heading[1] * r[0]) / n


def turn_side(
    before: FloatArray,
    axis_point: FloatArray,
    p_gripper: FloatArray,
    wound: float | None = None,
) -> float:
    """The wrap side of a peg from the cable's path: where it comes from, the peg, the gripper.

    A cable from ``before`` round the peg to the gripper turns towards the
    peg: a left turn (seen from above) wraps it with the axis on the cable's
    left, +1 as :func:`wrap_side`; a right turn -1; 0 for a straight path.
    The path's angle alone is right for wraps under half a turn; ``wound``,
    the turn [rad] last followed round the peg from ``before`` to the
    gripper (windings counted), picks the winding: the turn now is the
    angle plus the whole turns that bring it nearest ``wound``.
    """
    turn = path_turn(before, axis_point, p_gripper, wound)
    return 0.0 if abs(turn) < 1e-12 else math.copysign(1.0, turn)


def path_turn(
    before: FloatArray,
    axis_point: FloatArray,
    p_gripper: FloatArray,
    wound: float | None = None,
) -> float:
    """The cable's turn [rad] round the peg, seen from above: + left, - right (:func:`turn_side`).

    The angle from the way in (``before`` to the peg) to the way out (the
    peg to the gripper), with the whole turns that bring it nearest
    ``wound`` where a winding was followed.
    """
    a = (np.asarray(axis_point, dtype=float) - np.asarray(before, dtype=float))[:2]
    b = (np.asarray(p_gripper, dtype=float) - np.asarray(axis_point, dtype=float))[:2]
    cross = float(a[0] * b[1] - a[1] * b[0])
    angle = math.atan2(cross, float(a @ b))
    return angle if wound is None else nearest_turn(angle, wound)


def nearest_turn(angle: float, reference: float) -> float:
    """``angle`` [rad] plus the whole turns that bring it nearest ``reference`` [rad]."""
    return angle + 2.0 * math.pi * round((reference - angle) / (2.0 * math.pi))


def leave_point(
    axis_point: FloatArray, radius: float, through: FloatArray, side: float
) -> FloatArray:
    """The point [m] where the cable leaves the peg on its way to pass over ``through``.

    The tangent point, on the circle of ``radius`` [m] about the axis (peg
    radius plus cable radius), of the line to ``through`` that keeps the
    axis on ``side`` (+1: the cable's left, seen towards ``through``; as
    :func:`wrap_side`). At the axis point's height. With ``side`` 0, or
    ``through`` inside the circle, the axis point itself.
    """
    c = np.asarray(axis_point, dtype=float)
    v = np.asarray(through, dtype=float)[:2] - c[:2]
    dist = float(np.hypot(v[0], v[1]))
    if side == 0.0 or dist <= radius or radius <= 0.0:
        return c.copy()
    beta = math.acos(radius / dist)
    u = v / dist
    best = c.copy()
    for sign in (1.0, -1.0):
        cb, sb = math.cos(sign * beta), math.sin(sign * beta)
        t = c[:2] + radius * np.array([cb * u[0] - sb * u[1], sb * u[0] + cb * u[1]])
        heading = np.asarray(through, dtype=float)[:2] - t
        r = c[:2] - t
        if math.copysign(1.0, float(heading[0] * r[1] - heading[1] * r[0])) == side:
            best = np.array([t[0], t[1], c[2]])
    return best
