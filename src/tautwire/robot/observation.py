"""What a primitive may see: gripper poses, the measured wrench, the grippers.

No ground truth is ever part of an observation.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
from numpy.typing import NDArray

from tautwire.robot.arm import Arm

FloatArray = NDArray[np.float64]


@dataclass(frozen=True)
class Wrench:
    """A wrench measured by a wrist force-torque sensor.

    Attributes:
        arm: The wrist that carries the sensor.
        force: Force [N] in the world frame that the cable and the gripper's
            contacts exert on the gripper, sensor bias removed.  # (3,)
        torque: Torque [N m] in the world frame about the gripper's tool
            centre point.  # (3,)
    """

    arm: Arm
    force: FloatArray
    torque: FloatArray


@dataclass(frozen=True)
class GripperState:
    """Pose and fingers of one gripper.

    Attributes:
        position: Tool centre point [m], world frame.  # (3,)
        orientation: Unit quaternion [w, x, y, z], tool frame in world frame;
            the tool x-axis runs along the held cable.  # (4,)
        opening: Distance between the fingers [m].
        grip_force: Force [N] with which the fingers squeeze.
    """

    position: FloatArray
    orientation: FloatArray
    opening: float = 0.0
    grip_force: float = 0.0


@dataclass(frozen=True)
class Observation:
    """One sample of everything the robot senses.

    Attributes:
        time: Time [s] since the start of the run.
        left: State of the left gripper.
        right: State of the right gripper.
        wrenches: One wrench per wrist that carries a sensor (one or two).
    """

    time: float
    left: GripperState
    right: GripperState
    wrenches: tuple[Wrench, ...] = field(default_factory=tuple)

    def gripper(self, arm: Arm) -> GripperState:
        """Return the state of the gripper on ``arm``."""
        return self.left if arm == "left" else self.right

    def wrench(self, arm: Arm | None = None) -> Wrench:
        """Return the wrench of the sensor on ``arm`` (default: the first sensor).

        Raises:
            LookupError: if that wrist carries no sensor.
        """
        for w in self.wrenches:
            if arm is None or w.arm == arm:
                return w
        raise LookupError(f"no force-torque sensor on the {arm or 'any'} arm")

    def has_sensor(self, arm: Arm) -> bool:
        """Whether the wrist of ``arm`` carries a force-torque sensor."""
        return any(w.arm == arm for w in self.wrenches)
