"""Which tool axis, +x or -x, the held cable leaves along (grasp-aware orientation).

The fingers hold the cable along the tool x-axis, but nothing makes +x point
away from the contact: a gripper may start with +x towards the fixture as
often as away from it, and a regrip may leave either. The sensed pull tells
which: the force the cable exerts on the gripper points from the gripper
towards the contact, so the cable leaves along ``sign(x . f)`` x. A
primitive that orients the gripper decides the sign once, at the first taut
sample, and keeps it: near 90 deg the force alone could flip it back and
forth, and a turn of the grasp never happens by itself.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

from tautwire.model.quaternion import rotate, turn_x_onto

FloatArray = NDArray[np.float64]


class ToolAxis:
    """The sign s of the tool axis s x that points from the gripper along the cable to its contact.

    Attributes:
        sign: +1 (the cable leaves along +x), -1 (along -x), or None before
            the first decision.
    """

    def __init__(self) -> None:
        self.sign: float | None = None

    def decide(self, orientation: FloatArray, direction: FloatArray) -> float:
        """Decide the sign (once) from the tool orientation and the cable's direction.

        Args:
            orientation: Tool orientation [w, x, y, z].  # (4,)
            direction: Unit direction from the gripper towards the contact
                (the weight-compensated force's).  # (3,)

        Returns:
            The sign, +1 or -1.
        """
        if self.sign is None:
            x_axis = rotate(orientation, [1.0, 0.0, 0.0])
            self.sign = 1.0 if float(x_axis @ direction) >= 0.0 else -1.0
        return self.sign

    def target(self, orientation: FloatArray, direction: FloatArray) -> FloatArray:
        """The orientation [w, x, y, z] turned by the shortest arc that lays s x along the cable.

        Args:
            orientation: Current tool orientation [w, x, y, z].  # (4,)
            direction: Unit direction from the gripper towards the contact.  # (3,)
        """
        s = self.decide(orientation, direction)
        return turn_x_onto(orientation, s * np.asarray(direction, dtype=float))

    def angle(self, orientation: FloatArray, direction: FloatArray) -> float:
        """Angle [rad] between s x and the cable's direction towards the contact."""
        s = self.decide(orientation, direction)
        x_axis = rotate(orientation, [1.0, 0.0, 0.0])
        c = s * float(x_axis @ direction) / max(float(np.linalg.norm(direction)), 1e-12)
        return float(np.arccos(min(max(c, -1.0), 1.0)))
