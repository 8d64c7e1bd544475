"""Proportional motion controllers (equ:Motion_controller_error, equ:quaternion_error).

For one frame i in {left, right, abs, rel}:

    x_dot_m,i = k_p (x_d,i - x_c,i)                       (equ:Motion_controller_error)
    omega_m,i = k_o (q_c0 q_d - q_d0 q_c - q_d x q_c)      (equ:quaternion_error)

The motion-control signal zeta_m stacks them for both arms, either
individually [left, right] or coordinated [abs, rel]; a coordinated signal is
converted to the individual twist the robot takes with the exact inverse
velocity map of :mod:`tautwire.control.task_space`. The relative orientation
Q_rel = Q_right^-1 Q_left is expressed in the right tool frame, so its error
(and the relative angular velocity it asks for) is rotated into the world
frame by Q_right before the conversion.
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import ArrayLike, NDArray

from tautwire.control.quaternion_error import quaternion_error
from tautwire.control.task_space import (
    CoordinatedPose,
    DualPose,
    Pose,
    coordinated_pose,
    individual_twist,
)
from tautwire.errors import InvalidArgumentError
from tautwire.model import quaternion as qf

FloatArray = NDArray[np.float64]


class MotionController:
    """P controller of one frame's pose, returning a 6-D twist [v, w].

    Args:
        k_p: Position gain k_p [1/s], > 0.
        k_o: Orientation gain k_o [1/s], > 0 (the quaternion error is
            sin(theta/2), about half the angle, so the small-angle
            orientation time constant is 2 / k_o).

    Raises:
        InvalidArgumentError: if a gain is not a finite positive number.
    """

    def __init__(self, k_p: float = 2.0, k_o: float = 4.0) -> None:
        for name, value in (("k_p", k_p), ("k_o", k_o)):
            if not math.isfinite(value) or value <= 0.0:
                raise InvalidArgumentError(f"{name} must be a finite gain > 0 [1/s], got {value}")
        self.k_p = float(k_p)
        self.k_o = float(k_o)

    def __call__(self, desired: Pose, current: Pose) -> FloatArray:
        """Twist [x_dot_m, omega_m] that drives ``current`` to ``desired``.

        Args:
            desired: Desired pose x_d, Q_d.
            current: Current pose x_c, Q_c, in the same frame.

        Returns:
            [v, w] [m/s, rad/s] in that frame.  # (6,)
        """
        v = self.k_p * (np.asarray(desired.position, dtype=float) - current.position)
        w = self.k_o * quaternion_error(desired.orientation, current.orientation)
        return np.concatenate((v, w))

    def linear(self, x_desired: ArrayLike, x_current: ArrayLike) -> FloatArray:
        """x_dot_m = k_p (x_d - x_c) [m/s] (equ:Motion_controller_error).  # (3,)."""
        x_dot: FloatArray = self.k_p * (
            np.asarray(x_desired, dtype=float) - np.asarray(x_current, dtype=float)
        )
        return x_dot

    def angular(self, q_desired: ArrayLike, q_current: ArrayLike) -> FloatArray:
        """omega_m = k_o e(Q_d, Q_c) [rad/s] (equ:quaternion_error).  # (3,)."""
        return self.k_o * quaternion_error(q_desired, q_current)


def individual_motion_twist(
    controller: MotionController, desired: DualPose, current: DualPose
) -> FloatArray:
    """zeta_m = [x_dot_left, w_left, x_dot_right, w_right] for individual control.

    Args:
        controller: The P controller applied to each gripper.
        desired: Desired poses of both grippers, world frame.
        current: Current poses of both grippers, world frame.

    Returns:
        Individual task-space twist [m/s, rad/s], world frame.  # (12,)
    """
    return np.concatenate(
        (controller(desired.left, current.left), controller(desired.right, current.right))
    )


def coordinated_motion_command(
    controller: MotionController, desired: CoordinatedPose, current: DualPose
) -> FloatArray:
    """zeta_m = [x_dot_abs, w_abs, x_dot_rel, w_rel] for coordinated control.

    Args:
        controller: The P controller applied to the absolute and the relative frame.
        desired: Desired absolute and relative pose.
        current: Current poses of both grippers, world frame.

    Returns:
        Coordinated task-space twist [m/s, rad/s], world frame (the relative
        angular velocity already rotated into the world frame).  # (12,)
    """
    now = coordinated_pose(current)
    zeta_abs = controller(desired.absolute, now.absolute)  # (6,)
    v_rel = controller.linear(desired.relative.position, now.relative.position)
    w_rel_right = controller.angular(desired.relative.orientation, now.relative.orientation)
    # right tool frame -> world
    w_rel = qf.rotate_floats(qf.quat_floats(current.right.orientation), qf.vec_floats(w_rel_right))
    return np.concatenate((zeta_abs, v_rel, w_rel))


def coordinated_motion_twist(
    controller: MotionController, desired: CoordinatedPose, current: DualPose
) -> FloatArray:
    """Individual twist that realises the coordinated P control of the two arms.

    Args:
        controller: The P controller applied to the absolute and the relative frame.
        desired: Desired absolute and relative pose.
        current: Current poses of both grippers, world frame.

    Returns:
        Individual task-space twist [v_left, w_left, v_right, w_right]
        [m/s, rad/s], world frame, as the robot takes it.  # (12,)
    """
    return individual_twist(coordinated_motion_command(controller, desired, current), current)
