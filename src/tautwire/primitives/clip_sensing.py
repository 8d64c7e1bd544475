"""Feeling a clip from the force: where the taut cable crosses a clip, and the snap.

A taut cable pressed onto a clip bends over it, so the measured force at the
gripper points at the bend: the line from the gripper along the tension
direction crosses the clip's vertical at the height where the cable lies
there. Before the snap that is on the jaws, a few millimetres above the
seat; once the cable snaps in, it drops to the seat. This height, low-passed,
is the clipping primitives' force signature of the snap, and (after lifting
the gripper again) the proof that the cable stayed in.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from tautwire.primitives.low_pass import LowPass
from tautwire.primitives.outcome import Outcome

FloatArray = NDArray[np.float64]

#: Height [m] above the seat of the jaws' top: where a cable pressed over a
#: clip bends, the pivot of a held one.
JAW_TOP = 0.008
#: The cable counts as seated within this height [m] above the seat ...
SEATED = 0.004
#: ... no further than this [m] below it (a line that passes lower ran beside
#: the clip, down past its walls, not through its channel) ...
SEATED_BELOW = 0.004
#: ... and with its line passing the slot's exit within this distance [m]
#: across it (the channel's half width, about the cable's radius, plus the
#: line's noise: a cable beside the channel bends past the clip, not at it).
SIDEWAYS = 0.005


def height_at_clip(p_gripper: FloatArray, direction: FloatArray, seat: FloatArray) -> float | None:
    """Height [m] at which the tension line passes the clip's vertical axis.

    Args:
        p_gripper: Gripper position [m].  # (3,)
        direction: Unit tension direction from the gripper (towards what the
            cable bears on).  # (3,)
        seat: The clip's seat [m].  # (3,)

    Returns:
        The height of the line's point nearest the seat's vertical, or None
        when the line points away from the clip or is nearly vertical.
    """
    dx, dy = float(direction[0]), float(direction[1])
    n2 = dx * dx + dy * dy
    if n2 < 1e-6:
        return None
    lam = (float(seat[0] - p_gripper[0]) * dx + float(seat[1] - p_gripper[1]) * dy) / n2
    if lam <= 0.0:
        return None
    return float(p_gripper[2] + lam * float(direction[2]))


def miss_at_clip(p_gripper: FloatArray, direction: FloatArray, point: FloatArray) -> float | None:
    """Horizontal distance [m] by which the tension line misses ``point``'s vertical.

    Args:
        p_gripper: Gripper position [m].  # (3,)
        direction: Unit tension direction from the gripper.  # (3,)
        point: The point [m] (a clip's exit).  # (3,)

    Returns:
        The distance, or None where :func:`height_at_clip` has no height.
    """
    dx, dy = float(direction[0]), float(direction[1])
    n2 = dx * dx + dy * dy
    if n2 < 1e-6:
        return None
    rx, ry = float(point[0] - p_gripper[0]), float(point[1] - p_gripper[1])
    if rx * dx + ry * dy <= 0.0:
        return None
    return abs(rx * dy - ry * dx) / math.sqrt(n2)


#: Steepest rise [rad] of the cable from a clip's entry to the far contact
#: for one arm to clip it. The arm's bend presses the slot's exit end in;
#: the entry end is pressed only by the cable's kink there, f (s_in -
#: sin(rise)), s_in the slope the cable can take inside the jaws, from
#: their axes down to the seat within its shortest bend (for the simulated
#: cable one 20 mm segment: 4.3 mm / 20 mm, 12 deg). Steeper, the far side
#: holds the entry end up in the jaws' throat, where the force's line reads
#: as seated: Table I F (seed 0, 100 trials at dffa5c6) had all 13 of its
#: false successes at rises of 15-20 deg from the entry, none below 15 deg.
MAX_FAR_RISE = math.radians(13.0)


def far_rise(contact: FloatArray, seat: FloatArray, slot: FloatArray, half_length: float) -> float:
    """Rise [rad] of the cable from the clip's entry (its slot end towards ``contact``) to it.

    Args:
        contact: Where the cable leaves the far contact [m].  # (3,)
        seat: The clip's seat [m].  # (3,)
        slot: Unit direction of the slot.  # (3,)
        half_length: Half the clip's length along the slot [m].

    Returns:
        The angle above the horizontal (negative when the contact is lower).
    """
    c = np.asarray(contact, dtype=float)
    q = np.asarray(seat, dtype=float)
    u = np.asarray(slot, dtype=float)
    side = 1.0 if float((c - q) @ u) >= 0.0 else -1.0
    far = c - (q + side * half_length * u)
    return math.atan2(float(far[2]), math.hypot(float(far[0]), float(far[1])))


def push_tension(push_force: float, tension: float | None, force_limit: float) -> float:
    """Tension [N] to keep while pushing into a clip that needs ``push_force`` [N].

    Three times the push force (so that the bend needed, asin(P / f), stays
    near 20 deg and the gripper need not go far below the clip), at least the
    tension already set, at most 60 % of the force limit.
    """
    wanted = max(3.0 * push_force, tension or 0.0)
    return float(min(wanted, 0.6 * force_limit))


#: Press [N] planned per newton of the clip's push force (friction, sag and
#: the estimates' errors eat into the ideal press).
PRESS_MARGIN = 1.3


@dataclass(frozen=True)
class PivotPress:
    """The press one arm can make on a clip by pivoting the cable about it.

    The cable runs taut from a fixed contact over the clip to the gripper.
    Pivoting the gripper down about the clip's exit bends the cable there;
    the vertical press on the clip is f (sin a_near - sin a_far), a_near the
    cable's slope from the exit down to the gripper, a_far its slope from
    the contact down to the clip (positive when the contact is higher, which
    takes press away). Under force control the gripper's distance from the
    exit is not free: the span stretches by 1 / k per newton, so

        r(f) = r_0 + (f - f_0) / k,   sin a_near <= min(drop / r(f), sin a_max).

    A soft cable pulled harder moves the gripper out and flattens the bend
    that the height above the table allows; a stiff one does not.

    Attributes:
        radius: r_0 [m], the gripper's distance from the clip's exit now.
        tension: f_0 [N], the tension now.
        stiffness: k [N/m] of the span from the contact to the gripper.
        drop: Largest height [m] the gripper may go below the exit.
        sin_far: sin a_far (the contact's side).
        sin_max: sin a_max, the steepest slope allowed on the gripper's side.
    """

    radius: float
    tension: float
    stiffness: float
    drop: float
    sin_far: float
    sin_max: float

    def press(self, tension: float) -> float:
        """The largest vertical press [N] on the clip with the cable at ``tension`` [N]."""
        r = max(self.radius + (tension - self.tension) / self.stiffness, 1e-3)
        sin_near = min(max(self.drop, 0.0) / r, self.sin_max)
        return float(tension * (sin_near - self.sin_far))

    def tension_for(self, push_force: float, preferred: float, highest: float) -> float:
        """The tension [N] to push a clip of ``push_force`` [N] in with.

        ``preferred`` if that gives ``PRESS_MARGIN`` times the push force;
        otherwise the tension closest to it that does, between the tension
        now and ``highest``; if none does, the one that presses hardest.
        """
        wanted = PRESS_MARGIN * push_force
        if self.press(preferred) >= wanted:
            return preferred
        grid = np.append(np.linspace(min(self.tension, highest), highest, 60), preferred)
        press = np.array([self.press(float(f)) for f in grid])
        enough = grid[press >= wanted]
        if enough.size:
            return float(enough[np.argmin(np.abs(enough - preferred))])
        return float(grid[int(np.argmax(press))])


class ClipHeight:
    """Low-passed height of the cable at a clip, and how far beside it, from the measured force.

    The cable pulled down towards the gripper bends where it leaves the
    clip, at the end of the slot on the gripper's side: the height is taken
    there (at the seat's centre the line would read high by the slope times
    half the clip's length). The cable is seated when the line passes that
    exit at the seat's height, between :data:`SEATED_BELOW` under it and
    :data:`SEATED` over it, and within :data:`SIDEWAYS` of it across: a
    cable pushed down beside the clip reads low, or beside, or both.

    Args:
        seat: The clip's seat [m].  # (3,)
        slot: Unit direction of the slot.  # (3,)
        half_length: Half the clip's length along the slot [m].
    """

    def __init__(self, seat: FloatArray, slot: FloatArray, half_length: float) -> None:
        self.seat = np.asarray(seat, dtype=float)
        self.slot = np.asarray(slot, dtype=float)
        self.half_length = float(half_length)
        self._height: LowPass[float] = LowPass()
        self._miss: LowPass[float] = LowPass()

    @property
    def height(self) -> float | None:
        """The low-passed height [m] of the cable above the seat (None before a sample)."""
        return self._height.value

    @property
    def miss(self) -> float | None:
        """The low-passed distance [m] by which the line misses the slot's exit (None before)."""
        return self._miss.value

    def update(
        self, time: float, p_gripper: FloatArray, direction: FloatArray, taut: bool
    ) -> float | None:
        """Add the sample of ``time`` [s]; return the low-passed height [m] above the seat."""
        if not taut:
            return self.height
        side = 1.0 if float((p_gripper - self.seat) @ self.slot) >= 0.0 else -1.0
        exit_point = self.seat + side * self.half_length * self.slot
        z = height_at_clip(p_gripper, direction, exit_point)
        miss = miss_at_clip(p_gripper, direction, exit_point)
        if z is None or miss is None or not (math.isfinite(z) and math.isfinite(miss)):
            return self.height
        self._miss.update(time, miss)
        return self._height.update(time, z - float(self.seat[2]))

    def verdict(self, clip: str) -> Outcome:
        """After lifting: success if the cable is still seated in ``clip``, else ``not_clipped``."""
        mm = 1e3 * (self.height or 0.0)
        beside = 1e3 * (self.miss or 0.0)
        where = f"{mm:.1f} mm above its seat, {beside:.1f} mm beside its slot"
        if self.seated:
            return Outcome.success(f"clipped into {clip} (cable {where})")
        return Outcome.failure("not_clipped", f"the cable is not in {clip} when lifted ({where})")

    @property
    def seated(self) -> bool:
        """Whether the cable lies at the seat: at its height and in line with its slot."""
        return (
            self.height is not None
            and -SEATED_BELOW <= self.height <= SEATED
            and self.miss is not None
            and self.miss <= SIDEWAYS
        )
