"""What a primitive sends: a 12-D task-space twist and gripper commands."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Literal

import numpy as np
from numpy.typing import NDArray

from tautwire.errors import InvalidArgumentError

FloatArray = NDArray[np.float64]
GripperMode = Literal["hold", "open", "grip_force"]


@dataclass(frozen=True)
class GripperCommand:
    """Command for one gripper.

    Attributes:
        mode: ``"hold"`` keeps the current grasp (closed, full grip force),
            ``"open"`` opens the fingers and releases the cable,
            ``"grip_force"`` squeezes with ``grip_force`` so that the cable
            may slide against friction.
        grip_force: Grip force [N] for mode ``"grip_force"``.
    """

    mode: GripperMode = "hold"
    grip_force: float = 0.0

    def __post_init__(self) -> None:
        if self.mode not in ("hold", "open", "grip_force"):
            raise InvalidArgumentError(
                f"gripper mode must be 'hold', 'open' or 'grip_force', got {self.mode!r}"
            )
        if not np.isfinite(self.grip_force) or self.grip_force < 0.0:
            raise InvalidArgumentError(
                f"grip_force must be finite and >= 0 N, got {self.grip_force}"
            )


def _zero_twist() -> FloatArray:
    return np.zeros(12)


@dataclass(frozen=True)
class Command:
    """One control period's command.

    Attributes:
        twist: Task-space velocity in the world frame, individual form
            [v_left, w_left, v_right, w_right] in [m/s, rad/s].  # (12,)
        left: Command for the left gripper.
        right: Command for the right gripper.
    """

    twist: FloatArray = field(default_factory=_zero_twist)
    left: GripperCommand = field(default_factory=GripperCommand)
    right: GripperCommand = field(default_factory=GripperCommand)

    def __post_init__(self) -> None:
        twist = np.asarray(self.twist, dtype=float)
        if twist.shape != (12,):
            raise InvalidArgumentError(f"twist must have shape (12,), got {twist.shape}")
        if not np.all(np.isfinite(twist)):
            raise InvalidArgumentError("twist must be finite")
        object.__setattr__(self, "twist", twist)

    def gripper(self, arm: str) -> GripperCommand:
        """Return the command of the gripper on ``arm``."""
        return self.left if arm == "left" else self.right
