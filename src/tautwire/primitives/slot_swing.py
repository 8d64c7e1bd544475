"""Turning a cable that crosses a clip's slot at an angle onto the slot, once it rests on the jaws.

A taut cable held from a fixed contact c over a clip is straight in plan
view, so it runs along the slot only where c lies on the slot's axis. Where
it comes in at an angle alpha, a cable aimed over the seat crosses the
clip's length L diagonally: L / 2 tan(alpha) to either side at its ends
(2 mm at 7.5 deg over a 30 mm clip), beyond the jaws' axes (2.6 mm off the
centre line for a 2.5 mm cable) at one end. Pressed down, it then bears on
the outside of one jaw at that end and on the inside at the other, which
holds the jaw shut: random board 2071274635's F1 (7.5 deg) rested on the
jaws for 3.5 s at 9 N and slid off beside the clip.

A clipped cable is kinked where it enters the clip and runs along the slot
inside it. So once the cable rests on the jaws (the force's line stops
dropping there), the gripper turns about the clip's exit by alpha onto the
slot's axis at most at ``SWING_RATE``, in step with the bend past the touch:
the whole turn once bent by ``SWING_BEND`` or ``BEND_PER_TURN`` times alpha.
The groove between the jaws holds the entry end against the kink's pull,
f sin(alpha), with a hold that grows with the press; the exit end, resting
on a jaw's crest, is drawn in before the bend slides it off outwards. On
board 2071274635's F1 the jaws then opened 1.8 mm and the cable snapped in.

The entry end's hold comes from the far side's slope into the clip: on a
board whose fixtures stand level with the clip it is a few percent of the
tension, and the groove holds kinks of about 10 deg (random board
1652323633's F3, 19 deg across, slid off the jaws even so).
"""

from __future__ import annotations

import math
from collections import deque

import numpy as np
from numpy.typing import NDArray

FloatArray = NDArray[np.float64]

#: The cable rests on the jaws when the force's line over the clip is lower than
#: this [m] above the jaws' top and has stopped dropping ...
TOUCH_ABOVE = 0.004
#: ... by more than this [m] over ``STALL_TIME`` while the gripper pivots down.
STALL_DROP = 0.0005
#: Time [s] over which the line's drop is judged.
STALL_TIME = 0.3
#: Least bend [rad] past the touch by which the whole turn is made.
SWING_BEND = math.radians(10.0)
#: Bend past the touch per radian of turn by which the whole turn is made (the
#: groove holds a kink whose pull is within about 0.8 of the press).
BEND_PER_TURN = 1.5
#: Rate [rad/s] of the turn about the clip's exit.
SWING_RATE = 0.15
#: Turns smaller than this [rad] are not made (the jaws take the cable).
LEAST_TURN = math.radians(1.5)


def turn_onto(out: FloatArray, slot: FloatArray) -> float:
    """The signed turn [rad] about world z from ``out`` onto the slot's axis.

    Args:
        out: Horizontal unit direction from the clip to the gripper.  # (3,)
        slot: Unit direction of the slot (either sign).  # (3,)

    Returns:
        The angle from ``out`` to the slot direction that points the same
        way as ``out``, in (-pi/2, pi/2].
    """
    u = slot * math.copysign(1.0, float(slot @ out))
    return math.atan2(float(out[0] * u[1] - out[1] * u[0]), float(out @ u))


def turned(out: FloatArray, angle: float) -> FloatArray:
    """``out`` turned by ``angle`` [rad] about world z."""
    cs, sn = math.cos(angle), math.sin(angle)
    return np.array([cs * out[0] - sn * out[1], sn * out[0] + cs * out[1], 0.0])


class SlotSwing:
    """When and how far to turn the gripper about a clip's exit onto its slot.

    Args:
        turn: The turn [rad] to make (:func:`turn_onto`).
        jaw_top: Height [m] above the seat of the jaws' top.
    """

    def __init__(self, turn: float, jaw_top: float) -> None:
        self.left = turn if abs(turn) >= LEAST_TURN else 0.0
        self.total = self.left
        self.jaw_top = jaw_top
        self.touch: float | None = None  # pivot angle [rad] at which the cable met the jaws
        self._heights: deque[tuple[float, float, float]] = deque()  # (time, height, angle)

    @property
    def progress(self) -> float:
        """The share of the turn made, 0 to 1 (0 where there is none to make)."""
        return 0.0 if self.total == 0.0 else (self.total - self.left) / self.total

    @property
    def bend(self) -> float:
        """Bend [rad] past the touch by which the whole turn is made."""
        return max(SWING_BEND, BEND_PER_TURN * abs(self.total))

    def step(self, time: float, height: float | None, angle: float, period: float) -> float:
        """The turn [rad] to make in this control period (0: pivot on).

        Args:
            time: Now [s].
            height: The force's line over the clip [m] above its seat (None
                while unknown).
            angle: The pivot angle [rad] now.
            period: The control period [s].
        """
        if self.left == 0.0:
            return 0.0
        if self.touch is None:
            self._watch(time, height, angle)
            return 0.0
        # the turn grows with the bend past the touch: the groove's hold on
        # the entry end grows with the press, and the exit end, resting on a
        # jaw's crest across the slot, is drawn in before it slides off it
        # outwards (random board 1652323633's F3, 19 deg across: turned only
        # once bent by 28 deg, the cable had slid off the jaws by then)
        share = min(max((angle - self.touch) / self.bend, 0.0), 1.0)
        wanted = self.total * share - (self.total - self.left)
        if wanted * self.total <= 0.0:
            return 0.0
        step = math.copysign(min(abs(wanted), SWING_RATE * period), self.total)
        self.left -= step
        if abs(self.left) < 1e-9:
            self.left = 0.0
        return step

    def _watch(self, time: float, height: float | None, angle: float) -> None:
        """Record the touch: the line low over the jaws and no longer dropping."""
        if height is None:
            return
        self._heights.append((time, height, angle))
        while len(self._heights) > 1 and time - self._heights[1][0] >= STALL_TIME:
            self._heights.popleft()
        t0, h0, a0 = self._heights[0]
        if (
            height <= self.jaw_top + TOUCH_ABOVE
            and time - t0 >= STALL_TIME
            and angle > a0
            and h0 - height < STALL_DROP
        ):
            self.touch = angle
