"""Both grippers' tool axes laid along the cable between them (coordinated control).

When both grippers hold the cable (A, B), the taut cable runs straight
between their tool centre points. Each gripper holds it as well with +x
as with -x along that line, and a gripper may start at any yaw: its cable
then leaves the fingers bent round a fingertip, which rubs the pad (the
sensed tension reads low: D read 2.9 N for a true 3.5 N) and makes the force's
direction jump; a cable sliding through bent fingers does not see the
fingers' 2 mu F_grip. So before the force is relied on, each gripper turns
the tool axis, +x or -x, that is nearer the line onto it, by the shortest
arc: never more than a quarter turn about z from a yawed start (a half
turn would wrap the cable round the fingertip instead).

Coordinated control uses the relative orientation Q_rel = Q_right^-1
Q_left, which is ill-defined near a half turn (the Slerp midpoint Q_abs
flips). As in C (:mod:`tautwire.primitives.parallel_clipping`), a gripper
whose x-axis points from the right gripper towards the left is controlled
through its tool frame turned half about its own z-axis: both controlled
frames then have x from left to right, within a quarter of the line, and
their relative orientation is the difference of two such turns, under a
half turn. The world-frame twist of a frame turned by a constant offset is
the gripper's own twist, so the command applies unchanged.
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import NDArray

from tautwire.control import CoordinatedPose, DualPose, Pose, coordinated_pose
from tautwire.model.quaternion import multiply, rotate, turn_x_onto
from tautwire.primitives.tool_axis import EXIT_SCALE
from tautwire.robot import Observation

FloatArray = NDArray[np.float64]

#: Half a turn about the tool z-axis [w, x, y, z]: the tool frame with x reversed.
HALF_TURN_Z = np.array([0.0, 0.0, 0.0, 1.0])
#: Largest angle [rad] between a controlled tool axis and the line that counts as aligned.
ALIGNED = math.radians(10.0)
#: How long [s] grippers that had to turn must stay aligned before the force is relied on.
ALIGNED_TIME = 0.2


def _x_axis(q: FloatArray) -> FloatArray:
    return rotate(q, [1.0, 0.0, 0.0])


class PairAlignment:
    """The pair's controlled tool frames and their set point along the line between them.

    Decided once, from the observation at the start of a primitive: the
    line l from the left to the right tool centre point, and for each
    gripper whether its frame is turned half about z (its x-axis points
    against l: for the left gripper, against l itself; for the right one,
    towards the point ``EXIT_SCALE`` from the left tool centre point where
    the cable leaves the left fingers, which decides a grasp across l). The
    set point (:attr:`desired`) holds the start's absolute position and the
    direction of p_rel; each controlled frame is turned by the shortest arc
    that takes its x-axis onto l.

    Args:
        obs: The observation at the start.

    Attributes:
        line: Unit direction [-] from the left to the right tool centre point
            at the start.  # (3,)
        flip: For (left, right): whether that gripper's frame is turned half
            about z.
        desired: The coordinated set point of the controlled frames.
    """

    def __init__(self, obs: Observation) -> None:
        line = obs.right.position - obs.left.position
        self.line: FloatArray = line / max(float(np.linalg.norm(line)), 1e-12)
        # the cable leaves the left fingers through the fingertip towards the
        # right gripper, and runs straight from there into the right fingers
        # through the fingertip that faces it (decides a grasp across the line)
        x_left, x_right = _x_axis(obs.left.orientation), _x_axis(obs.right.orientation)
        flip_left = float(x_left @ self.line) < 0.0
        exit_left = obs.left.position + (-EXIT_SCALE if flip_left else EXIT_SCALE) * x_left
        self.flip: tuple[bool, bool] = (
            flip_left,
            float(x_right @ (exit_left - obs.right.position)) > 0.0,
        )
        frames = self.tool_frames(obs)
        target = DualPose(
            Pose(frames.left.position, turn_x_onto(frames.left.orientation, self.line)),
            Pose(frames.right.position, turn_x_onto(frames.right.orientation, self.line)),
        )
        self.desired: CoordinatedPose = coordinated_pose(target)
        self._aligned_since: float | None = None
        self._first: float | None = None

    def tool_frames(self, obs: Observation) -> DualPose:
        """Both grippers' poses, a flipped one's frame turned half about its z-axis."""
        left = Pose(obs.left.position, obs.left.orientation)
        right = Pose(obs.right.position, obs.right.orientation)
        if self.flip[0]:
            left = Pose(left.position, multiply(left.orientation, HALF_TURN_Z))
        if self.flip[1]:
            right = Pose(right.position, multiply(right.orientation, HALF_TURN_Z))
        return DualPose(left, right)

    def angle(self, obs: Observation) -> float:
        """The larger angle [rad] between a controlled frame's x-axis and the line now."""
        line = obs.right.position - obs.left.position
        line = line / max(float(np.linalg.norm(line)), 1e-12)
        frames = self.tool_frames(obs)
        worst = 0.0
        for frame in (frames.left, frames.right):
            c = float(_x_axis(frame.orientation) @ line)
            worst = max(worst, math.acos(min(max(c, -1.0), 1.0)))
        return worst

    def settled(self, obs: Observation) -> bool:
        """Whether both axes lie along the line: from the first sample on, or for ALIGNED_TIME.

        Call once per control period.
        """
        if self._first is None:
            self._first = obs.time
        if self.angle(obs) > ALIGNED:
            self._aligned_since = None
            return False
        if self._aligned_since is None:
            self._aligned_since = obs.time
        return self._aligned_since == self._first or obs.time - self._aligned_since >= ALIGNED_TIME
