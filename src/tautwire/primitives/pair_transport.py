"""Carrying a cable held by both grippers to a new pose: turning and moving in step.

Two grippers that hold a cable between them, taut from a fixed point
behind the near one, carry it to a clip: their middle moves to over the
seat while the line between them turns onto the slot. Each gripper holds
the cable at one point, so the near gripper must stay within the cable it
holds past the fixed point behind it. The pose it ends in is planned that
way (``tasks/planner.py``), but the path there is not, when the middle
goes straight to its goal while the line turns only as fast as the tool
axes follow it: the line then lags, and the near gripper swings out
beyond its end pose. Random board 402445297's C into F6: the line turned
59 deg; the middle arrived with the line still 38 deg off, the near
gripper 11 mm beyond its end pose from the clip behind it, F5, and the
near span went taut, 3 -> 15.5 N in 0.2 s (true 16.4 N, over the limit).

So the middle's set point advances only as far as the turn has come (and
the turn's only as far as the middle has), each at most ``LEAD_SHARE`` of
the whole ahead of the other: the pair moves as one screw from the start
to the end pose, and the near gripper goes from its start to its end
without swinging beyond either.
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import NDArray

FloatArray = NDArray[np.float64]

#: Share of the whole motion by which the middle may lead the turn, or the turn the middle.
LEAD_SHARE = 0.15
#: Turns [rad] and moves [m] smaller than these count as made from the start.
LEAST_TURN = math.radians(1.0)
LEAST_MOVE = 0.002


def _heading(v: FloatArray) -> float:
    return math.atan2(float(v[1]), float(v[0]))


class PairTransport:
    """Set points that carry a pair from its start to an end pose in step.

    Args:
        centre: The grippers' middle at the start [m].  # (3,)
        line: The line between the grippers at the start (any length).  # (3,)
        goal: The middle's end point [m].  # (3,)
        direction: The line's end direction (horizontal turn only).  # (3,)
    """

    def __init__(
        self, centre: FloatArray, line: FloatArray, goal: FloatArray, direction: FloatArray
    ) -> None:
        self.start = np.asarray(centre, dtype=float).copy()
        self.goal = np.asarray(goal, dtype=float).copy()
        self.heading0 = _heading(np.asarray(line, dtype=float))
        end = _heading(np.asarray(direction, dtype=float))
        self.turn = math.remainder(end - self.heading0, math.tau)

    def moved(self, centre: FloatArray) -> float:
        """Share (0 to 1) of the middle's way made at ``centre``."""
        way = self.goal - self.start
        n2 = float(way @ way)
        if n2 < LEAST_MOVE**2:
            return 1.0
        share = float((np.asarray(centre, dtype=float) - self.start) @ way) / n2
        return min(max(share, 0.0), 1.0)

    def turned(self, line: FloatArray) -> float:
        """Share (0 to 1) of the turn made with the grippers' line along ``line``."""
        if abs(self.turn) < LEAST_TURN:
            return 1.0
        made = math.remainder(_heading(np.asarray(line, dtype=float)) - self.heading0, math.tau)
        return min(max(made / self.turn, 0.0), 1.0)

    def centre(self, line: FloatArray) -> FloatArray:
        """The middle's set point [m]: no further than the turn made allows."""
        share = min(1.0, self.turned(line) + LEAD_SHARE)
        out: FloatArray = self.start + share * (self.goal - self.start)
        return out

    def heading(self, centre: FloatArray) -> FloatArray:
        """The line's horizontal set direction: no further turned than the middle's way allows."""
        share = min(1.0, self.moved(centre) + LEAD_SHARE)
        angle = self.heading0 + share * self.turn
        return np.array([math.cos(angle), math.sin(angle), 0.0])
