"""The simulated wrist force-torque sensor.

A real wrist sensor measures everything its gripper transmits. In the
simulated world that is the total constraint force on the gripper's free
joint: the held cable's ``connect`` equality plus every contact on the
gripper's finger pads (the generalized constraint force of a free joint is
the net force, world frame, and the torque about the body origin, which is
the tool centre point, in the body frame). The sign is the force that the
cable and the contacts exert on the gripper. Tests check it against the
explicit sum of the equality's constraint force and ``mj_contactForce`` over
the gripper's contacts.

The sensor adds zero-mean Gaussian noise per axis from a seeded generator and
is sampled once per control period. What it samples is the mean of the
period's physics steps (a sensor filtered at the control rate): the last
step alone aliased the cable's vibration near the grasp, which the period's
twist update excites at the control rate, into a steady false pull.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

from tautwire.errors import InvalidArgumentError
from tautwire.robot.arm import Arm
from tautwire.robot.observation import Wrench

FloatArray = NDArray[np.float64]


class FTSensor:
    """Gaussian noise model of one wrist force-torque sensor.

    Args:
        arm: The wrist carrying it.
        noise_force: Standard deviation [N] per force axis.
        noise_torque: Standard deviation [N m] per torque axis.
        rng: Seeded generator of the noise.

    Raises:
        InvalidArgumentError: for a negative or non-finite standard deviation.
    """

    def __init__(
        self, arm: Arm, noise_force: float, noise_torque: float, rng: np.random.Generator
    ) -> None:
        for what, value in (("noise_force", noise_force), ("noise_torque", noise_torque)):
            if not np.isfinite(value) or value < 0.0:
                raise InvalidArgumentError(f"{what} must be finite and >= 0, got {value}")
        self._arm: Arm = arm
        self._noise_force = float(noise_force)
        self._noise_torque = float(noise_torque)
        self._rng = rng
        self._scale = np.array([self._noise_force] * 3 + [self._noise_torque] * 3)

    @property
    def arm(self) -> Arm:
        """The wrist carrying the sensor."""
        return self._arm

    def measure(self, force: FloatArray, torque: FloatArray) -> Wrench:
        """One noisy reading of a true wrench.

        Args:
            force: True force [N] on the gripper, world frame.  # (3,)
            torque: True torque [N m] about the tool centre point, world frame.  # (3,)
        """
        # one draw of six: the same numbers as three for the force, then three for the torque
        noise = self._scale * self._rng.standard_normal(6)
        return Wrench(self._arm, force + noise[0:3], torque + noise[3:6])
