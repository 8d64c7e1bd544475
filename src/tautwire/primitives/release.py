"""Release: open a gripper and let the cable go.

Not one of the paper's nine primitives (SCENARIO.md, "Moves between
primitives"): the end of a hand-over (H by the other gripper, then release)
and of a parallel clip whose second gripper is no longer needed.
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import NDArray

from tautwire.errors import InvalidArgumentError
from tautwire.estimation import update_by_constraints
from tautwire.model import PathGraph
from tautwire.primitives.arm_control import current_pose
from tautwire.primitives.context import PrimitiveContext
from tautwire.primitives.outcome import Outcome
from tautwire.primitives.primitive import Primitive
from tautwire.robot import Arm, Command, GripperCommand, Observation

FloatArray = NDArray[np.float64]

#: Turn [rad] round a peg below which a cable that no gripper holds may
#: leave it for its other side (a winding's friction keeps it).
HELD_WRAP = math.pi
#: The fingers count as open once they are this much [m] wider than when the release began.
OPENED_BY = 0.004
#: ... and have stayed so for this long [s].
OPEN_TIME = 0.3


def release_point(graph: PathGraph, arm: Arm, positions: dict[str, FloatArray]) -> bool:
    """Turn ``arm``'s gripper point of ``graph`` into a free point (the model's edit of a release).

    The cable keeps what its fixtures and other grippers hold: the point
    stays where it is along the cable, unconstrained, and its edges carry no
    tension until a primitive measures one. The graph is mapped onto the
    remaining constraints again (``positions``: the grippers' tool centre
    points [m] by arm), so that a released end hangs. Where no gripper
    holds the cable any more, nothing keeps it up on the pegs it bears on
    (contact points, held by the tension alone): each may slide down its
    peg to the board, and its height's std becomes at least its height
    above the board (random board 2082005138: W1, wound round F2 at 94 mm
    and released after its last clip, slid down F2 to 27 mm while the
    model held F2 at a trusted 4.6 mm std). Nor does anything keep it on
    the side of a peg it turns round by less than ``HELD_WRAP``: the cable
    straightens through its clips (which hold it across, not along), and
    may spring off to the other side, so the model no longer says which
    side (its ``wrap`` becomes 0; random board 2124379844: W1, turned 32 deg
    round peg F3 and released after its last clip, ended on F3's other
    side while the model still had it round F3's right).

    Returns:
        Whether the graph had a point held by ``arm``.
    """
    i = graph.index_of("gripper", arm)
    if i is None:
        return False
    point = graph.points[i]
    point.kind, point.label, point.covariance = "free", "released", None
    for k in (i - 1, i):
        if 0 <= k < len(graph.edges):
            graph.edges[k].tension = 0.0
    constraints: dict[int, FloatArray] = {}
    for j, pt in enumerate(graph.points):
        if pt.kind == "gripper":
            constraints[j] = positions.get(pt.label, pt.position)
        elif pt.kind in ("fixed", "contact"):
            constraints[j] = pt.position
    if constraints:
        update_by_constraints(graph, constraints)
    if graph.index_of("gripper") is None:
        for pt in graph.points:
            if pt.kind != "contact":
                continue
            height = max(float(pt.position[2]), 0.0)  # above the board, the plane z = 0
            cov = np.zeros((3, 3)) if pt.covariance is None else pt.covariance.copy()
            cov[2, 2] = max(float(cov[2, 2]), height * height)
            pt.covariance = cov
            if pt.wrap is None or abs(pt.wrap) < HELD_WRAP:
                pt.wrap = 0.0  # which side of the peg it ends on is no longer known
    return True


class Release(Primitive):
    """Open the gripper on ``arm`` and let the cable go.

    Both grippers hold their poses while the fingers open (the other
    gripper's cable keeps the tension its fixtures and grasp leave).

    Preconditions: none (releasing an empty gripper only opens it).
    Model edits: the gripper's point of the cable's path graph becomes a
    free point (:func:`release_point`); the cable keeps what its fixtures
    and the other gripper still hold (with no gripper left on it, its pegs'
    heights become unknown down to the board). The context of a gripper that
    released its cable no longer senses it.

    Success: the fingers opened by :data:`OPENED_BY` and stayed open for
    :data:`OPEN_TIME` (a gripper that held no cable: the open command for
    that long). Failure: ``timeout`` if they do not open.

    Args:
        arm: The gripper that lets go.
        timeout: Longest run time [s].
    """

    name = "release"
    letter = ""

    def __init__(self, arm: Arm, timeout: float = 3.0) -> None:
        super().__init__(timeout)
        if arm not in ("left", "right"):
            raise InvalidArgumentError(f"arm must be 'left' or 'right', got {arm!r}")
        self.arm: Arm = arm

    def on_start(self, obs: Observation, ctx: PrimitiveContext) -> None:
        """Remember the poses to hold and how far the fingers are apart."""
        self._hold = current_pose(obs)
        self._opening = obs.gripper(self.arm).opening
        self._open_since: float | None = None
        self._empty = ctx.graph.index_of("gripper", self.arm) is None
        est = ctx.estimator
        # the other gripper's estimate keeps running; this one's stops
        self._update = est.arm != self.arm and ctx.graph.index_of("gripper", est.arm) is not None
        if self._update:
            est.learn_elasticity = False
            est.rotation = None

    def on_step(self, obs: Observation, ctx: PrimitiveContext) -> Command:
        """Open the fingers, hold still, then edit the model."""
        if self._update:
            ctx.estimator.update(obs)
        twist = ctx.controller(current_pose(obs), self._hold)
        opening = obs.gripper(self.arm).opening
        if self._empty or opening >= self._opening + OPENED_BY:
            if self._open_since is None:
                self._open_since = obs.time
            elif obs.time - self._open_since >= OPEN_TIME:
                positions = {"left": obs.left.position, "right": obs.right.position}
                held = release_point(ctx.graph, self.arm, positions)
                what = "the cable" if held else "nothing (it held no cable)"
                self.outcome = Outcome.success(
                    f"the {self.arm} fingers opened to {1e3 * opening:.1f} mm and let go of {what}"
                )
        else:
            self._open_since = None
        fingers = GripperCommand("open")
        if self.arm == "left":
            return Command(twist, left=fingers)
        return Command(twist, right=fingers)
