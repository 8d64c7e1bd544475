"""Lines of a cable that leaves a round contact (a peg) tangentially.

A taut cable bends around a peg and leaves it along a tangent, so the line
through the gripper along the measured force misses the peg's axis by the
radius R the cable's centre line keeps from it (peg radius + cable radius).
While the gripper circles the peg in a known sense, the side is known: the
gripper position shifted sideways by R gives a line through the axis, which
the point-contact filter (equ:kalmanUpdate) can use as it is.

The same geometry tells whether a line that no longer fits the current
contact meets a peg of the board design: shifted by that peg's R, it passes
the peg's axis, between the gripper and the old contact.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

from tautwire.model.vector3 import cross3, norm3

FloatArray = NDArray[np.float64]

#: Prior std [m] of the radius R of a round contact: the cable's bending keeps
#: its centre line millimetres farther out than peg radius + cable radius
#: (12-16 mm around the 10.5 mm of scenarios/peg-change.yaml).
RADIUS_STD = 0.002

#: How much farther [m] than peg radius + cable radius the cable's centre line
#: keeps from a peg's axis where it leaves it: the median offset of the whole
#: wrench's line from the true axis while I circled a peg was 3.3-4.3 mm more
#: than peg radius + cable radius on robustness trials 1, 29 and 38 (the
#: discretised cable leaves from a vertex; a real cable's bending stiffness
#: adds B / (2 R T)).
RADIUS_MARGIN = 0.003

#: How far [m] a peg may sit from its board-design position, and a line from
#: its nominal tangent (the cable's bending and the fingers move it by
#: millimetres), for a gated line to count as meeting that peg.
DESIGN_TOLERANCE = 0.01


#: How far [m] a line that still fits the current contact may pass from a
#: peg's nominal tangent to count as resting on the peg: a taut cable that
#: touches a peg on its way to the old contact bears on the peg. The whole
#: wrench's line passes 2-4 mm from the nominal tangent when the cable first
#: touches (Fig. 5c: declared one to two iterations late at 2 mm, at once at 4).
TANGENT_TOLERANCE = 0.004


def side_towards_axis(force: FloatArray, axis: FloatArray, sense: float) -> FloatArray | None:
    """Unit vector normal to the line (and to ``axis``) from the line towards the peg's axis.

    Args:
        force: Force [N] the cable exerts on the gripper (along the line).  # (3,)
        axis: Unit rotation axis of the circling (the peg's axis direction).  # (3,)
        sense: +1 or -1: the rotation's sense about ``axis``.

    Returns:
        The unit vector, or None when the force is along the axis.  # (3,)
    """
    side = cross3(force, axis)
    n = norm3(side)
    if n < 1e-9:
        return None
    out: FloatArray = (sense / n) * side
    return out


def shift_onto_axis(
    p_gripper: FloatArray, force: FloatArray, axis: FloatArray, sense: float, radius: float
) -> FloatArray:
    """The gripper position shifted sideways by ``radius`` so its line passes the peg's axis.

    Args:
        p_gripper: Gripper position [m].  # (3,)
        force: Force [N] the cable exerts on the gripper (along the line).  # (3,)
        axis: Unit rotation axis of the circling (the peg's axis direction).  # (3,)
        sense: +1 or -1: the rotation's sense about ``axis``.
        radius: R [m], the distance of the cable's centre line from the axis.

    Returns:
        The shifted position [m] (``p_gripper`` itself when the force is
        along the axis).  # (3,)
    """
    side = side_towards_axis(force, axis, sense)
    if side is None:
        return p_gripper
    shifted: FloatArray = p_gripper + radius * side
    return shifted


def line_meets_peg(
    p_gripper: FloatArray,
    force: FloatArray,
    axis: FloatArray,
    sense: float,
    axis_point: FloatArray,
    radius: float,
    contact: FloatArray,
    tolerance: float = DESIGN_TOLERANCE,
) -> FloatArray | None:
    """Where a line tangent to a peg of the board design meets its axis, if it does.

    Args:
        p_gripper: Gripper position [m].  # (3,)
        force: Force [N] the cable exerts on the gripper.  # (3,)
        axis: Unit rotation axis (the peg's axis direction).  # (3,)
        sense: +1 or -1: the rotation's sense about ``axis``.
        axis_point: A point [m] on the peg's axis (board design).  # (3,)
        radius: R [m] (peg radius + cable radius).
        contact: The current contact estimate [m]: the peg must lie between
            the gripper and it.  # (3,)
        tolerance: Largest distance [m] of the shifted line from the axis.

    Returns:
        The point [m] on the peg's axis at the line's height, or None when
        the line passes the axis farther than ``tolerance`` (after the shift),
        or the peg is not between the gripper and ``contact``.  # (3,)
    """
    fn = norm3(force)
    if fn < 1e-9:
        return None
    u = force / fn  # from the gripper towards the contact
    u_across = u - axis * float(axis @ u)  # the line's direction normal to the axis
    n_across = norm3(u_across)
    if n_across < 1e-9:
        return None  # a line along the axis meets no peg side
    e = u_across / n_across
    q = shift_onto_axis(p_gripper, force, axis, sense, radius)
    to_axis = axis_point - q
    across = to_axis - axis * float(axis @ to_axis)  # to the axis, normal to it
    along = float(e @ across)  # normal to the axis, to where the line passes it
    miss = across - e * along  # the shifted line's miss distance, normal to the axis
    if norm3(miss) > tolerance:
        return None
    t = along / n_across  # along the (sloped) line to the same place
    if not 0.0 < t < float(u @ (contact - p_gripper)):
        return None  # behind the gripper, or beyond the old contact
    line_point = q + t * u
    meet: FloatArray = axis_point + axis * float(axis @ (line_point - axis_point))
    return meet
