"""How far the cable truly turned in a rotation (primitive I), from the pull alone.

I counts its turn from the gripper's path about the model's contact; that
count is only as right as the contact. Circling a far anchor while the
cable wraps a near peg the model has not accepted yet, the count reads
the gripper's angle about the anchor, not the span's turn about the peg
(random board 483199372: I counted 20 deg about A1 while the cable, caught
on F1, truly turned 39 deg). A taut cable pulls along its span, so the
pull's direction before the turn and after it tells the span's turn with
no model at all: at the start the mean of the first taut samples (the
gripper has hardly moved yet), at the end the cable's direction the bias
check measures holding still at two tensions, which no sensor bias tilts
(:mod:`~tautwire.primitives.bias_check`). The pull gives the turn modulo
a full turn; the count says which winding.
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import ArrayLike, NDArray

from tautwire.errors import InvalidArgumentError

FloatArray = NDArray[np.float64]

#: Largest difference [rad] between the pull's turn and the angle asked
#: for I to succeed. The truth's tolerance is 6 deg, and the pull reads the
#: cable where it leaves the fingers, not the straight span's chord from the
#: peg: on random board 144771393 (seed 29) they parted by 2-3 deg (at the
#: start the span entered the fingers 32 mm behind the tool centre point,
#: 4.8 mm aside), and with 4 deg here the pull's 36 deg for 32 asked passed
#: while the span truly turned 38 (a false success). At 3 deg the gripper
#: takes that miss up (the pull then read 32 deg, the span 35); a gap of
#: more than 3 deg would still pass falsely.
TURN_TOLERANCE = math.radians(3.0)
#: Taut samples averaged for the start direction.
START_SAMPLES = 5
#: Least pull [N] normal to the axis for a start sample to count (at the
#: end, the least share of the unit direction).
MIN_PULL = 0.2


def axis_angle(a: ArrayLike, b: ArrayLike, axis: ArrayLike) -> float:
    """The signed angle [rad] from ``a`` to ``b`` about the unit ``axis``, in (-pi, pi].

    Both vectors are projected onto the plane normal to ``axis``.
    """
    n = np.asarray(axis, dtype=float).reshape(3)
    u = np.asarray(a, dtype=float).reshape(3)
    v = np.asarray(b, dtype=float).reshape(3)
    u = u - n * float(n @ u)
    v = v - n * float(n @ v)
    return math.atan2(float(n @ np.cross(u, v)), float(u @ v))


class TurnCheck:
    """The span's turn in a rotation, read from the pull's direction.

    Args:
        axis: The rotation's unit axis (world frame).  # (3,)
    """

    def __init__(self, axis: ArrayLike) -> None:
        a = np.asarray(axis, dtype=float).reshape(3)
        size = float(np.linalg.norm(a))
        if not math.isfinite(size) or size < 1e-9:
            raise InvalidArgumentError(f"axis must be a non-zero 3-vector, got {axis!r}")
        self.axis: FloatArray = a / size
        self._sum = np.zeros(3)
        self._count = 0

    def _normal(self, force: ArrayLike) -> FloatArray | None:
        f = np.asarray(force, dtype=float).reshape(3)
        if not np.all(np.isfinite(f)):
            return None
        normal: FloatArray = f - self.axis * float(self.axis @ f)
        return normal if float(np.linalg.norm(normal)) >= MIN_PULL else None

    @property
    def started(self) -> bool:
        """Whether the start direction has its samples."""
        return self._count >= START_SAMPLES

    def add_start(self, force: ArrayLike) -> None:
        """Add a taut pull [N] (world frame) to the start direction, until it has enough."""
        if self.started:
            return
        normal = self._normal(force)
        if normal is not None:
            self._sum += normal / float(np.linalg.norm(normal))
            self._count += 1

    def turned(self, end: ArrayLike, counted: float) -> float | None:
        """The span's turn [rad] from the start to the pull ``end``, on the winding of ``counted``.

        Args:
            end: The pull's direction (any length) at the end, world frame.  # (3,)
            counted: The turn [rad] the gripper's path counted: of the
                turns the pull allows (one every full turn), the nearest.

        Returns:
            The turn, or None without a start or with no pull normal to the axis.
        """
        e = np.asarray(end, dtype=float).reshape(3)
        size = float(np.linalg.norm(e))
        if not self.started or not math.isfinite(size) or size <= 0.0:
            return None
        normal = self._normal(e * (1.0 / size))  # a unit pull: mostly normal to the axis
        if normal is None:
            return None
        wrapped = axis_angle(self._sum, normal, self.axis)
        windings = round((counted - wrapped) / (2.0 * math.pi))
        return wrapped + 2.0 * math.pi * windings
