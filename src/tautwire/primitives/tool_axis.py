"""Which tool axis, +x or -x, the held cable leaves along (grasp-aware orientation).

The fingers hold the cable along the tool x-axis, but nothing makes +x point
away from the contact: a gripper may start with +x towards the fixture as
often as away from it, and a regrip may leave either. The sensed pull tells
which: the force the cable exerts on the gripper points from the gripper
towards the contact, so the cable leaves along ``sign(x . f)`` x. A
primitive that orients the gripper decides the sign once and keeps it: near
90 deg the force alone could flip it back and forth, and a turn of the grasp
never happens by itself.

Across the cable the force's direction says nothing: a cable that leaves
the fingers through one fingertip and bends by a little more than 90 deg
towards the contact pulls with ``x . f`` of the other sign (from a gripper
at 0.3 m, within about atan(12 mm / 0.3 m) = 2.3 deg of across), and at
the first taut sample (0.3 N, 0.05 N of noise) the direction is 10 deg
uncertain. Turned the wrong way, the gripper wraps the cable half round that
fingertip (measured: 3 of 40 Table I D scenes, all within 3 deg of across).
The whole wrench says which fingertip: the line of action passes through
the point e = p + s a x where the cable leaves the fingers (a > 0 from the
tool centre point), so its offset o = (f x tau) / |f|^2 from the tool
centre point has o . x = s a (1 - (f_hat . x)^2), while f_hat . x =
s cos(theta): both carry the sign s, the offset where the direction is
weak. :meth:`ToolAxis.observe` low-passes the wrench and decides on

    s = sign(f_hat . x + (o . x) / EXIT_SCALE)

once the low-passed pull reaches ``DECIDE_FORCE`` (there the offset's
noise, 0.002 N m / 1 N = 2 mm per sample, is a fifth of EXIT_SCALE); until
then a primitive that observes does not turn the gripper.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

from tautwire.estimation.force_line import line_offset
from tautwire.model.quaternion import rotate, turn_x_onto
from tautwire.primitives.low_pass import LowPass

FloatArray = NDArray[np.float64]

#: Low-passed pull [N] at which :meth:`ToolAxis.observe` decides the sign.
DECIDE_FORCE = 1.0
#: Length [m] that weighs the line's offset along x against the force's
#: direction: about how far from the tool centre point the cable leaves the
#: fingers (both terms carry the sign, so it need not be exact).
EXIT_SCALE = 0.01
#: A turn of the tool onto the cable pauses while the tension is above this
#: multiple of its set point (the force control then lets the cable out
#: before the fingers turn on): random board 1695658280's G turned 85 deg
#: with the cable resting on the clip 74 mm ahead and pulled from 3 to 13 N.
PAUSE_TENSION = 2.0


class ToolAxis:
    """The sign s of the tool axis s x that points from the gripper along the cable to its contact.

    Attributes:
        sign: +1 (the cable leaves along +x), -1 (along -x), or None before
            the first decision.
    """

    def __init__(self) -> None:
        self.sign: float | None = None
        self._watching = False
        self._force: LowPass[np.ndarray] = LowPass()
        self._torque: LowPass[np.ndarray] = LowPass()
        self._cable: LowPass[np.ndarray] = LowPass()  # the cable's direction (follow)

    def follow(
        self,
        time: float,
        orientation: FloatArray,
        direction: FloatArray,
        tension: float,
        set_point: float,
    ) -> tuple[float, FloatArray | None]:
        """Turn along a taut cable: its low-passed direction, the angle to it, the orientation.

        Args:
            time: Time [s] of the sample.
            orientation: Current tool orientation [w, x, y, z].  # (4,)
            direction: Unit direction from the gripper towards the contact.  # (3,)
            tension: The cable's tension [N].
            set_point: Its set point [N].

        Returns:
            The angle [rad] between s x and the low-passed direction
            (:meth:`angle`), and the orientation to turn to (:meth:`target`),
            or None while the tension is above ``PAUSE_TENSION`` times the
            set point (the turn waits).  # (4,)
        """
        cable = self._cable.update(time, np.asarray(direction, dtype=float))
        angle = self.angle(orientation, cable)
        if tension > PAUSE_TENSION * set_point:
            return angle, None
        return angle, self.target(orientation, cable)

    def observe(
        self, time: float, orientation: FloatArray, force: FloatArray, torque: FloatArray
    ) -> float | None:
        """Add one wrench of the taut cable; decide the sign from it once the pull is clear.

        After the first call the sign is decided only here, from the whole
        wrench (see the module docstring); until then :meth:`target` holds
        the orientation and :meth:`angle` measures against the line.

        Args:
            time: Time [s] of the sample.
            orientation: Tool orientation [w, x, y, z].  # (4,)
            force: Force [N] the cable exerts on the gripper, world frame.  # (3,)
            torque: Torque [N m] about the tool centre point, world frame.  # (3,)

        Returns:
            The sign, or None while the low-passed pull is under ``DECIDE_FORCE``.
        """
        self._watching = True
        if self.sign is not None:
            return self.sign
        f = self._force.update(time, np.asarray(force, dtype=float))
        tau = self._torque.update(time, np.asarray(torque, dtype=float))
        magnitude = float(np.linalg.norm(f))
        if not magnitude >= DECIDE_FORCE:  # also NaN
            return None
        x_axis = rotate(orientation, [1.0, 0.0, 0.0])
        evidence = float(x_axis @ f) / magnitude + float(x_axis @ line_offset(f, tau)) / EXIT_SCALE
        self.sign = 1.0 if evidence >= 0.0 else -1.0
        return self.sign

    def decide(self, orientation: FloatArray, direction: FloatArray) -> float:
        """Decide the sign (once) from the tool orientation and the cable's direction.

        Only for a primitive that does not :meth:`observe` the wrench (one
        that starts with the tool axis along the cable).

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

        Followed round a peg (I), the shortest arc rolls the tool by the
        cone's solid angle (random board 1652323633: 62 deg after 670 deg).
        Laying y level there too (:func:`~tautwire.model.quaternion.turn_x_onto_level`)
        made random board 360400295's F3 after I push the cable 7 mm beside
        its slot (not traced), so the grasp keeps its roll.

        While an observing primitive has not decided the sign, ``orientation``
        itself (no turn yet).

        Args:
            orientation: Current tool orientation [w, x, y, z].  # (4,)
            direction: Unit direction from the gripper towards the contact.  # (3,)
        """
        if self.sign is None and self._watching:
            return np.asarray(orientation, dtype=float).copy()
        s = self.decide(orientation, direction)
        return turn_x_onto(orientation, s * np.asarray(direction, dtype=float))

    def angle(self, orientation: FloatArray, direction: FloatArray) -> float:
        """Angle [rad] between s x and the cable's direction towards the contact.

        While an observing primitive has not decided the sign, the angle
        between the x-axis and the cable's line (either sense).
        """
        x_axis = rotate(orientation, [1.0, 0.0, 0.0])
        c = float(x_axis @ direction) / max(float(np.linalg.norm(direction)), 1e-12)
        if self.sign is None and self._watching:
            c = abs(c)
        else:
            c *= self.decide(orientation, direction)
        return float(np.arccos(min(max(c, -1.0), 1.0)))
