"""The kinematic state of one simulated gripper."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from tautwire.model.quaternion import as_quaternion, multiply
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

    Args:
        position: [m].  # (3,)
        orientation: [w, x, y, z].  # (4,)
        linear: Velocity [m/s], world frame.  # (3,)
        angular: Angular velocity [rad/s], world frame.  # (3,)
        dt: Duration [s].

    Returns:
        The new position and orientation (exact for a constant twist).
    """
    angle = float(np.linalg.norm(angular)) * dt
    if angle > 0.0:
        axis = angular / np.linalg.norm(angular)
        dq = np.concatenate(([np.cos(0.5 * angle)], np.sin(0.5 * angle) * axis))
        orientation = as_quaternion(multiply(dq, orientation))
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
    """

    position: FloatArray
    orientation: FloatArray
    linear: FloatArray
    angular: FloatArray
    mode: GripperMode = "open"
    grip_force: float = 0.0
    held: tuple[str, int] | None = None
