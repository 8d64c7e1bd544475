"""Release: open a gripper and let the cable go.

Not one of the paper's nine primitives (SCENARIO.md, "Moves between
primitives"): the end of a hand-over (H by the other gripper, then release)
and of a parallel clip whose second gripper is no longer needed.
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import NDArray

from tautwire.control import Pose
from tautwire.errors import InvalidArgumentError
from tautwire.estimation import update_by_constraints
from tautwire.model import PathGraph
from tautwire.model.quaternion import rotate
from tautwire.primitives.arm_control import current_pose, with_pose
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
#: How far [m] the open gripper first moves into the bend the cable makes at it.
RETREAT_ASIDE = 0.012
#: How far [m] it then backs out along its approach axis (tool +z), clear of the
#: pads (half height 8 mm) and their lips over the cable.
RETREAT_BACK = 0.03
#: Smallest bend [rad] at the gripper for the move aside (straighter: straight back).
RETREAT_BEND = math.radians(20.0)
#: The retreat has ended within this distance [m] of its last way point.
RETREAT_TOLERANCE = 0.002


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
    the side of a peg it turns round by less than ``HELD_WRAP`` where no
    gripper pulls the cable round it any more (no gripper left, or only
    beyond a clip or an anchor: :func:`_pulled`): the cable straightens
    through its clips (which hold it across, not along), and may spring off
    to the other side, so the model no longer says which side (its ``wrap``
    becomes 0; random board 2124379844: W1, turned 32 deg round peg F3 and
    released after its last clip, ended on F3's other side while the model
    still had it round F3's right; random board 1045612557: W2's near
    gripper let go after C into F10, the far one holding W2 beyond F10, and
    W2 had left peg F9 (turned 50 deg) while the model still had it round
    F9's left).

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
    for j, pt in enumerate(graph.points):
        held = pt.wrap is not None and abs(pt.wrap) >= HELD_WRAP  # a winding's friction
        if pt.kind == "contact" and not held and not _pulled(graph, j):
            pt.wrap = 0.0  # which side of the peg it ends on is no longer known
    return True


def _pulled(graph: PathGraph, j: int) -> bool:
    """Whether a gripper holds the cable on either side of point ``j`` with no fixed point between.

    Only a gripper keeps a peg's cable taut: a clip holds the cable across,
    not along, so a gripper beyond one pulls it through the clip rather
    than round the peg, and an anchor ends it.
    """
    for step in (-1, 1):
        k = j + step
        while 0 <= k < len(graph.points):
            kind = graph.points[k].kind
            if kind == "gripper":
                return True
            if kind == "fixed":
                break
            k += step
    return False


def retreat_aside(
    graph: PathGraph, arm: Arm, position: FloatArray, orientation: FloatArray
) -> FloatArray:
    """Where [m] the open gripper on ``arm`` moves first to clear the cable it let go (world frame).

    A gripper that held a cable where the cable bends (the near gripper of
    a parallel clip: along the clip's slot on one side, towards the fixture
    before it on the other) has the cable hooked round the end of the pad
    on the bend's inner side once the fingers open, pressed against it by
    the cable's tension, and under the pads' lips. Backing straight out then
    carries the cable with it (random board 1695658280: the open left
    gripper round W2 after C into F4; H's rise for the next grasp dragged
    W2 up with it to 13.55 N, and a 30 mm lift right after the release
    lifted W2 out of F4). Moving first along the bisector of the model's two
    edges at the gripper, into the bend, takes that pad away from both of
    the cable's arms; the other pad, on the bend's outer side, closes in
    on the cable by less than the half opening. The move is in the tool's
    x-y plane (the plane the fingers open in).

    Args:
        graph: The cable's path graph, the gripper still holding it.
        arm: The gripper that lets go.
        position: Its tool centre point [m].  # (3,)
        orientation: Its orientation [w, x, y, z].  # (4,)

    Returns:
        The offset [m] (3,): zero where the gripper holds no point of
        ``graph``, an end of it, or a cable bent by less than
        :data:`RETREAT_BEND`.
    """
    i = graph.index_of("gripper", arm)
    if i is None or i == 0 or i == len(graph.points) - 1:
        return np.zeros(3)
    normal = rotate(orientation, [0.0, 0.0, 1.0])
    arms = []
    for k in (i - 1, i + 1):
        d = graph.points[k].position - position
        d = d - normal * float(normal @ d)  # in the plane the fingers open in
        n = float(np.linalg.norm(d))
        if n < 1e-6:
            return np.zeros(3)
        arms.append(d / n)
    bisector = arms[0] + arms[1]
    n = float(np.linalg.norm(bisector))
    if n < 2.0 * math.sin(0.5 * RETREAT_BEND):  # |u1 + u2| = 2 sin(bend / 2)
        return np.zeros(3)
    return RETREAT_ASIDE * bisector / n


class Release(Primitive):
    """Open the gripper on ``arm``, let the cable go and back the gripper off it.

    Both grippers hold their poses while the fingers open (the other
    gripper's cable keeps the tension its fixtures and grasp leave). Then
    the open gripper retreats from the cable it let go, the other still
    holding: first :data:`RETREAT_ASIDE` into the bend the model's cable
    makes at it (:func:`retreat_aside`; none where it runs straight), then
    :data:`RETREAT_BACK` back along its approach axis (tool +z), so that no
    later motion of it drags the cable by a pad or a lip.

    Preconditions: none (releasing an empty gripper only opens it, without
    the retreat).
    Model edits: the gripper's point of the cable's path graph becomes a
    free point (:func:`release_point`); the cable keeps what its fixtures
    and the other gripper still hold (with no gripper left on it, its pegs'
    heights become unknown down to the board). The context of a gripper that
    released its cable no longer senses it.

    Success: the fingers opened by :data:`OPENED_BY`, stayed open for
    :data:`OPEN_TIME` (a gripper that held no cable: the open command for
    that long), and the gripper ended its retreat within
    :data:`RETREAT_TOLERANCE`. Failure: ``timeout`` if they do not open
    (the model unchanged) or the retreat does not end.

    Args:
        arm: The gripper that lets go.
        timeout: Longest run time [s].
    """

    name = "release"
    letter = ""

    def __init__(self, arm: Arm, timeout: float = 5.0) -> None:
        super().__init__(timeout)
        if arm not in ("left", "right"):
            raise InvalidArgumentError(f"arm must be 'left' or 'right', got {arm!r}")
        self.arm: Arm = arm

    def on_start(self, obs: Observation, ctx: PrimitiveContext) -> None:
        """Remember the poses to hold and how far the fingers are apart."""
        self._hold = current_pose(obs)
        self._own_hold = self._hold.left if self.arm == "left" else self._hold.right
        self._opening = obs.gripper(self.arm).opening
        self._open_since: float | None = None
        self._empty = ctx.graph.index_of("gripper", self.arm) is None
        self._retreat: list[FloatArray] = []  # way points [m] once the cable is let go
        self._opened = ""
        est = ctx.estimator
        # the other gripper's estimate keeps running; this one's stops
        self._update = est.arm != self.arm and ctx.graph.index_of("gripper", est.arm) is not None
        if self._update:
            est.learn_elasticity = False
            est.rotation = None

    def on_step(self, obs: Observation, ctx: PrimitiveContext) -> Command:
        """Open the fingers, hold still, edit the model, then back off the cable."""
        if self._update:
            ctx.estimator.update(obs)
        me = obs.gripper(self.arm)
        fingers = GripperCommand("open")
        if self._retreat:
            if float(np.linalg.norm(self._retreat[0] - me.position)) <= RETREAT_TOLERANCE:
                if len(self._retreat) == 1:
                    self.outcome = Outcome.success(
                        f"{self._opened}; backed {1e3 * RETREAT_BACK:.0f} mm off it"
                    )
                else:
                    self._retreat.pop(0)
            target = Pose(self._retreat[0], self._own_hold.orientation)
            twist = ctx.controller(current_pose(obs), with_pose(self._hold, self.arm, target))
            return self._command(twist, fingers)
        twist = ctx.controller(current_pose(obs), self._hold)
        opening = me.opening
        if self._empty or opening >= self._opening + OPENED_BY:
            if self._open_since is None:
                self._open_since = obs.time
            elif obs.time - self._open_since >= OPEN_TIME:
                positions = {"left": obs.left.position, "right": obs.right.position}
                aside = retreat_aside(ctx.graph, self.arm, me.position, me.orientation)
                held = release_point(ctx.graph, self.arm, positions)
                what = "the cable" if held else "nothing (it held no cable)"
                self._opened = (
                    f"the {self.arm} fingers opened to {1e3 * opening:.1f} mm and let go of {what}"
                )
                if not held:
                    self.outcome = Outcome.success(self._opened)
                else:
                    start = self._own_hold.position
                    back = RETREAT_BACK * rotate(me.orientation, [0.0, 0.0, 1.0])
                    self._retreat = [start + aside, start + aside + back]
                    if not aside.any():
                        self._retreat.pop(0)
        else:
            self._open_since = None
        return self._command(twist, fingers)

    def _command(self, twist: FloatArray, fingers: GripperCommand) -> Command:
        """``twist`` (12,) with ``fingers`` for this primitive's gripper."""
        if self.arm == "left":
            return Command(twist, left=fingers)
        return Command(twist, right=fingers)
