"""Feeling that a clip holds the cable: lift the gripper a little and see what the pull turns about.

The clipping primitives first judge the snap from the line of the measured
force (:class:`~tautwire.primitives.clip_sensing.ClipHeight`). That line
passes through where the cable leaves the fingers, which the wrench's line
of action places only to within several millimetres (a bent cable in the
pads adds a couple): on a random board F read a cable 7.5 mm beside a slot
as 1.7 mm beside it. The tug needs no such point. A clipped cable is held
down at the clip, so lifting the gripper by an angle a about the clip's
exit turns the pull by a; a cable that only rests on or beside the clip
lifts off it and turns about its far contact instead, by a r / R (r the
gripper's distance from the clip, R from the far contact). Only the change
of the force's direction between two poses enters, so a constant offset of
the cable in the fingers, the span's weight and a sensor bias cancel.
Measured on that board (seed 1695658280, clip F3, the gripper 104 mm from
it): lifted by 4 deg, the pull turned 1.4 deg, against 5.1 deg about the
clip and 1.8 deg about the far peg.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from tautwire.primitives.low_pass import LowPass

FloatArray = NDArray[np.float64]

#: World vertical, the default plane of a tug.
UP = np.array([0.0, 0.0, 1.0])

#: Upward pull on a clipped cable the tug may make, as a share of the clip's
#: push force. A cable caught in the jaws' throat, at their narrowest gap,
#: comes out at a small fraction of it: at 0.35 (0.4-0.6 N, up to 10 deg)
#: Table I F (seed 0, trials 0-39) lost 6 of 20 clips that the simulator
#: had confirmed (5 pulled out of the throat, 1 read out by the line), and
#: one cable crept out after the tug had read it held.
TUG_SHARE = 0.1
#: Least and largest angle [rad] by which the tug lifts the gripper about the clip.
MIN_TUG = math.radians(3.0)
MAX_TUG = math.radians(4.0)
#: Time constant [s] of the low-pass on the pull's direction.
PULL_TIME = 0.1
#: Least difference [rad] between the turns about the clip and about the far
#: contact for the tug to tell them apart (about ten times the low-passed
#: direction's noise at 0.05 N on 3 N).
DISTINCT = math.radians(0.8)
#: Share of the way from the turn about the far contact to the turn about the
#: clip that the pull must turn for the clip to hold it. A clipped cable turns
#: less than about a rigid exit (the jaws give as it lifts in their throat); a
#: loose one no more than about the far contact (it bends and drags). Measured:
#: the shipped harness's C3, in the jaws, 3.4 deg against 5.0 / 2.0 deg (at half
#: the way it read loose); random board 1695658280's F3, the cable 7.5 mm beside
#: the slot, 1.4 deg against 5.1 / 1.8 deg.
HOLD_SHARE = 1.0 / 3.0
#: Time [s] the gripper rests lifted before the pull is read.
TUG_SETTLE = 0.4
#: How near its lifted set point the gripper must be to rest there, as a share
#: of the lift (at least ``TUG_REACHED_MIN`` [m]): the hypotheses are figured
#: from where it is, but a lift cut short parts them less. At 3 mm, random
#: boards 1742396983 and 247036674 (seed 11) read D's 3 deg tugs 5 mm long
#: at 1.8-2.4 deg about the clip.
TUG_REACHED_SHARE = 0.1
TUG_REACHED_MIN = 3e-4


def tug_angle(push_force: float, tension: float) -> float:
    """The angle [rad] to lift the gripper about the clip's exit.

    Lifted by a, a held cable pulls up on the clip with about T sin(a):
    at most ``TUG_SHARE`` of the push force that holds it in, within
    [``MIN_TUG``, ``MAX_TUG``].

    Args:
        push_force: The clip's push force [N].
        tension: The tension [N] kept during the tug.
    """
    s = TUG_SHARE * push_force / max(tension, 1e-6)
    return min(max(math.asin(min(s, 1.0)), MIN_TUG), MAX_TUG)


def lifted(
    position: FloatArray,
    pivot: FloatArray,
    out: FloatArray,
    angle: float,
    up: FloatArray = UP,
) -> FloatArray:
    """``position`` turned by ``angle`` [rad] from ``out`` towards ``up`` about ``pivot``.

    The axis through ``pivot`` is normal to both: with ``up`` vertical the
    point rises in the vertical plane of ``out``; with ``up`` horizontal it
    swings sideways. The distance from ``pivot`` is kept.

    Args:
        position: The point to turn [m].  # (3,)
        pivot: A point of the axis [m] (a clip's exit).  # (3,)
        out: Unit direction from the pivot towards ``position``, normal to ``up``.  # (3,)
        angle: Towards ``up`` [rad].
        up: Unit direction the point turns towards (default vertical).  # (3,)
    """
    o, n = np.asarray(out, dtype=float), np.asarray(up, dtype=float)
    w = np.asarray(position, dtype=float) - np.asarray(pivot, dtype=float)
    ahead, high = float(w @ o), float(w @ n)
    c, s = math.cos(angle), math.sin(angle)
    result: FloatArray = (
        np.asarray(pivot, dtype=float)
        + (w - ahead * o - high * n)
        + (c * ahead - s * high) * o
        + (s * ahead + c * high) * n
    )
    return result


def elevation(v: FloatArray, out: FloatArray, up: FloatArray = UP) -> float:
    """Angle [rad] of ``v`` towards ``up``, in the plane of ``out`` and ``up``.

    Args:
        v: A direction from the gripper towards the cable.  # (3,)
        out: Unit direction from the clip to the gripper.  # (3,)
        up: Unit direction normal to ``out`` (default vertical).  # (3,)
    """
    return math.atan2(float(np.asarray(v) @ up), -float(np.asarray(v) @ out))


@dataclass(frozen=True)
class TugReading:
    """How far the pull turned when the gripper was lifted, against the two hypotheses [rad].

    Attributes:
        turned: The measured turn of the pull (downwards positive).
        held: The turn if the clip holds the cable (about its exit).
        loose: The turn if it does not (about the far contact).
    """

    turned: float
    held: float
    loose: float
    how: str = "lifted"

    @property
    def distinct(self) -> bool:
        """Whether the two hypotheses differ by at least ``DISTINCT``."""
        return self.held - self.loose >= DISTINCT

    @property
    def holds(self) -> bool:
        """Whether the pull turned ``HOLD_SHARE`` of the way from ``loose`` to ``held`` or more."""
        return self.turned >= self.loose + HOLD_SHARE * (self.held - self.loose)

    def describe(self) -> str:
        """One line: the measured turn and the two expected ones, in degrees."""
        return (
            f"{self.how}, the pull turned {math.degrees(self.turned):.1f} deg (about the clip "
            f"{math.degrees(self.held):.1f} deg, about the far contact "
            f"{math.degrees(self.loose):.1f} deg)"
        )


class ClipTug:
    """The pull's direction at rest and lifted, and the reading of the two.

    Args:
        out: Unit horizontal direction from the clip to the gripper.  # (3,)
        up: Unit direction the gripper turns towards about the clip's exit:
            vertical (a lift, the default) or horizontal (a swing aside).  # (3,)
    """

    def __init__(self, out: FloatArray, up: FloatArray = UP) -> None:
        self.out = np.asarray(out, dtype=float)
        self.up = np.asarray(up, dtype=float)
        self._pull: LowPass[np.ndarray] = LowPass(PULL_TIME)
        self._rest: tuple[FloatArray, float] | None = None

    def update(self, time: float, force: FloatArray) -> None:
        """Add the force [N] the cable exerts on the gripper, measured at ``time`` [s]."""
        f = np.asarray(force, dtype=float)
        n = float(np.linalg.norm(f))
        if math.isfinite(n) and n > 1e-6:
            self._pull.update(time, f / n)

    def mark_rest(self, p_gripper: FloatArray) -> None:
        """Keep the gripper's position [m] and the pull's elevation now, at rest."""
        if self._pull.value is not None:
            self._rest = (
                np.array(p_gripper, dtype=float),
                elevation(self._pull.value, self.out, self.up),
            )

    def reading(self, p_gripper: FloatArray, exit_point: FloatArray, far: FloatArray) -> TugReading:
        """The turn of the pull from rest to now, with the gripper lifted to ``p_gripper`` [m].

        Args:
            p_gripper: The gripper's position now [m].  # (3,)
            exit_point: The clip's exit on the gripper's side [m].  # (3,)
            far: Where the cable leaves its far contact [m].  # (3,)

        Raises:
            RuntimeError: no rest pose was marked.
        """
        if self._rest is None or self._pull.value is None:
            raise RuntimeError("mark the rest pose before reading the tug")
        p0, e0 = self._rest
        p1 = np.asarray(p_gripper, dtype=float)

        def turn(pivot: FloatArray) -> float:
            return elevation(pivot - p0, self.out, self.up) - elevation(
                pivot - p1, self.out, self.up
            )

        turned = e0 - elevation(self._pull.value, self.out, self.up)
        how = "lifted" if abs(float(self.up[2])) > 0.5 else "swung aside"
        return TugReading(turned, turn(np.asarray(exit_point)), turn(np.asarray(far)), how)
