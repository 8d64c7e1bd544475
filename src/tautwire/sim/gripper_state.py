"""The kinematic state of one simulated gripper."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from tautwire.errors import InvalidArgumentError
from tautwire.model.quaternion import multiply_floats, quat_floats
from tautwire.robot.command import GripperMode

FloatArray = NDArray[np.float64]


def integrate_pose(
    position: FloatArray,
    orientation: FloatArray,
    linear: FloatArray,
    angular: FloatArray,
    dt: float,
) -> tuple[FloatArray, FloatArray]:
    """Advance a pose by a constant world-frame twist for ``dt`` [s].

    It runs once or twice per control period for each moving gripper, so it
    works on floats where that gives the same numbers: the norms are
    ``sqrt(x @ x)``, exactly what ``np.linalg.norm`` computes, and the product
    and renormalisation are those of :func:`tautwire.model.quaternion.multiply`
    and :func:`tautwire.model.quaternion.as_quaternion` (a test holds it to
    them bit for bit).

    Args:
        position: [m].  # (3,)
        orientation: [w, x, y, z].  # (4,)
        linear: Velocity [m/s], world frame.  # (3,)
        angular: Angular velocity [rad/s], world frame.  # (3,)
        dt: Duration [s].

    Returns:
        The new position and orientation (exact for a constant twist).
    """
    rate = math.sqrt(float(angular @ angular))
    angle = rate * dt
    if angle > 0.0:
        axis = angular / rate
        c, s = np.cos(0.5 * angle), np.sin(0.5 * angle)
        dq = (float(c), float(s * axis[0]), float(s * axis[1]), float(s * axis[2]))
        q = np.array(multiply_floats(dq, quat_floats(orientation)))
        norm = math.sqrt(float(q @ q))
        if not math.isfinite(norm) or norm < 1e-12:
            raise InvalidArgumentError(f"the gripper orientation became {q!r} (not a rotation)")
        q = q / norm
        orientation = -q if q[0] < 0.0 else q
    return position + linear * dt, orientation


@dataclass
class GripperState:
    """Mutable state of one gripper in the simulated world.

    Attributes:
        position: Tool centre point [m], world frame.  # (3,)
        orientation: [w, x, y, z].  # (4,)
        linear: Commanded velocity [m/s], world frame.  # (3,)
        angular: Commanded angular velocity [rad/s], world frame.  # (3,)
        mode: Finger mode.
        grip_force: Force [N] with which the fingers squeeze (0 when open).
        held: (cable name, vertex index) held by a connect equality, or None.
        moving: Whether ``linear`` is non-zero.
        turning: Whether ``angular`` is non-zero (both flags are set with the
            twist, :meth:`tautwire.sim.world.SimWorld.set_twist`).
    """

    position: FloatArray
    orientation: FloatArray
    linear: FloatArray
    angular: FloatArray
    mode: GripperMode = "open"
    grip_force: float = 0.0
    held: tuple[str, int] | None = None
    moving: bool = False
    turning: bool = False
