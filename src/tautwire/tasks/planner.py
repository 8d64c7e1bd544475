"""The route planner: turns cables' target routes into the steps of a task.

A route (SCENARIO.md, "Target routes and the planner") lists, in order from
a cable's start anchor, the pegs it passes (on a side, with optional
windings) and the clips it is pushed into. The planner routes one cable
after the other with the gripper that holds it (which must carry a force
sensor), in the primitives' own terms:

- **tension**: D pulls the cable taut against its last fixed point;
- **peg**: ``move`` (taut) sweeps the cable onto the peg from the side the
  route asks for, in waypoints at most ``SWEEP_STEP`` apart about the last
  fixed point, after lifting the cable over the peg if it lies on the other
  side; I (``rotate_around_feature_point``) then winds the cable round it
  by the rest of the wrap towards the next entry plus the windings (left:
  counter-clockwise, positive about +z);
- **clip**: ``move`` onto the line from the last fixed point over the seat,
  G (align) and F (single-arm clipping) when the slot runs within
  ``SLOT_ANGLE`` of that line; otherwise the free gripper grasps the cable
  (H), both press it in (C) and the grasping gripper lets go (``release``);
- **slide out**: E, when the cable between the last fixed point and the
  gripper is too short for the next entry;
- **hand over**: H by the other gripper nearer the last fixed point, then
  ``release`` of the holding one, when the gripper holds the cable so far
  out that the next entry's motion leaves the reach or F could not press
  the clip in.

It checks every planned gripper point against the reach box, the height of
each peg and clip (a cable can be caught on the peg; F or C can press the
clip in: :class:`~tautwire.primitives.clip_sensing.PivotPress`), the slot's
direction, and the cable's length (the route along the fixtures plus what
each primitive needs beyond them must fit the cable). A route it cannot do
raises :class:`RouteError`, one line naming the cable, the route entry and
the reason.

The planner works on plain data (:class:`RouteProblem`); it does not look
at collisions with fixtures that are not on the route, nor between the two
grippers.
"""

from __future__ import annotations

import math
from collections.abc import Iterator, Mapping
from dataclasses import dataclass, field, replace
from typing import Literal

import numpy as np
from numpy.typing import NDArray

from tautwire.errors import TautwireError
from tautwire.estimation.round_contact import DESIGN_TOLERANCE, RADIUS_MARGIN
from tautwire.model.vector3 import nearest_on_segment
from tautwire.primitives.clip_sensing import (
    JAW_TOP,
    MAX_FAR_RISE,
    PRESS_MARGIN,
    PivotPress,
    far_rise,
    push_tension,
)
from tautwire.primitives.model_estimator import LINE_HEIGHT_TOLERANCE
from tautwire.primitives.move import PEG_ABOVE, PEG_CLEARANCE
from tautwire.primitives.parallel_clipping import ABOVE as PARALLEL_ABOVE
from tautwire.primitives.parallel_clipping import TABLE_CLEARANCE as PARALLEL_TABLE_CLEARANCE
from tautwire.primitives.single_arm_clipping import (
    ABOVE,
    MAX_ANGLE,
    MAX_SLOT_ANGLE,
    PRESS_EXTRA,
    TABLE_CLEARANCE,
)
from tautwire.robot import Arm
from tautwire.robot.workspace import Workspace

FloatArray = NDArray[np.float64]
Point = tuple[float, float, float]
Side = Literal["left", "right"]
ParamValue = bool | float | str | list[float]

#: F is planned only up to this angle [rad] between the slot and the cable,
#: where the other gripper is busy and C cannot take the clip: beyond it one
#: arm kinks the cable where it enters the clip and only the far side's
#: slope presses that end in (a level anchor-clip scene seated up to 15
#: deg and missed 17 and 20 deg; random boards missed at 13.4-18.7 deg,
#: 13.6 and 17.2 deg at c5c448e). F's own precondition is looser
#: (``MAX_SLOT_ANGLE``, 25 deg).
SLOT_ANGLE = min(math.radians(13.0), MAX_SLOT_ANGLE)
#: Largest angle [rad] in space between the slot and the cable from the clip's
#: entry to its last fixed point (the crossing in the top view and the rise
#: to it together: cos = cos(crossing) cos(rise)) at which F is planned. The
#: arm's bend turns the cable onto the slot on its own side; on the far side
#: the cable kinks at the entry by this angle, sideways and down at once.
#: Random boards (seeds 15-20) with a peg before the clip: F missed 4 of 5
#: clips at 15.1-16.8 deg (crossings 8.9-12.9 deg, rises 10.4-12.6 deg: each
#: within its own limit), the cable resting on the jaws' crest at the entry
#: with 3 N on a 1.6 N clip; it seated 17 of the 18 at 10.2-14.8 deg whose
#: outcome is known.
F_KINK = math.radians(14.0)
#: Beyond this angle [rad] between the slot and the cable, C clips where the
#: other gripper is free, F only where it is not. One arm kinks the cable
#: where it enters the clip, and only the far side's slope presses that end
#: in: on a level anchor-clip scene F seated up to 15 deg and missed 17 and
#: 20 deg (the slot's exit end snapped in, the entry end stayed on the
#: jaws); random boards missed clips at 11.6-18.7 deg. C holds the cable
#: along the slot with both grippers (12, 13, 17 and -20 deg: clipped).
F_ANGLE = math.radians(10.0)
#: Beyond this angle [rad] between the slot and the cable from a peg, F is
#: not planned (C where the other gripper is free, else the route is
#: refused). A straight cable crossing a 30 mm clip at alpha passes its ends
#: 15 mm tan(alpha) to either side, 2.6 mm at 10 deg: on the jaws' axes. From
#: an anchor or a clip the cable's line is known and F aims it over the seat
#: (seeds 24-26: 20 of 20 seated at 10.0-12.7 deg); a peg's leave point
#: moves 2-3 mm round the peg as the tension and the gripper's pose change
#: (random board 1674132175's F3 from peg F2: the taut line passed the axis
#: 11.4 mm off at F's start, 9.0 mm off 1.6 s on), so the cable met the jaws
#: 1.5 mm off centre, its exit end on the outer side of a jaw, and slid off.
#: Seeds 24-25: from a peg F seated 3 of 5 clips at 10.5-12.4 deg, every one below.
PEG_F_ANGLE = F_ANGLE
#: Largest angle [rad] between the slot and the cable at which C presses a
#: cable in: C turns the line between its grippers onto the slot about the
#: seat, and turned further the near gripper's way crosses the clip or the
#: near span goes taut. Random boards (seeds 10-14) whose slot lay 60-86 deg
#: across the cable failed C four times in six (14.4-14.6 N protective
#: stops, a cable pulled out of the clip, and 28.7 N true on board
#: 701294796, over the limit: the near gripper carried through the clip);
#: every C up to 58 deg clipped (the stored boards 1045612557 and
#: 1695658280 at 55 and 58 deg).
C_ANGLE = math.radians(59.0)
#: Largest turn [rad] of the cable out of the clip it last left towards a
#: clip C presses it into. C's near gripper holds the span that bends round
#: the last clip's exit and pulls it sideways there: on random boards
#: (seeds 10-20) C after turns of 81-150 deg stopped at 13.7-14.4 N (the
#: protective stop: 1942220284, 1053372611, 1160238227) or missed the clip
#: (1672212970) 4 times in the 5 whose outcome is known; after turns of
#: 61-80 deg it missed once in 10 (544908519 at 73 deg).
C_TURN = math.radians(80.0)
#: Largest turn [rad] of the pair onto the slot that C makes from the line
#: the other gripper grasps along (where the gripper was left, e.g. by the
#: slide out of the last clip, which runs on along that clip's slot).
#: Beyond it the cable is first swung over the clip. Over seeds 24-27,
#: every C whose pair turned 60-79 deg clipped (11 boards); both that
#: turned more stopped at the protective stop: 916737448 (109 deg, 13.6
#: N) and 905979088 (97 deg, 13.8 N; the line from F5 to F6 was 53 deg
#: from the slot). Past 90 deg C turned the short way, the near gripper to
#: the clip's far side, beyond the cable it held past the fixed point.
C_PAIR_TURN = math.radians(80.0)
#: How far [m] a cable that turns out of a clip runs on along the slot past
#: its exit before it turns: its straight span points back to a virtual
#: corner this far ahead of the exit, not to the exit (random board
#: 1672212970's F6, 82 deg on from F5: the measured line passed 9.4 mm
#: beside the exit, a corner 9.5 mm on). From there, not from the exit, the
#: cable crosses the next clip's slot: random boards whose next clip the
#: cable crossed at 9.2-12.8 deg from the exit missed it with F eight times
#: (seeds 11-14), the cable resting on the jaws with the slot's entry end
#: beside them, where the corner put the crossing at 12.7-15.7 deg.
BEND_RUN = 0.01
#: Least cable [m] a gripper keeps beyond the point it last routed.
MIN_LEAD = 0.04
#: Cable [m] beyond the needed point a slide (E) or a hand-over leaves.
LEAD = 0.08
#: Least cable [m] a gripper keeps past a peg it winds the cable round: the
#: span to it must be long enough to sense (a few of the simulated cable's
#: segments outside the fingers) and to turn about.
PEG_LEAD = 0.08
#: Least horizontal distance [m] of a winding gripper from the cable's own
#: span into the peg (the fingers would catch it).
FINGER_CLEARANCE = 0.03
#: Least horizontal distance [m] of the tool centre point from a fixture's body it
#: passes lower than ``GRIPPER_ABOVE`` over its top (fingers and pads); a move
#: at run time keeps the same clearance from a peg (``move.PEG_CLEARANCE``).
GRIPPER_CLEARANCE = PEG_CLEARANCE
#: Length [m] of the free tail beyond the gripper that runs on at its height,
#: along the span, before it droops (the pads' 10 mm and about as much
#: again): it must clear the board like the taut cable. The shipped
#: harness's W2 began its winding of P2 with the gripper 36 mm from C4's
#: centre, the tail pointing at it: the tail caught in C4's jaws and took
#: the pull, 2.7 N, while the span went slack; W1's tail passes C3 44 mm
#: off, 6 mm over its top, unharmed.
TAIL_REACH = 0.025
#: Horizontal room [m], beyond a fixture's body and the cable's radius, that
#: the free tail hanging from a sliding gripper must keep from a fixture it
#: could hang onto: the slide runs the fingers along the cable over where
#: the tail lies (random board 1695658280: W2's slide out of F5 ran the
#: gripper 16 mm over W1's clip F2; the tail, 0.5 m of it hanging from the
#: fingers, lay on F2, the pull through the fingers rose to 5.8 N, the
#: grip-force control opened the fingers and the cable fell out of them).
HANGING_TAIL_CLEAR = 0.01
#: Height [m] over a fixture's top at which the tool centre point passes it (the
#: harness board's slides pass clips 19 mm over their jaws unharmed; a move at
#: run time rises as high over a peg in its way, ``move.PEG_ABOVE``).
GRIPPER_ABOVE = PEG_ABOVE
#: Length [m] of a cable's last laid span, next to the fixed point the gripper
#: works about, that the fingers may pass over low (the fixture's own body is
#: checked there).
LAID_TRIM = 0.04
#: The name of the collision of a winding gripper with its cable's span into the peg.
OWN_SPAN = "the cable's own span"
#: Horizontal room [m] a slide leaves between where it ends and the reach of
#: every fixture but the one it leaves, for the tail that hangs from the fingers.
SLIDE_CLEAR = 0.03
#: Cable [m] a slide (E) leaves beyond the gripper, so that the end stays in the fingers.
TAIL = 0.03
#: A slide that the fixtures its tail would land on leave shorter than
#: ``MIN_SLIDE`` [m] (E judges its friction after 0.5 s at 0.04 m/s) is left
#: out where it is needed for at most ``SLIDE_SKIP`` [m], within what the
#: plan knows of where the gripper holds the cable (random board
#: 1652323633: a slide cut to the 1.1 mm it needed failed its own
#: judgement, having judged nothing).
MIN_SLIDE = 0.02
SLIDE_SKIP = 0.005
#: Angle [rad] past the tangent by which a move presses the cable onto a peg.
CATCH = math.radians(8.0)
#: Angle [rad] short of the tangent to a peg up to which a sweep is observed.
TOUCH = math.radians(5.0)
#: Largest turn [rad] about the last fixed point between two move waypoints.
SWEEP_STEP = math.radians(30.0)
#: Highest [m] over a peg's top a gripper winds a full turn round it from.
#: Higher, the span rising to the gripper lifts the wrap as it climbs its
#: own strand, and it slips off over the top: on random boards (seeds
#: 10-21) full turns wound from 131-137 mm round 110 mm pegs at radii of
#: 243-274 mm went slack 3 times in 5 (630257320, 1546552617, 1761140914:
#: the cable off the peg at the turn's end); the 38 wound from 109-124 mm
#: whose outcome is known all held.
WIND_ABOVE = 0.015
#: Height [m] by which a winding's span passes another peg above the band in
#: which the model takes it for a contact on that peg. While I circles, a
#: force line tangent to a peg of the design (within ``DESIGN_TOLERANCE``)
#: whose height at the axis is at most the top plus the cable's radius,
#: ``RADIUS_MARGIN`` and ``LINE_HEIGHT_TOLERANCE`` declares that peg the
#: contact at once (``ModelEstimator._peg_change``). Random board 538472386
#: (seed 24): I round F1 ended with its span 8-10 mm over F2's top, about 10
#: mm beside F2's axis, clear of it by the sweep's 5 mm ``CLEARANCE``; a
#: line met F2's axis 8.7 mm over its top, F2 became the model's contact
#: though the cable never touched it, and I failed ``not_wound``. A span that
#: passes another peg that near horizontally passes at least this much over
#: the band (the lines' scatter in height at the peg: 1-3 mm).
SENSED_MARGIN = 0.004
#: Height [m] over a peg's top at which a lifted cable passes it.
OVER_PEG = 0.02
#: Steepest rise [rad] of a taut cable from the clip it last went into while
#: the moves that catch a peg carry it (the one check so far): steeper,
#: it draws its end up into the jaws' throat (F's own limit, MAX_FAR_RISE), and
#: pulled across the slot too it comes out (random board 1808415002: lifted
#: over F3 at 25 deg from F2 and 60 deg across its slot, W1 left F2, slack).
CLIP_RISE = MAX_FAR_RISE
#: Friction coefficient [-] the planner counts on between a cable and a peg it
#: bends round (half the 0.2 of the world's pegs): a gripper that pulls the
#: cable up more steeply than that holds it (:func:`peg_climb`) lifts it up
#: the peg and off its top. Random board 250645250 (seed 26): W2 wound 27 deg
#: round F4 (top at 110 mm), then lifted to 154 mm, 113 mm from F4, "to lift
#: the cable clear of the board before sliding it out" (climb 0.38): MuJoCo
#: had the cable off F4 at the move's end and the move found it slack. Over
#: the 90 boards of seeds 24-26 every other move planned from a peg climbed
#: at most 0.08, and all of those boards completed. A full turn round the
#: peg does not hold it either (the span rising to the gripper lifts the
#: wrap up its own strand, as in ``WIND_ABOVE``): random board 333750234
#: (seed 27), W2 wound 401 deg round F4 (top 110 mm), then lifted to 197
#: mm, 162 mm from F4 (climb 0.41), held 3 N through E and D, and 1.5 s
#: later the wrap came off over the top in 0.08 s (F4's contact force 14.7
#: -> 0.03 N, the tension 2.9 -> 0.1 N).
PEG_HOLD_FRICTION = 0.1
#: Step [rad] of the rise a gripper is lifted by, about the last fixed point,
#: before a slide that would otherwise run into a fixture.
LIFT_STEP = math.radians(2.0)
#: Largest turn [rad] aside about the vertical, and its step, of the pose a
#: slide starts from where a fixture stands straight on along it (see
#: ``_Planner.slide_lift``).
SIDE_TURN = math.radians(30.0)
SIDE_STEP = math.radians(10.0)
#: Cable length [m] between the two grippers of a parallel clip (H + C).
SPAN = 0.12
#: H grasps at least this far [m] from either end of the taut edge.
GRASP_MARGIN = 0.04
#: Cable [m] beyond its straight length that C's near span keeps when the
#: cable snaps in (see ``_Planner.parallel_half_span``).
NEAR_SLACK = 0.010
#: Cable [m] a right-angle turn out of the last clip's slot costs C's near
#: span (a turn theta costs 1 - cos theta of it): the cable leaves the jaws
#: straight and bends beyond them. Random board 1652323633's C into F7: the
#: near span left F6 75 deg off its slot, and with ``NEAR_SLACK`` alone it
#: went taut on the way over F7 (13.6 N).
BEND_SLACK = 0.020
#: Half the widest distance [m] between C's grippers: a gripper holding more
#: cable hands it over nearer first (random board 1808415002: 139 mm, the
#: near gripper grasped 40 mm from the anchor, and C pulled 28 N).
MAX_HALF_SPAN = 0.10
#: Least turn [rad] of I round a peg that the route goes on from (it finds the peg).
MIN_WIND = math.radians(20.0)
#: Turn [rad] of I round the route's last peg past the catch: with nothing
#: after it to aim at, I still turns the cable far enough to find the peg, so
#: the model has it (the shipped harness's P3 was caught, never found: W2's
#: route could not count as done).
LAST_WIND = math.radians(30.0)
#: Wraps [rad] this small are left to the catch move (no I step).
SMALL_TURN = math.radians(3.0)
#: Decimals of the numbers in a plan (0.1 mm, 0.1 mrad).
DIGITS = 4
#: Height [m] a swept cable keeps over the top of a fixture it passes (beyond its radius).
CLEARANCE = 0.005
#: Steps [m] by which the height at which the cable passes a peg is raised to clear fixtures.
PASS_STEP = 0.005
#: Horizontal reach [m] of a parked gripper's open fingers (pads 20 mm
#: either side of the tool centre point, 6 mm thick, 20 mm long) with the
#: cable's radius and room to spare: a taut cable swept closer catches on
#: them (random board 1652323633: W1's winding round F1 swept the cable
#: into the right gripper, parked holding W2 2 cm under the cable's line).
PARKED_REACH = 0.045
#: Depth [m] of a gripper's finger pads below its tool centre point.
PAD_DEPTH = 0.008
#: Turn short of a whole turn [rad] from which a winding lies on its own
#: incoming strand at the peg: the two tangents then cross within about a
#: cable's diameter of the peg's surface.
CROSS_MARGIN = math.radians(45.0)
#: Climb [cable diameters] of a winding where it crosses its own strand on a
#: peg (random board 208802845: W2 wound 356 deg round F4, caught at 98-100
#: mm, lay on 101-107 mm past the crossing, reached the top at 110 mm and
#: slipped off it).
CROSS_CLIMB = 1.5
#: Height [cable diameters] above its pass height at which a winding leaves its
#: peg, on top of its own strand, for each crossing: measured 1.5-2.2 (random
#: boards 208802845 and 1991395197, wound once), with half a diameter to spare.
LEAVE_CLIMB = 2.5


class RouteError(TautwireError):
    """A route the robot cannot do.

    Its string is one line: ``cable W1, route entry 2 (C1): reason``.

    Attributes:
        cable: the cable's name.
        entry: 1-based index of the route entry (``None``: the cable as a whole).
        fixture: the entry's fixture name (``None`` with ``entry``).
        reason: what makes it impossible (and what would do).
    """

    def __init__(self, cable: str, entry: int | None, fixture: str | None, reason: str) -> None:
        self.cable = cable
        self.entry = entry
        self.fixture = fixture
        self.reason = reason
        where = f"cable {cable}" if entry is None else f"cable {cable}, route entry {entry}"
        if fixture is not None:
            where += f" ({fixture})"
        super().__init__(" ".join(f"{where}: {reason}".split()))


@dataclass(frozen=True)
class BoardFixture:
    """A fixture of the board, as the planner sees it.

    Attributes:
        name: unique name.
        kind: ``anchor``, ``peg`` or ``clip``.
        position: anchor point, peg base centre or clip seat [m].
        radius: a peg's radius [m].
        height: a peg's height above ``position`` [m].
        yaw: a clip's slot direction about z [rad].
        push_force: the force that pushes a cable into a clip [N].
        length: a clip's length along its slot [m].
    """

    name: str
    kind: Literal["anchor", "peg", "clip"]
    position: Point
    radius: float = 0.0
    height: float = 0.0
    yaw: float = 0.0
    push_force: float = 0.0
    length: float = 0.0


@dataclass(frozen=True)
class RouteEntry:
    """One fixture of a target route.

    Attributes:
        fixture: the peg or clip's name.
        side: for a peg, the side of the cable it stays on, seen along the route.
        wind: for a peg, full turns around it.
    """

    fixture: str
    side: Side | None = None
    wind: int = 0


@dataclass(frozen=True)
class CableToRoute:
    """A cable, where it starts and is held, and its target route.

    Attributes:
        name: the cable's name.
        length: rest length [m].
        stiffness: axial stiffness of the whole cable [N/m].
        radius: cable radius [m].
        start: the anchor holding its first end (``None``: a free end).
        via: fixtures it initially bears against, in order.
        holds: ``(arm, arc length [m])`` of each gripper that holds it.
        route: the target route (empty: the planner leaves the cable alone).
    """

    name: str
    length: float
    stiffness: float
    radius: float
    start: str | None
    via: tuple[str, ...]
    holds: tuple[tuple[Arm, float], ...]
    route: tuple[RouteEntry, ...]


@dataclass(frozen=True)
class RobotLayout:
    """The robot as the planner sees it.

    Attributes:
        grippers: start position of each tool centre point [m].
        sensors: the arms that carry a force-torque sensor.
        reach: the box every planned tool centre point must lie in.
        force_limit: the run's force limit [N].
    """

    grippers: Mapping[Arm, Point]
    sensors: frozenset[Arm]
    reach: Workspace
    force_limit: float


@dataclass(frozen=True)
class RouteProblem:
    """Everything the planner needs.

    Attributes:
        fixtures: the board.
        cables: every cable on it (those without a route are left alone).
        robot: grippers, sensors, reach and force limit.
        tension: the tension [N] D keeps while routing.
        friction_force: the tension [N] kept while the cable slides out (E).
    """

    fixtures: tuple[BoardFixture, ...]
    cables: tuple[CableToRoute, ...]
    robot: RobotLayout
    tension: float = 3.0
    friction_force: float = 1.5


@dataclass(frozen=True)
class PlannedStep:
    """One step of the plan: a primitive or a move with its parameters.

    Attributes:
        primitive: canonical name (``single_arm_tension``, ``move``, ...).
        params: parameters by name, ``cable`` included (SI units).
        why: what the step is for, in words.
    """

    primitive: str
    params: Mapping[str, ParamValue]
    why: str

    def as_task_step(self) -> dict[str, ParamValue]:
        """The step as a scenario's ``task:`` entry (flat)."""
        return {"primitive": self.primitive, **self.params}


@dataclass(frozen=True)
class CablePlan:
    """What the plan does with one cable.

    Attributes:
        name: the cable's name.
        steps: indices of its steps in :attr:`Plan.steps`.
        route_length: cable [m] from the start to the last routed point
            (along the fixtures, windings and slack before a parallel clip included).
        held_at: arc length [m] at which a gripper holds it at the end.
        arm: the gripper that holds it at the end.
    """

    name: str
    steps: tuple[int, ...]
    route_length: float
    held_at: float
    arm: Arm


@dataclass(frozen=True)
class Plan:
    """The planned task.

    Attributes:
        steps: in order.
        cables: one entry per routed cable.
    """

    steps: tuple[PlannedStep, ...]
    cables: tuple[CablePlan, ...]

    def task(self) -> list[dict[str, ParamValue]]:
        """The steps as a scenario's ``task:`` list."""
        return [step.as_task_step() for step in self.steps]


def plan_routes(problem: RouteProblem) -> Plan:
    """Plan every cable's route, cable after cable.

    The problem's order first; where that presses clips in with one arm
    beyond ``F_ANGLE`` because the other gripper still holds a cable not
    yet routed, the reverse order of two cables too, and the plan with
    fewer such clips (the first on a tie, or the one that plans at all).

    Raises:
        RouteError: for the first route entry the robot cannot do (in
            the problem's order).
    """
    first: _Planner | None = None
    error: RouteError | None = None
    try:
        first = _Planner(problem)
        plan = first.plan()
    except RouteError as exc:
        error, first = exc, None
    if len(problem.cables) == 2 and (first is None or first.steep_single > 0):
        swapped = replace(problem, cables=tuple(reversed(problem.cables)))
        try:
            second = _Planner(swapped)
            other = second.plan()
        except RouteError:
            pass
        else:
            if first is None or second.steep_single < first.steep_single:
                return other
    if first is None:
        assert error is not None
        raise error
    return plan


# ------------------------------------------------------------------ geometry


def _vec(p: Point | FloatArray) -> FloatArray:
    return np.array([float(c) for c in p], dtype=float)


def _flat(v: FloatArray) -> FloatArray:
    return np.array([v[0], v[1], 0.0])


def _unit(v: FloatArray) -> FloatArray:
    n = float(np.linalg.norm(v))
    return v / n if n > 1e-12 else np.zeros(3)


def _turn(v: FloatArray, angle: float) -> FloatArray:
    """``v`` turned by ``angle`` [rad] about +z."""
    c, s = math.cos(angle), math.sin(angle)
    return np.array([c * v[0] - s * v[1], s * v[0] + c * v[1], v[2]])


def _heading(v: FloatArray) -> float:
    return math.atan2(float(v[1]), float(v[0]))


def _swept(start: FloatArray, end: FloatArray, sign: float) -> float:
    """Angle [rad, 0..2 pi) from horizontal ``start`` to ``end``, turning the ``sign`` way."""
    return (sign * (_heading(end) - _heading(start))) % (2.0 * math.pi)


def _cross_z(a: FloatArray, b: FloatArray) -> float:
    return float(a[0] * b[1] - a[1] * b[0])


def _tangent_from(point: FloatArray, centre: FloatArray, rho: float, sign: float) -> FloatArray:
    """Horizontal unit direction from ``point`` that grazes the circle (centre, rho).

    ``sign`` +1: the circle stays on the direction's left; -1: on its right.
    """
    rel = _flat(centre - point)
    d = float(np.linalg.norm(rel))
    beta = math.asin(min(1.0, rho / d))
    return _turn(rel / d, -sign * beta)


def _tangent_to(point: FloatArray, centre: FloatArray, rho: float, sign: float) -> FloatArray:
    """Horizontal unit direction from the circle towards ``point``, leaving it tangentially.

    ``sign`` +1: the circle stays on the direction's left (the cable turned
    counter-clockwise round it); -1: on its right.
    """
    rel = _flat(centre - point)
    d = float(np.linalg.norm(rel))
    beta = math.asin(min(1.0, rho / d))
    return -_turn(rel / d, sign * beta)


def _fmt(p: FloatArray) -> str:
    return "[" + ", ".join(f"{float(c):.3f}" for c in p) + "]"


def _round(v: float) -> float:
    return round(float(v), DIGITS) + 0.0


def fixture_top(fixture: BoardFixture) -> float | None:
    """Height [m] of a fixture's top that a cable collides with (``None``: an anchor, no body)."""
    if fixture.kind == "peg":
        return fixture.position[2] + fixture.height
    if fixture.kind == "clip":
        return fixture.position[2] + JAW_TOP
    return None


def fixture_reach(fixture: BoardFixture) -> float:
    """Horizontal radius [m] about a fixture's position inside which its body stands."""
    if fixture.kind == "peg":
        return fixture.radius
    return 0.5 * fixture.length


def peg_climb(before: FloatArray, peg: BoardFixture, height: float, gripper: FloatArray) -> float:
    """How hard a taut cable bent round ``peg`` at ``height`` [m] is pulled up it.

    The cable comes from ``before`` [m] (the fixed point it leaves before
    the peg) and goes to the gripper at ``gripper`` [m], with the same
    tension on both sides. The result is the upward pull over the pull
    against the peg (the normal force), both per unit tension: the cable
    slides up the peg when it exceeds the friction coefficient. Negative
    when the two sides pull it down.

    Args:
        before: The fixed point before the peg [m].
        peg: The peg.
        height: Height [m] of the cable on the peg.
        gripper: The gripper's point [m].

    Returns:
        Upward pull over normal force [-].
    """
    at = np.array([peg.position[0], peg.position[1], height], dtype=float)
    a = _unit(_vec(before) - at)
    b = _unit(_vec(gripper) - at)
    up = float(a[2] + b[2])
    normal = float(np.linalg.norm(_flat(a + b)))
    return up / max(normal, 1e-9)


def gripper_collision(
    point: FloatArray, fixtures: tuple[BoardFixture, ...], skip: frozenset[str] = frozenset()
) -> Collision | None:
    """The fixture (if any) that a gripper at ``point`` [m] would touch with its fingers."""
    for fixture in fixtures:
        top = fixture_top(fixture)
        if top is None or fixture.name in skip:
            continue
        gap = float(np.linalg.norm(_flat(point - _vec(fixture.position))))
        if gap < fixture_reach(fixture) + GRIPPER_CLEARANCE and point[2] < top + GRIPPER_ABOVE:
            return Collision(fixture.name, float(point[2]), top + GRIPPER_ABOVE, "gripper")
    return None


def tail_collision(
    gripper: FloatArray,
    pivot: FloatArray,
    fixtures: tuple[BoardFixture, ...],
    cable_radius: float,
    skip: frozenset[str] = frozenset(),
) -> Collision | None:
    """The fixture (if any) that the free tail beyond a gripper at ``gripper`` [m] runs into.

    The tail leaves the fingers straight on from the taut span from
    ``pivot``, at the gripper's height, for :data:`TAIL_REACH`.
    """
    out = _flat(gripper - pivot)
    length = float(np.linalg.norm(out))
    if length < 1e-9:
        return None
    end = gripper + TAIL_REACH * out / length
    hit = segment_collision(gripper, end, fixtures, cable_radius, skip)
    if hit is None:
        return None
    return Collision(hit.fixture, hit.height, hit.needed, "cable's free tail")


def hanging_tail_collision(
    start: FloatArray,
    end: FloatArray,
    tail: float,
    fixtures: tuple[BoardFixture, ...],
    cable_radius: float,
    skip: frozenset[str] = frozenset(),
) -> Collision | None:
    """The fixture (if any) under a slide from ``start`` to ``end`` [m] that its hanging tail meets.

    The ``tail`` [m] of cable beyond the fingers hangs from them: a
    fixture whose body lies within :data:`HANGING_TAIL_CLEAR` (plus the
    cable's radius) of the gripper's way in the top view, with its top
    less than the tail's length below the gripper, is in the tail's way.
    """
    room = cable_radius + HANGING_TAIL_CLEAR
    for fixture, top, height in _fixtures_beside(start, end, fixtures, room, skip):
        if height - top < tail:
            return Collision(fixture.name, height, top + tail, "cable's free tail")
    return None


def parked_collision(
    start: FloatArray, end: FloatArray, parked: Mapping[Arm, FloatArray], cable_radius: float
) -> Collision | None:
    """The parked gripper (if any) that the straight taut cable from ``start`` to ``end`` hits.

    A gripper that stands still while the other one works (holding another
    cable, or let go) is in the way where the segment passes within
    :data:`PARKED_REACH` of its tool centre point (horizontally) above the
    bottom of its pads: the arm above it leaves no way over.
    """
    a, b = _flat(start), _flat(end)
    for arm, at in parked.items():
        p = _flat(at)
        t = _along(a, b, p)
        if float(np.linalg.norm(a + t * (b - a) - p)) > PARKED_REACH:
            continue
        height = float(start[2]) + t * float(end[2] - start[2])
        bottom = float(at[2]) - PAD_DEPTH - cable_radius - CLEARANCE
        if height > bottom:
            return Collision(f"the {arm} gripper", height, bottom, "cable")
    return None


@dataclass(frozen=True)
class Collision:
    """A taut cable segment (or the gripper holding it) that runs into a fixture.

    Attributes:
        fixture: the fixture's name.
        height: the cable's height [m] where it passes the fixture.
        needed: the least height [m] at which it clears the fixture's top.
        by: what runs into it: the taut ``cable``, the ``gripper`` (its
            fingers) or the ``cable's free tail`` beyond it.
        sensed: the cable clears the fixture but passes it so near that the
            model would take it for a contact there (``segment_collision`` with ``sensed``).
    """

    fixture: str
    height: float
    needed: float
    by: Literal["cable", "gripper", "cable's free tail"] = "cable"
    sensed: bool = False


def _along(a: FloatArray, b: FloatArray, p: FloatArray) -> float:
    """Where along the segment from ``a`` to ``b`` (0 to 1) it passes nearest ``p``."""
    ab = b - a
    n2 = float(ab @ ab)
    return 0.0 if n2 < 1e-12 else min(1.0, max(0.0, float((p - a) @ ab) / n2))


def _hits_gripper(hit: Collision) -> bool:
    """Whether ``hit`` is a parked gripper's (:func:`parked_collision`), not a fixture's."""
    return hit.fixture.endswith(" gripper")


def _needs(hit: Collision) -> str:
    """What clears the thing a :class:`Collision` runs into, for an error message."""
    if _hits_gripper(hit):  # only under its fingers
        return f"the bottom of {hit.fixture}'s fingers is at {hit.needed:.3f} m"
    return f"{hit.fixture} needs at least {hit.needed:.3f} m"


def segment_collision(
    start: FloatArray,
    end: FloatArray,
    fixtures: tuple[BoardFixture, ...],
    cable_radius: float,
    skip: frozenset[str] = frozenset(),
    sensed: bool = False,
) -> Collision | None:
    """The fixture (if any) that the straight cable from ``start`` to ``end`` runs into.

    The cable is taut, so it is the straight segment; a fixture is in its way
    when the segment passes within the fixture's reach plus the cable's radius
    (horizontally) below its top plus :data:`CLEARANCE`. The fixture of
    ``skip`` (the one the cable leaves or is aimed at) is not checked.

    With ``sensed`` (a winding's span, which I's force lines sense), a peg is
    in its way too where the span only looks bearing on it: passing within
    the peg's reach plus the cable's radius, ``RADIUS_MARGIN`` and
    ``DESIGN_TOLERANCE`` of its axis (horizontally) below its top plus the
    cable's radius, ``RADIUS_MARGIN``, ``LINE_HEIGHT_TOLERANCE`` and
    ``SENSED_MARGIN`` (see ``SENSED_MARGIN``); such a collision is marked
    ``sensed``.
    """
    for fixture, top, height in _fixtures_beside(start, end, fixtures, cable_radius, skip):
        needed = top + cable_radius + CLEARANCE
        if height < needed:
            return Collision(fixture.name, height, needed)
    if not sensed:
        return None
    pegs = tuple(f for f in fixtures if f.kind == "peg")
    room = cable_radius + RADIUS_MARGIN + DESIGN_TOLERANCE
    for fixture, top, height in _fixtures_beside(start, end, pegs, room, skip):
        needed = top + cable_radius + RADIUS_MARGIN + LINE_HEIGHT_TOLERANCE + SENSED_MARGIN
        if height < needed:
            return Collision(fixture.name, height, needed, sensed=True)
    return None


def _fixtures_beside(
    start: FloatArray,
    end: FloatArray,
    fixtures: tuple[BoardFixture, ...],
    room: float,
    skip: frozenset[str],
) -> Iterator[tuple[BoardFixture, float, float]]:
    """(fixture, its top, the segment's height there) for each body within ``room`` [m] of it.

    In the top view, the straight segment from ``start`` to ``end`` [m]
    passes within the fixture's reach plus ``room`` of its position;
    fixtures without a body (anchors) and those of ``skip`` are left out.
    The height is the segment's where it passes nearest the fixture.
    """
    a, b = _flat(start), _flat(end)
    ab = b - a
    for fixture in fixtures:
        top = fixture_top(fixture)
        if top is None or fixture.name in skip:
            continue
        p = _flat(_vec(fixture.position))
        t = _along(a, b, p)
        if float(np.linalg.norm(a + t * ab - p)) > fixture_reach(fixture) + room:
            continue
        yield fixture, top, float(start[2]) + t * float(end[2] - start[2])


# ------------------------------------------------------------------ planner


@dataclass
class _Cable:
    """The planner's running state of the cable being routed."""

    spec: CableToRoute
    arm: Arm
    at: float  # the held arc length [m]
    gripper: FloatArray  # the planned tool centre point [m]
    contact: FloatArray  # the last fixed point the cable leaves [m]
    s_contact: float  # its arc length [m]
    entry: int | None = None  # 1-based route entry being planned
    fixture: str | None = None
    steps: list[int] = field(default_factory=list)
    #: Where F leaves the gripper, lower than ``gripper`` (see ``_Planner.after_push``);
    #: None once another step is planned (``_Planner.emit``).
    pressed: FloatArray | None = None
    #: The cable laid so far: the fixed points it leaves, by fixture, from its start.
    laid: list[tuple[str, FloatArray]] = field(default_factory=list)
    #: Arc length [m] from which the cable stretches under the gripper's pull:
    #: its start, or the last peg it is wound round a full turn (clips and
    #: pegs it bends over let it slide through).
    s_held: float = 0.0

    def lay(self, fixture: str) -> None:
        """The cable now leaves ``fixture`` at ``contact``: the last fixed point it is laid to."""
        self.laid.append((fixture, self.contact.copy()))

    @property
    def last(self) -> str | None:
        """The fixture at the last fixed point (None before the cable is laid to one)."""
        return self.laid[-1][0] if self.laid else None

    @property
    def free(self) -> float:
        """Cable [m] between the last fixed point and the gripper."""
        return self.at - self.s_contact


@dataclass(frozen=True)
class _PegMotion:
    """How the gripper catches a peg and winds round it (see ``_Planner.peg_motion``)."""

    moves: list[tuple[FloatArray, str]]
    catch: FloatArray
    wind: list[FloatArray]
    z_grip: float
    collision: Collision | None
    what: str
    catch_from: int  # the first move (index) that bends the cable onto the peg
    rest: float  # the turn [rad] I winds after the catch


class _Planner:
    def __init__(self, problem: RouteProblem) -> None:
        self.problem = problem
        self.robot = problem.robot
        self.fixtures = {f.name: f for f in problem.fixtures}
        self.steps: list[PlannedStep] = []
        self.cables: list[CablePlan] = []
        self.routed: list[_Cable] = []  # the cables planned, as laid
        self.holder: dict[Arm, str | None] = {"left": None, "right": None}
        for cable in problem.cables:
            for arm, _ in cable.holds:
                self.holder[arm] = cable.name
        self.done: dict[str, bool] = {}  # routed cable -> whether a clip holds its end
        #: where each gripper stands [m] while the other one routes a cable
        self.parked: dict[Arm, FloatArray] = {
            arm: _vec(p) for arm, p in problem.robot.grippers.items()
        }
        self.steep_single = 0  # clips F presses in beyond F_ANGLE (C's gripper was busy)
        self.clips_used: dict[str, str] = {}

    # -- helpers

    def fail(self, cable: _Cable, reason: str) -> RouteError:
        return RouteError(cable.spec.name, cable.entry, cable.fixture, reason)

    def emit_move(self, cable: _Cable, point: FloatArray, why: str, **params: ParamValue) -> None:
        """A taut ``move`` of the cable's gripper to ``point`` [m].

        Raises:
            RouteError: The move would pull the cable up off the peg it was
                last laid round (:meth:`lifts_off_peg`).
        """
        climb = self.lifts_off_peg(cable, point)
        if climb is not None:
            raise self.fail(
                cable,
                f"to {why}, the gripper at z = {float(point[2]):.3f} m pulls the cable up "
                f"{cable.last} with {climb:.2f} of its pull against the peg (expected at most "
                f"{PEG_HOLD_FRICTION:g}: steeper, the cable slides up the peg and off its top)",
            )
        self.emit(
            cable, "move", why, arm=cable.arm, to=[float(v) for v in point], taut=True, **params
        )

    def emit(self, cable: _Cable, primitive: str, why: str, **params: ParamValue) -> None:
        cable.pressed = None  # any step moves the gripper on from where F left it
        values: dict[str, ParamValue] = {}
        for key, value in params.items():
            if isinstance(value, float):
                value = _round(value)
            elif isinstance(value, list):
                value = [_round(c) for c in value]
            values[key] = value
        if primitive == "move":
            values.setdefault("observe", True)
        values["cable"] = cable.spec.name
        cable.steps.append(len(self.steps))
        self.steps.append(PlannedStep(primitive, values, why))

    def lifts_off_peg(self, cable: _Cable, point: FloatArray) -> float | None:
        """The climb (:func:`peg_climb`) of a gripper at ``point`` [m] lifting the cable off a peg.

        None where it does not: the last fixed point is not a peg, or the
        climb with the cable at the top of the peg's band (the cable's
        radius and 3 mm under the top) is at most ``PEG_HOLD_FRICTION``,
        wound round it or not. The cable may slide up the peg on the way
        there, no further.
        """
        last = self.fixtures.get(cable.last) if cable.last else None
        if last is None or last.kind != "peg" or len(cable.laid) < 2:
            return None
        top = last.position[2] + last.height - cable.spec.radius - 0.003
        climb = peg_climb(cable.laid[-2][1], last, top, point)
        return climb if climb > PEG_HOLD_FRICTION else None

    def check_reach(self, cable: _Cable, point: FloatArray, what: str) -> None:
        if not self.robot.reach.contains([float(c) for c in point]):
            raise self.fail(
                cable,
                f"{what} takes the gripper to {_fmt(point)}, out of reach "
                f"(expected {self.robot.reach.describe()})",
            )

    def other_arm_available(self, cable: _Cable) -> bool:
        """Whether :meth:`other_arm_free` would give the other gripper (nothing planned)."""
        other: Arm = "right" if cable.arm == "left" else "left"
        held = self.holder[other]
        return held is None or bool(self.done.get(held))

    def other_arm_free(self, cable: _Cable) -> Arm | None:
        """The other gripper, released from a finished clipped cable if need be; or None."""
        other: Arm = "right" if cable.arm == "left" else "left"
        held = self.holder[other]
        if held is None:
            return other
        if self.done.get(held):
            self.holder[other] = None
            self.steps.append(
                PlannedStep(
                    "release",
                    {"arm": other, "cable": held},
                    f"free the {other} gripper: {held} is routed and its last clip holds it",
                )
            )
            cable.steps.append(len(self.steps) - 1)
            return other
        return None

    def parked_other(self, cable: _Cable) -> dict[Arm, FloatArray]:
        """Where the gripper that does not hold ``cable`` stands [m], by arm."""
        other: Arm = "right" if cable.arm == "left" else "left"
        return {other: self.parked[other]}

    def why_other_busy(self, cable: _Cable) -> str:
        other: Arm = "right" if cable.arm == "left" else "left"
        held = self.holder[other]
        if held is None:
            return f"the {other} gripper has no force sensor"
        if held in self.done:
            return f"the {other} gripper holds {held}, whose route does not end in a clip"
        return f"the {other} gripper holds {held}"

    # -- the plan

    def plan(self) -> Plan:
        for spec in self.problem.cables:
            if spec.route:
                self.plan_cable(spec)
        return Plan(tuple(self.steps), tuple(self.cables))

    def plan_cable(self, spec: CableToRoute) -> None:
        probe = _Cable(spec, "left", 0.0, np.zeros(3), np.zeros(3), 0.0)
        start = None if spec.start is None else self.fixtures.get(spec.start)
        if start is None or start.kind != "anchor":
            raise self.fail(
                probe,
                "has no start anchor (expected start: an anchor; D tensions the cable against it)",
            )
        if len(spec.holds) != 1:
            raise self.fail(
                probe,
                "is held by both grippers (expected one hold: the planner routes with the "
                "gripper that holds the cable and keeps the other free)",
            )
        arm, at = spec.holds[0]
        if arm not in self.robot.sensors:
            raise self.fail(
                probe,
                f"is held by the {arm} gripper, which has no force sensor (expected the "
                "holding gripper to sense: sensor.arm both or " + arm + ")",
            )
        anchor = _vec(start.position)
        cable = _Cable(spec, arm, at, _vec(self.robot.grippers[arm]), anchor, 0.0)
        cable.lay(start.name)
        # the cable starts through its via fixtures: the route must begin with them
        entries = list(enumerate(spec.route, start=1))
        for k, name in enumerate(spec.via):
            if k >= len(entries) or entries[k][1].fixture != name:
                raise self.fail(
                    cable,
                    f"starts through {name} (via) but its route does not begin with "
                    f"{', '.join(spec.via)} (expected the via fixtures first, in order)",
                )
        for k, entry in entries:
            cable.entry, cable.fixture = k, entry.fixture
            fixture = self.fixtures.get(entry.fixture)
            if fixture is None or fixture.kind == "anchor":
                what = "an anchor" if fixture is not None else "not a fixture of the board"
                routable = [f.name for f in self.problem.fixtures if f.kind != "anchor"]
                raise self.fail(
                    cable,
                    f"{entry.fixture} is {what} (expected a peg or clip: "
                    f"{', '.join(routable) or 'none'})",
                )
            if fixture.kind == "peg" and entry.side is None:
                raise self.fail(cable, "a peg needs a side (expected left or right)")
            if fixture.kind == "clip" and fixture.name in self.clips_used:
                raise self.fail(
                    cable, f"clip {fixture.name} already holds {self.clips_used[fixture.name]}"
                )
        cable.entry, cable.fixture = None, None
        laid = len(spec.via)
        for k, entry in entries[:laid]:  # laid by the initial routing: follow the geometry
            cable.entry, cable.fixture = k, entry.fixture
            self.follow_laid(cable, entry, entries[k][1] if k < len(entries) else None)
        cable.entry, cable.fixture = None, None
        gap = float(np.linalg.norm(cable.gripper - cable.contact))
        if gap > cable.free + 1e-6:
            raise self.fail(
                cable,
                f"{cable.free:.3f} m of cable cannot span the {gap:.3f} m from its last fixed "
                f"point {_fmt(cable.contact)} to the {cable.arm} gripper (expected the gripper "
                "within the cable's reach)",
            )
        # D: tension against the last fixed point
        taut = cable.contact + cable.free * _unit(cable.gripper - cable.contact)
        self.check_reach(cable, taut, "tensioning")
        cable.gripper = taut
        self.emit(
            cable,
            "single_arm_tension",
            "pull the cable taut",
            arm=cable.arm,
            force=self.problem.tension,
        )
        for k, entry in entries[laid:]:
            cable.entry, cable.fixture = k, entry.fixture
            following = entries[k][1] if k < len(entries) else None
            fixture = self.fixtures[entry.fixture]
            if fixture.kind == "peg":
                self.plan_peg(cable, entry, fixture, following)
            else:
                self.plan_clip(cable, fixture)
        self.done[spec.name] = self.fixtures[spec.route[-1].fixture].kind == "clip"
        self.holder[cable.arm] = spec.name
        self.parked[cable.arm] = cable.gripper.copy()
        self.cables.append(
            CablePlan(spec.name, tuple(cable.steps), cable.s_contact, cable.at, cable.arm)
        )
        self.routed.append(cable)

    def next_point(self, entry: RouteEntry | None) -> FloatArray | None:
        """Where the cable heads for after a peg: the next fixture's seat or axis [m]."""
        if entry is None:
            return None
        fixture = self.fixtures.get(entry.fixture)
        return None if fixture is None else _vec(fixture.position)

    # -- pegs

    def wrap(
        self, cable: _Cable, peg: BoardFixture, entry: RouteEntry, following: RouteEntry | None
    ) -> tuple[FloatArray, FloatArray, float, float]:
        """The taut wrap of ``peg``: (u_in, tangent point T1, the turn [rad], rho [m])."""
        sign = 1.0 if entry.side == "left" else -1.0
        rho = peg.radius + cable.spec.radius
        centre = _vec(peg.position)
        c = cable.contact
        d = float(np.linalg.norm(_flat(centre - c)))
        if d <= rho + 1e-3:
            raise self.fail(cable, "the peg stands at the cable's last fixed point")
        u_in = _tangent_from(c, centre, rho, sign)
        t1 = c + u_in * math.sqrt(max(d * d - rho * rho, 0.0))
        t1[2] = c[2]
        target = self.next_point(following)
        if target is None:
            turn = CATCH + LAST_WIND
        elif float(np.linalg.norm(_flat(target - centre))) <= rho + 1e-3:
            turn = CATCH
        else:
            u_out = _tangent_to(target, centre, rho, sign)
            turn = _swept(u_in, u_out, sign)
        return u_in, t1, turn + 2.0 * math.pi * entry.wind, rho

    def follow_laid(self, cable: _Cable, entry: RouteEntry, following: RouteEntry | None) -> None:
        """Advance along a fixture the initial routing already lays the cable through."""
        fixture = self.fixtures[entry.fixture]
        if fixture.kind == "clip":
            self.advance_clip(cable, fixture)
            return
        cable.lay(fixture.name)
        if entry.wind:
            raise self.fail(cable, "the initial routing (via) lays no windings")
        sign = 1.0 if entry.side == "left" else -1.0
        centre = _vec(fixture.position)
        after = self.next_point(following)
        if after is None:
            after = cable.gripper
        bend = _cross_z(_flat(centre - cable.contact), _flat(after - centre))
        if bend * sign < 0.0:  # a left peg turns the cable left: cross > 0
            raise self.fail(
                cable,
                f"the initial routing (via) bends the cable round the peg's other side "
                f"(expected the peg on the {'right' if sign > 0 else 'left'})",
            )
        self.advance_peg(cable, fixture, entry, following)

    def advance_peg(
        self, cable: _Cable, peg: BoardFixture, entry: RouteEntry, following: RouteEntry | None
    ) -> float:
        """Move the last fixed point past the wrapped peg; return the cable it used [m]."""
        sign = 1.0 if entry.side == "left" else -1.0
        u_in, t1, turn, rho = self.wrap(cable, peg, entry, following)
        centre = _vec(peg.position)
        centre[2] = t1[2]
        used = float(np.linalg.norm(t1 - cable.contact)) + rho * turn
        normal = _turn(u_in, sign * math.pi / 2.0)  # from the tangent point towards the axis
        t2 = centre + _turn(-normal * rho, sign * turn)
        cable.contact, cable.s_contact = t2, cable.s_contact + used
        return used

    def plan_peg(
        self, cable: _Cable, entry: RouteEntry, peg: BoardFixture, following: RouteEntry | None
    ) -> None:
        sign = 1.0 if entry.side == "left" else -1.0
        u_in, t1, turn, rho = self.wrap(cable, peg, entry, following)
        to_peg = float(np.linalg.norm(_flat(t1 - cable.contact)))
        lead = PEG_LEAD
        if turn > math.pi:
            # the winding passes over the span into the peg: the gripper goes round beyond it
            lead = max(lead, to_peg + FINGER_CLEARANCE)
        need = to_peg + rho * turn + lead
        self.ensure_free(cable, need, "to pass the peg")
        # the height at which the cable passes the peg, and the gripper's height for it
        base, top = peg.position[2], peg.position[2] + peg.height
        lo, hi = base + cable.spec.radius + 0.003, top - cable.spec.radius - 0.003
        if lo > hi:
            raise self.fail(
                cable, f"the peg is {peg.height:.3f} m high, too low to catch the cable"
            )
        crossings = max(0, math.ceil((turn + CROSS_MARGIN - 2.0 * math.pi) / (2.0 * math.pi)))
        climb = crossings * CROSS_CLIMB * 2.0 * cable.spec.radius
        hi -= climb
        if lo > hi:
            raise self.fail(
                cable,
                f"the peg is {peg.height:.3f} m high, too low to wind the cable "
                f"{math.degrees(turn):.0f} deg round it (it climbs {climb * 1e3:.0f} mm "
                f"over its own strand)",
            )
        c = cable.contact
        # the lowest pass height (from the cable's own height up) whose sweep and
        # winding keep the cable over every other fixture
        z_pass = min(max(float(c[2]), lo), hi)
        while True:
            motion = self.peg_motion(cable, entry, peg, following, u_in, turn, rho, to_peg, z_pass)
            if motion.collision is None or z_pass >= hi:
                break
            z_pass = min(z_pass + PASS_STEP, hi)
        if motion.collision is not None and motion.collision.fixture == OWN_SPAN:
            raise self.fail(
                cable,
                f"winding round the peg takes the gripper through the cable's own span into "
                f"it (expected the gripper at least {FINGER_CLEARANCE:g} m beside that span or "
                f"above it; hold the cable further out or the peg higher)",
            )
        if motion.collision is not None and _hits_gripper(motion.collision):
            hit = motion.collision
            raise self.fail(
                cable,
                f"{motion.what} takes the cable into {hit.fixture}, which stands there while "
                f"this cable is routed: the cable passes it at z = {hit.height:.3f} m, above "
                f"the bottom of its fingers at {hit.needed:.3f} m",
            )
        if motion.collision is not None and motion.collision.sensed:
            hit = motion.collision
            raise self.fail(
                cable,
                f"{motion.what} passes the cable by {hit.fixture} at z = {hit.height:.3f} m, "
                f"where its pull would read as bearing on {hit.fixture} (expected at least "
                f"{hit.needed:.3f} m there), and the cable cannot pass the peg higher than "
                f"z = {hi:.3f} m",
            )
        if motion.collision is not None:
            hit = motion.collision
            why = f" ({climb * 1e3:.0f} mm lower, for the winding's climb over its own strand)"
            raise self.fail(
                cable,
                f"{motion.what} takes the {hit.by} into {hit.fixture}: it passes at z = "
                f"{hit.height:.3f} m, {_needs(hit)}, and the "
                f"cable cannot pass the peg higher than z = {hi:.3f} m" + (why if climb else ""),
            )
        last = self.fixtures.get(cable.last) if cable.last else None
        if last is not None and last.kind == "clip":
            for point, why in motion.moves:
                run = float(np.linalg.norm(_flat(point - c)))
                rise = math.atan2(float(point[2] - c[2]), max(run, 1e-6))
                if rise > CLIP_RISE:
                    raise self.fail(
                        cable,
                        f"to {why}, the gripper at z = {float(point[2]):.3f} m pulls the cable up "
                        f"out of {last.name} at {math.degrees(rise):.0f} deg (the clip holds it "
                        f"to {math.degrees(CLIP_RISE):.0f} deg)",
                    )
        if following is not None and motion.rest < MIN_WIND:
            raise self.fail(
                cable,
                f"the cable bends only {math.degrees(motion.rest):.0f} deg round the peg after "
                f"the catch before it would point at {following.fixture} (expected at least "
                f"{math.degrees(MIN_WIND):.0f} deg: I finds the peg that the next step aims from)",
            )
        if motion.z_grip < TABLE_CLEARANCE:
            raise self.fail(
                cable,
                f"the cable from {_fmt(c)} can pass the peg only below z = {hi:.3f} m, and "
                f"the gripper would go down to z = {motion.z_grip:.3f} m (expected at least "
                f"{TABLE_CLEARANCE:g} m above the board)",
            )
        if entry.wind and motion.rest > SMALL_TURN and motion.z_grip > top + WIND_ABOVE:
            raise self.fail(
                cable,
                f"winding a full turn with the gripper at z = {motion.z_grip:.3f} m, "
                f"{(motion.z_grip - top) * 1e3:.0f} mm over the peg's top (expected at most "
                f"{WIND_ABOVE * 1e3:.0f} mm: higher, the span lifts the wrap off the peg; the "
                "cable passes the peg no lower clear of the board)",
            )
        for point, _ in motion.moves:
            self.check_reach(cable, point, "catching the peg")
        for point in motion.wind:
            self.check_reach(cable, point, "winding round the peg")
        for k, (point, why) in enumerate(motion.moves):
            if k < motion.catch_from:
                self.emit_move(cable, point, why)
            else:
                # the last move of the catch hands the peg to the model
                catches = k == len(motion.moves) - 1
                self.emit_move(
                    cable, point, why, observe=False, **({"catch": peg.name} if catches else {})
                )
        cable.gripper = motion.catch
        rest = motion.rest
        if rest > SMALL_TURN:
            # the moves kept the gripper's orientation while the cable swept round
            self.emit(cable, "gripper_alignment", "align the gripper with the cable", arm=cable.arm)
            radius = float(np.linalg.norm(_flat(motion.catch - _vec(peg.position))))
            centre = _vec(peg.position)
            centre[2] = motion.z_grip
            start = _flat(motion.catch - centre)
            turns = (
                f", {entry.wind} full turn{'s' if entry.wind != 1 else ''}" if entry.wind else ""
            )
            self.emit(
                cable,
                "rotate_around_feature_point",
                f"wind the cable round the peg ({math.degrees(rest):.0f} deg{turns})",
                arm=cable.arm,
                angle=sign * rest,
                axis=[0.0, 0.0, 1.0],
                about=peg.name,
            )
            left = max(radius - rho * rest, MIN_LEAD)
            cable.gripper = centre + _turn(_unit(start), sign * rest) * left
        self.advance_peg(cable, peg, entry, following)
        # a winding leaves the peg on top of its own strand (random board
        # 1991395197: wound 352 deg round F1 at 97 mm, the cable left it at
        # about 108 mm and rose 16.7 deg to the next clip, too steep for F)
        cable.contact[2] = z_pass + crossings * LEAVE_CLIMB * 2.0 * cable.spec.radius
        cable.lay(peg.name)
        if entry.wind:
            cable.s_held = cable.s_contact  # a full turn holds the cable by its friction

    def peg_motion(
        self,
        cable: _Cable,
        entry: RouteEntry,
        peg: BoardFixture,
        following: RouteEntry | None,
        u_in: FloatArray,
        turn: float,
        rho: float,
        to_peg: float,
        z_pass: float,
    ) -> _PegMotion:
        """The moves that catch ``peg`` with the cable at ``z_pass`` [m], and the winding after.

        The moves sweep the cable about the last fixed point onto the peg from
        the side the route asks for, after lifting it over the peg if it lies
        on the other side; the winding (I) turns the gripper round the peg.
        Every position of the taut cable on the way is checked against the
        board's other fixtures (the first collision is returned).
        """
        sign = 1.0 if entry.side == "left" else -1.0
        c = cable.contact
        top = peg.position[2] + peg.height
        reach = cable.free - rho * CATCH  # from the last fixed point to the gripper, caught
        z_grip = float(c[2]) + (z_pass - float(c[2])) * reach / max(to_peg, 1e-6)
        u_catch = _turn(u_in, sign * CATCH)
        horizontal = math.sqrt(max(reach * reach - (z_grip - float(c[2])) ** 2, 1e-6))
        catch = c + u_catch * horizontal
        catch[2] = z_grip
        u_now = _unit(_flat(cable.gripper - c))
        u_peg = _unit(_flat(_vec(peg.position) - c))
        peg_side = _cross_z(u_now, u_peg) * sign  # > 0: the peg lies on the wanted side
        moves: list[tuple[FloatArray, str]] = []
        start = cable.gripper
        if peg_side > 0.0:
            # first to the height the cable catches the peg at: a slide and
            # a tension before leave the gripper where the cable's direction
            # takes it (random boards 1652323633 and 1808415002: 75-80 mm
            # up, from where the sweep carried the cable over the peg's top)
            start = cable.gripper.copy()
            start[2] = z_grip
            moves.append((start, "bring the cable to the height it catches the peg at"))
        if peg_side <= 0.0:  # the peg is on the other side: lift the cable over it
            clear = top + OVER_PEG
            z_lift = float(c[2]) + (clear - float(c[2])) * reach / max(to_peg, 1e-6)
            lifted = cable.gripper.copy()
            lifted[2] = max(z_lift, float(lifted[2]))
            beside = c + _turn(u_in, -sign * CATCH) * horizontal  # clear of the peg
            beside[2] = lifted[2]
            moves.append((lifted, "lift the cable over the peg"))
            moves += [
                (p, "carry the cable over the peg") for p in self.arc(c, lifted, beside, -sign)
            ]
            start = beside.copy()
            start[2] = z_grip
            moves.append((start, "lower the cable beside the peg, on the route's side"))
        # the approach up to TOUCH short of the tangent is observed (it pivots
        # about the last fixed point); the catch, where the bend grows, is not
        touch = c + _turn(u_in, -sign * TOUCH) * horizontal
        touch[2] = z_grip
        to_touch = _swept(_flat(start - c), _flat(touch - c), sign)
        catch_from = len(moves)
        if SMALL_TURN < to_touch < math.pi:
            moves += [
                (p, "sweep the cable towards the peg") for p in self.arc(c, start, touch, sign)
            ]
            catch_from = len(moves)
            moves.append((catch, "sweep the cable onto the peg"))
        else:
            moves += [(p, "sweep the cable onto the peg") for p in self.arc(c, start, catch, sign)]
        skip = frozenset({peg.name} | ({cable.last} if cable.last else set()))
        collision = self.path_collision(cable, c, cable.gripper, [p for p, _ in moves], skip)
        what = "catching the peg"
        wind: list[FloatArray] = []
        rest = turn - CATCH
        nxt = None if following is None else self.fixtures.get(following.fixture)
        if nxt is not None and nxt.kind == "clip":
            # wind until the gripper points short of the clip by short_of(), about the peg
            axis = _vec(peg.position)
            aim = _turn(
                _unit(_flat(_vec(nxt.position) - axis)), -sign * self.short_of(peg, following)
            )
            swept = _swept(_flat(catch - axis), aim, sign)
            # the catch is past the aim already where the sweep to it exceeds
            # the taut wrap by more than half a turn: random board 1522202503
            # (seed 10) passed F5 nearly straight (a 2 deg wrap), caught it
            # 37 deg past the aim and wound 323 deg round it, 50 mm of cable
            # the length budget did not have, and F6 was out of reach
            if swept > turn - 2.0 * math.pi * entry.wind + math.pi:
                swept -= 2.0 * math.pi
            rest = max(swept + 2.0 * math.pi * entry.wind, 0.0)
        if collision is None and rest > SMALL_TURN:
            centre = _vec(peg.position)
            centre[2] = z_grip
            arm = _flat(catch - centre)
            n = max(8, math.ceil(rest / math.radians(5.0)))
            wind = [centre + _turn(arm, sign * rest * k / n) for k in range(1, n + 1)]
            pivot = _vec(peg.position)
            pivot[2] = z_pass
            around = self.overlapping(frozenset({peg.name}))
            for point in wind:
                flat = _flat(point)
                span = nearest_on_segment(flat, _flat(c), _flat(_vec(peg.position)))
                gap = float(np.linalg.norm(flat - span))
                if gap < FINGER_CLEARANCE and z_grip < float(c[2]) + FINGER_CLEARANCE:
                    collision = Collision(OWN_SPAN, z_grip, float(c[2]) + FINGER_CLEARANCE)
                    what = "winding round the peg"
                    break
                collision = (
                    segment_collision(
                        pivot, point, self.problem.fixtures, cable.spec.radius, around, sensed=True
                    )
                    or gripper_collision(point, self.problem.fixtures, around)
                    or self.tail_hit(cable, point, pivot, around)
                    or self.laid_hit(cable, point)
                    or parked_collision(pivot, point, self.parked_other(cable), cable.spec.radius)
                )
                if collision is not None:
                    what = "winding round the peg"
                    break
        return _PegMotion(moves, catch, wind, z_grip, collision, what, catch_from, rest)

    def tail_hit(
        self, cable: _Cable, gripper: FloatArray, pivot: FloatArray, skip: frozenset[str]
    ) -> Collision | None:
        """:func:`tail_collision` where the cable runs on past the gripper (beyond ``TAIL``)."""
        if cable.spec.length - cable.at <= TAIL:
            return None
        return tail_collision(gripper, pivot, self.problem.fixtures, cable.spec.radius, skip)

    def hanging_tail_hit(
        self, cable: _Cable, start: FloatArray, end: FloatArray, distance: float
    ) -> Collision | None:
        """:func:`hanging_tail_collision` for a slide of ``distance`` [m] from ``start`` to ``end``.

        The tail is what is left past the gripper at the slide's end; the
        fixture the cable leaves (and any overlapping it) is not checked.
        """
        tail = cable.spec.length - cable.at - distance
        if tail <= TAIL:
            return None
        skip = self.overlapping(frozenset(n for n in (cable.last,) if n is not None))
        return hanging_tail_collision(
            start, end, tail, self.problem.fixtures, cable.spec.radius, skip
        )

    def short_of(self, peg: BoardFixture, following: RouteEntry | None) -> float:
        """Angle [rad] by which a winding stops short of pointing at the next entry, a clip.

        Pointing at the clip, the cable (or, sliding out, the gripper) would
        run into it; the move that brings the cable over the clip turns the rest.
        """
        nxt = None if following is None else self.fixtures.get(following.fixture)
        if nxt is None or nxt.kind != "clip":
            return 0.0
        d = float(np.linalg.norm(_flat(_vec(nxt.position) - _vec(peg.position))))
        clear = fixture_reach(nxt) + GRIPPER_CLEARANCE + 0.015
        return math.asin(min(1.0, clear / max(d, 1e-6)))

    def overlapping(self, names: frozenset[str]) -> frozenset[str]:
        """``names`` and every fixture whose body overlaps theirs (alternatives on one spot)."""
        out = set(names)
        for a in names:
            fa = self.fixtures.get(a)
            if fa is None:
                continue
            for f in self.problem.fixtures:
                gap = float(np.linalg.norm(_flat(_vec(f.position) - _vec(fa.position))))
                if gap < fixture_reach(f) + fixture_reach(fa):
                    out.add(f.name)
        return frozenset(out)

    def require_clear(
        self,
        cable: _Cable,
        pivot: FloatArray,
        start: FloatArray,
        waypoints: list[FloatArray],
        what: str,
        target: str | None = None,
        fingers: bool = False,
    ) -> None:
        """Fail unless the taut cable from ``pivot`` clears the board on the gripper's way.

        The fixture the cable leaves and ``target`` (the one it is aimed at)
        are not checked; with ``fingers``, the gripper and the tail beyond
        it are checked against ``target`` too.
        """
        skip = frozenset(n for n in (cable.last, target) if n is not None)
        held = frozenset(n for n in (cable.last,) if n is not None) if fingers else None
        hit = self.path_collision(cable, pivot, start, waypoints, skip, held)
        if hit is not None:
            raise self.fail(
                cable,
                f"{what} takes the {hit.by} into {hit.fixture}: it passes at z = "
                f"{hit.height:.3f} m, {_needs(hit)} there "
                f"(expected the swept cable and the gripper clear of every other fixture)",
            )

    def path_collision(
        self,
        cable: _Cable,
        pivot: FloatArray,
        start: FloatArray,
        waypoints: list[FloatArray],
        skip: frozenset[str],
        gripper_skip: frozenset[str] | None = None,
    ) -> Collision | None:
        """The first fixture the taut cable from ``pivot`` (or its gripper) runs into.

        The gripper moves from ``start`` through ``waypoints``, straight
        between them. ``gripper_skip`` (default ``skip``): the fixtures the
        gripper and the tail beyond it are not checked against.
        """
        skip = self.overlapping(skip)
        held_skip = skip if gripper_skip is None else self.overlapping(gripper_skip)
        previous = start
        for point in waypoints:
            for k in range(1, 9):
                g = previous + (point - previous) * (k / 8.0)
                hit = segment_collision(pivot, g, self.problem.fixtures, cable.spec.radius, skip)
                if hit is None:
                    hit = self.held_hit(cable, g, pivot, held_skip)
                if hit is None:
                    hit = parked_collision(pivot, g, self.parked_other(cable), cable.spec.radius)
                if hit is not None:
                    return hit
            previous = point
        return None

    def held_hit(
        self, cable: _Cable, gripper: FloatArray, pivot: FloatArray, skip: frozenset[str]
    ) -> Collision | None:
        """The fixture (if any) the gripper at ``gripper`` [m] or the tail beyond it runs into.

        Or a laid cable span its fingers would catch (:meth:`laid_hit`).
        """
        hit = gripper_collision(gripper, self.problem.fixtures, skip)
        if hit is None:
            hit = self.tail_hit(cable, gripper, pivot, skip)
        if hit is None:
            hit = self.laid_hit(cable, gripper)
        return hit

    def laid_hit(self, cable: _Cable, gripper: FloatArray) -> Collision | None:
        """The laid cable span (if any) the fingers of a gripper at ``gripper`` [m] catch.

        A span laid between two fixed points (either cable's, the one being
        routed up to its last fixed point) lies no higher than the straight
        line between them. The fingers catch it where the tool centre point
        passes within ``FINGER_CLEARANCE`` of it horizontally with the pads'
        bottom lower than its top plus ``CLEARANCE``. Random board 604736314
        (seed 10): the sweep onto peg F3 ended, and the winding round it
        ran, with the fingers at 80 mm across W1's first span, anchor A1 to
        clip F1, at 80 mm; they dragged it, and the pull on clip F2 rose to
        43 N (the protective stop read 23 N at the gripper).
        """
        g = _flat(gripper)
        for other in [*self.routed, cable]:
            laid = other.laid
            for k in range(len(laid) - 1):
                (name_a, a), (name_b, b) = laid[k], laid[k + 1]
                if other is cable and k == len(laid) - 2:
                    length = float(np.linalg.norm(_flat(b - a)))
                    if length <= LAID_TRIM:
                        continue
                    b = a + (b - a) * (1.0 - LAID_TRIM / length)
                t = _along(_flat(a), _flat(b), g)
                on = a + t * (b - a)
                if float(np.linalg.norm(g - _flat(on))) >= FINGER_CLEARANCE:
                    continue
                needed = float(on[2]) + other.spec.radius + CLEARANCE + PAD_DEPTH
                if float(gripper[2]) < needed:
                    span = f"{other.spec.name}'s span from {name_a} to {name_b}"
                    return Collision(span, float(gripper[2]), needed, "gripper")
        return None

    def held_in_clip(self, cable: _Cable, point: FloatArray) -> FloatArray:
        """``point`` [m], lowered where the cable would rise from its clip beyond ``CLIP_RISE``.

        Out of a clip, a gripper higher than that pulls the cable up out of
        the jaws (random board 355974382, seed 15: after the slide out of
        F6 the planner put the gripper 80 mm higher than it was, at z =
        185 mm, and the first move over F7 went up to 155 mm, 20 deg over
        F6's exit; the cable came out of the 1.9 N clip, and the move ended
        before the model saw it: a false success).
        """
        last = self.fixtures.get(cable.last) if cable.last else None
        if last is None or last.kind != "clip":
            return point
        c = cable.contact
        top = float(c[2]) + float(np.linalg.norm(_flat(point - c))) * math.tan(CLIP_RISE)
        if float(point[2]) <= top:
            return point
        lowered = point.copy()
        lowered[2] = top
        return lowered

    def arc(
        self, c: FloatArray, start: FloatArray, end: FloatArray, sign: float
    ) -> list[FloatArray]:
        """Waypoints to ``end`` (included), turning the ``sign`` way about ``c`` from ``start``."""
        a = _flat(start - c)
        b = _flat(end - c)
        swept = _swept(a, b, sign)
        if swept > math.pi * 1.5:  # the short way round is the other way: go straight
            return [end]
        n = max(1, math.ceil(swept / SWEEP_STEP))
        points: list[FloatArray] = []
        ra, rb = float(np.linalg.norm(a)), float(np.linalg.norm(b))
        for k in range(1, n + 1):
            t = k / n
            p = c + _turn(_unit(a), sign * swept * t) * ((1.0 - t) * ra + t * rb)
            p[2] = (1.0 - t) * float(start[2]) + t * float(end[2])
            points.append(p)
        points[-1] = end.copy()
        return points

    # -- clips

    def slot_line(self, cable: _Cable, clip: BoardFixture) -> tuple[FloatArray, FloatArray]:
        """The slot's direction away from the last fixed point, and its exit."""
        slot = np.array([math.cos(clip.yaw), math.sin(clip.yaw), 0.0])
        seat = _vec(clip.position)
        along = _flat(seat - cable.contact)
        if float(np.linalg.norm(along)) < 0.5 * clip.length + 0.01:
            raise self.fail(cable, "the clip lies at the cable's last fixed point")
        if float(along @ slot) < 0.0:
            slot = -slot
        return slot, seat + 0.5 * clip.length * slot

    def advance_clip(self, cable: _Cable, clip: BoardFixture) -> None:
        _, exit_point = self.slot_line(cable, clip)
        cable.s_contact += float(np.linalg.norm(exit_point - cable.contact))
        cable.contact = exit_point
        cable.lay(clip.name)
        self.clips_used[clip.name] = cable.spec.name

    def crossing(self, cable: _Cable, clip: BoardFixture, slot: FloatArray) -> float:
        """The angle [rad] at which the taut cable crosses ``clip``'s slot.

        From the cable's last fixed point; out of a clip, from the virtual
        corner ``BEND_RUN`` ahead of its exit, along its slot (the cable runs
        on straight there before it turns).
        """
        far = cable.contact
        last = None if cable.last is None else self.fixtures.get(cable.last)
        if last is not None and last.kind == "clip":
            way = _flat(cable.contact - _vec(last.position))
            if float(np.linalg.norm(way)) > 1e-9:
                far = far + BEND_RUN * _unit(way)
        along = _unit(_flat(_vec(clip.position) - far))
        return math.acos(min(1.0, abs(float(along @ slot))))

    def turn_out_of_clip(self, cable: _Cable, clip: BoardFixture) -> float:
        """The turn [rad] the cable makes out of the clip it last left towards ``clip``'s seat.

        0 where it last left no clip.
        """
        last = None if cable.last is None else self.fixtures.get(cable.last)
        if last is None or last.kind != "clip":
            return 0.0
        way = _flat(cable.contact - _vec(last.position))
        line = _flat(_vec(clip.position) - cable.contact)
        if float(np.linalg.norm(way)) < 1e-9 or float(np.linalg.norm(line)) < 1e-9:
            return 0.0
        return math.acos(min(1.0, max(-1.0, float(_unit(way) @ _unit(line)))))

    def beyond_f(self, cable: _Cable, single: bool, beyond: bool, why: str) -> bool:
        """Whether F still presses the clip in where ``beyond`` says it is past one of F's limits.

        Past it, C does where the other gripper can; else the route is
        refused: ``why`` (the limit passed) and what keeps the other gripper.
        """
        if not (single and beyond):
            return single
        if not self.other_arm_available(cable):
            raise self.fail(
                cable, f"{why} and C needs the other gripper, but {self.why_other_busy(cable)}"
            )
        return False

    def plan_clip(self, cable: _Cable, clip: BoardFixture) -> None:
        slot, exit_point = self.slot_line(cable, clip)
        angle = self.crossing(cable, clip, slot)
        seat = _vec(clip.position)
        c = cable.contact
        run = float(np.linalg.norm(_flat(seat - c)))
        slope = math.atan2(float(c[2] - seat[2]), run)
        if abs(slope) > MAX_ANGLE:
            raise self.fail(
                cable,
                f"the cable would reach the clip at {math.degrees(slope):.0f} deg from its last "
                f"fixed point at {_fmt(c)} (expected at most {math.degrees(MAX_ANGLE):.0f} deg)",
            )
        single = angle <= F_ANGLE or (angle <= SLOT_ANGLE and not self.other_arm_available(cable))
        rise = far_rise(c, seat, slot, 0.5 * clip.length)
        # F's own precondition: steeper, the far side holds the slot's entry
        # end up in the jaws' throat (single_arm_clipping.py)
        single = self.beyond_f(
            cable,
            single,
            rise > MAX_FAR_RISE,
            f"the cable rises {math.degrees(rise):.1f} deg from the clip to its last fixed "
            f"point at {_fmt(c)} (F clips at most {math.degrees(MAX_FAR_RISE):.0f} deg)",
        )
        last = None if cable.last is None else self.fixtures.get(cable.last)
        if last is not None and last.kind == "peg":
            single = self.beyond_f(
                cable,
                single,
                angle > PEG_F_ANGLE,
                f"the slot is {math.degrees(angle):.1f} deg across the cable's line from peg "
                f"{last.name} (F seats at most {math.degrees(PEG_F_ANGLE):.0f} deg from a peg, "
                "whose leave point moves round it by a few mm)",
            )
        kink = math.acos(min(1.0, math.cos(angle) * math.cos(rise)))
        single = self.beyond_f(
            cable,
            single,
            kink > F_KINK,
            f"the cable reaches the clip {math.degrees(angle):.1f} deg across its slot and "
            f"rising {math.degrees(rise):.1f} deg from its last fixed point at {_fmt(c)}: a "
            f"kink of {math.degrees(kink):.1f} deg at the entry (F clips at most "
            f"{math.degrees(F_KINK):.0f} deg)",
        )
        if single:
            if angle > F_ANGLE:
                self.steep_single += 1
            self.plan_single_clip(cable, clip, exit_point)
        else:
            if angle > C_ANGLE:
                raise self.fail(
                    cable,
                    f"the slot is {math.degrees(angle):.0f} deg across the cable's line from "
                    f"{_fmt(c)} (C turns the cable onto a slot by at most "
                    f"{math.degrees(C_ANGLE):.0f} deg; a peg before the clip would turn it)",
                )
            turn = self.turn_out_of_clip(cable, clip)
            if turn > C_TURN:
                raise self.fail(
                    cable,
                    f"the cable turns {math.degrees(turn):.0f} deg out of {cable.last} towards "
                    f"the clip (C clips at most {math.degrees(C_TURN):.0f} deg on from a clip; "
                    "a peg between would take the turn)",
                )
            other = self.other_arm_free(cable)
            if other is None:
                raise self.fail(
                    cable,
                    f"the slot is {math.degrees(angle):.0f} deg across the cable's line from "
                    f"{_fmt(c)} (F seats at most {math.degrees(SLOT_ANGLE):.0f} deg) and C needs "
                    f"the other gripper, but {self.why_other_busy(cable)}",
                )
            self.plan_parallel_clip(cable, clip, slot, exit_point, other)
        self.clips_used[clip.name] = cable.spec.name

    def press_plan(
        self, cable: _Cable, clip: BoardFixture, exit_point: FloatArray, r: float
    ) -> float:
        """The largest press [N] F can make on ``clip`` with the gripper ``r`` [m] past its exit."""
        c = cable.contact
        exit_top = exit_point.copy()
        exit_top[2] = clip.position[2] + JAW_TOP
        far = c - exit_top
        span = float(np.linalg.norm(far)) + r
        k_span = cable.spec.stiffness * cable.spec.length / max(span, 1e-3)
        plan = PivotPress(
            radius=r,
            tension=self.problem.tension,
            stiffness=k_span,
            drop=float(exit_top[2]) - TABLE_CLEARANCE,
            sin_far=float(far[2]) / max(float(np.linalg.norm(far)), 1e-9),
            sin_max=math.sin(MAX_ANGLE),
        )
        limit = self.robot.force_limit
        wanted = push_tension(clip.push_force, self.problem.tension, limit)
        return plan.press(plan.tension_for(clip.push_force, wanted, 0.6 * limit))

    def plan_single_clip(self, cable: _Cable, clip: BoardFixture, exit_point: FloatArray) -> None:
        c = cable.contact
        to_exit = float(np.linalg.norm(exit_point - c))
        needed = PRESS_MARGIN * clip.push_force
        if self.press_plan(cable, clip, exit_point, MIN_LEAD) < needed:
            best = self.press_plan(cable, clip, exit_point, MIN_LEAD)
            raise self.fail(
                cable,
                f"the seat at z = {clip.position[2]:.3f} m leaves too little height to press the "
                f"cable in: bending it over the clip presses at most {best:.1f} N of the "
                f"{needed:.1f} N needed (the gripper stays {TABLE_CLEARANCE:g} m above the board)",
            )
        if cable.free < to_exit + MIN_LEAD:
            # slide out only so far that F's pivot clears the board
            lead = self.clear_pivot_radius(cable, clip, exit_point, LEAD)
            self.ensure_free(cable, to_exit + MIN_LEAD, "to clip", lead=lead)
        r = cable.free - to_exit
        if self.press_plan(cable, clip, exit_point, r) < needed:
            # held too far out: grasp nearer with the other gripper
            r_ok = self.closest_press_radius(cable, clip, exit_point, r, needed)
            if cable.s_contact + to_exit + r_ok < cable.at - GRASP_MARGIN:
                # within the grippers' margin the press falls a little short
                # of PRESS_MARGIN, and F judges the snap it gets at run time
                r = self.push_hand_over(cable, to_exit, r_ok, "to press the clip in")
        hit = self.pivot_collision(cable, clip, exit_point, r)
        if hit is not None:
            r_ok = self.clear_pivot_radius(cable, clip, exit_point, r)
            why = ""
            if self.pivot_collision(cable, clip, exit_point, r_ok) is not None:
                why = "however near the clip it holds the cable"
            elif self.other_arm_free(cable) is None:
                why = (
                    f"held {r:.3f} m past the clip (clear within {r_ok:.3f} m), and no "
                    f"hand-over is possible: {self.why_other_busy(cable)}"
                )
            if why:
                raise self.pivot_error(cable, clip, hit, why)
            r = self.push_hand_over(cable, to_exit, r_ok, "to press the clip clear")
            hit = self.pivot_collision(cable, clip, exit_point, r)
            if hit is not None:
                raise self.pivot_error(
                    cable, clip, hit, f"held {r:.3f} m past the clip after the hand-over"
                )
        target = self.swing_over_clip(cable, clip, "bring the cable over the clip, along its slot")
        self.emit(cable, "gripper_alignment", "align the gripper with the cable", arm=cable.arm)
        self.emit(
            cable,
            "single_arm_clipping",
            "push the cable into the clip",
            arm=cable.arm,
            clip=clip.name,
        )
        cable.pressed = self.after_push(cable, clip, exit_point, target)
        cable.s_contact += to_exit
        cable.contact = exit_point
        cable.lay(clip.name)

    def swing_over_clip(self, cable: _Cable, clip: BoardFixture, why: str) -> FloatArray:
        """Swing the taut cable about its last fixed point until it runs over the clip's seat.

        The gripper goes round the fixed point at the cable's free length
        (waypoints :meth:`arc`, kept low enough out of a clip) to where the
        straight cable passes ``ABOVE`` over the seat; each waypoint is a
        taut ``move`` described by ``why``.

        Returns:
            The gripper's new position [m] (also set on ``cable``).

        Raises:
            RouteError: The gripper would go below ``TABLE_CLEARANCE`` or out
                of reach, or the swept cable would meet a fixture.
        """
        c = cable.contact
        seat_over = _vec(clip.position) + np.array([0.0, 0.0, ABOVE])
        target = c + _unit(seat_over - c) * cable.free
        if float(target[2]) < TABLE_CLEARANCE:
            raise self.fail(
                cable,
                f"over the clip the cable from {_fmt(c)} takes the gripper down to z = "
                f"{float(target[2]):.3f} m (expected at least {TABLE_CLEARANCE:g} m above the "
                "board)",
            )
        waypoints = self.arc(c, cable.gripper, target, self.turn_sign(c, cable.gripper, target))
        waypoints = [self.held_in_clip(cable, point) for point in waypoints]
        for point in waypoints:
            self.check_reach(cable, point, "bringing the cable over the clip")
        self.require_clear(
            cable, c, cable.gripper, waypoints, "bringing the cable over the clip", clip.name
        )
        for point in waypoints:
            self.emit_move(cable, point, why)
        cable.gripper = target
        return target

    def push_hand_over(self, cable: _Cable, to_exit: float, r: float, what: str) -> float:
        """Hand the cable over ``r`` [m] past the clip's exit for F's push; the new ``r`` [m].

        At least ``MIN_LEAD`` past it; nearer where the grippers' margin
        asks (:meth:`hand_over`).
        """
        at = cable.s_contact + to_exit
        self.hand_over(cable, at + r, what, nearest=at + MIN_LEAD)
        return cable.free - to_exit

    def pivot_error(
        self, cable: _Cable, clip: BoardFixture, hit: Collision, why: str
    ) -> RouteError:
        """The refusal of a clip whose push (F's pivot) runs into ``hit``, saying ``why``."""
        return self.fail(
            cable,
            f"pressing the cable into {clip.name} takes the {hit.by} into {hit.fixture}: it "
            f"passes at z = {hit.height:.3f} m, {_needs(hit)} there, {why}",
        )

    def after_push(
        self, cable: _Cable, clip: BoardFixture, exit_point: FloatArray, aimed: FloatArray
    ) -> FloatArray:
        """Where F leaves the gripper [m]: on the slot's axis, lifted back only to rest.

        F pivots the gripper about the exit raised to the jaws' top, turns it
        onto the slot and lifts it back only to the straight line from the
        last fixed point through the seat, or to where the push began if that
        is lower (``SingleArmClipping``): on a level board level with the
        jaws' top, 10-20 mm below where it was aimed. A slide from there
        runs low (random board 208802845: E after F1 carried the fingers
        onto F3's jaws, and the wrist read the jaws' push with the cable's).
        """
        c = cable.contact
        seat = _vec(clip.position)
        slot, _ = self.slot_line(cable, clip)
        top = exit_point.copy()
        top[2] = float(clip.position[2]) + JAW_TOP
        ahead = float(np.linalg.norm(_flat(aimed - top)))
        radius = math.hypot(ahead, float(aimed[2] - top[2]))
        start = math.atan2(-float(aimed[2] - top[2]), max(ahead, 1e-9))
        rest = math.atan2(float(c[2] - seat[2]), max(float(np.linalg.norm(_flat(seat - c))), 1e-9))
        angle = max(rest, start)
        out: FloatArray = top + radius * (
            math.cos(angle) * slot - math.sin(angle) * np.array([0.0, 0.0, 1.0])
        )
        return out

    def pivot_collision(
        self, cable: _Cable, clip: BoardFixture, exit_point: FloatArray, r: float
    ) -> Collision | None:
        """The first fixture F's push runs into with the gripper ``r`` [m] past the clip's exit.

        F pivots the gripper down about the exit (raised to the jaws' top)
        until it has pressed the clip in (the bend that presses the push
        force with ``PRESS_MARGIN`` at the push tension, and twice
        ``PRESS_EXTRA`` on), at most to the board's clearance or
        ``MAX_ANGLE`` (where no snap comes it goes on down: a gripper that
        then meets a fixture ends the step at the force limit, cleanly),
        first in the vertical
        plane of the line from the last fixed point over the seat, then
        turned onto the slot's axis (:mod:`~tautwire.primitives.slot_swing`):
        both planes are checked. Random board 208802845's F2 pressed the
        cable in its fingers onto F3, the next clip 137 mm on along the slot,
        with 33 N.
        """
        c = cable.contact
        seat = _vec(clip.position)
        slot, _ = self.slot_line(cable, clip)
        exit_top = exit_point.copy()
        exit_top[2] = float(seat[2]) + JAW_TOP
        seat_over = seat + np.array([0.0, 0.0, ABOVE])
        tension = push_tension(clip.push_force, self.problem.tension, self.robot.force_limit)
        # the gripper stands where the cable, stretched by F's push tension,
        # is taut: on along it by the stretch of all the cable from its start
        # or a full winding (the clips before let it slide). Random board
        # 1355239919 (seed 19): F5 planned 45 mm short of F6's centre, the
        # cable (0.38 m of it to the start, 106 N axial) stretched 25 mm at
        # the 7 N push, the gripper stood 21 mm from F6 and the tail
        # pressed F6 with 12 N
        to_exit = float(np.linalg.norm(exit_point - c))
        held = cable.s_contact + to_exit + r - cable.s_held  # the stretching length
        stretch = tension * held / max(cable.spec.stiffness * cable.spec.length, 1e-9)
        start = c + _unit(seat_over - c) * (to_exit + r + stretch)
        reach = float(np.linalg.norm(start - exit_top))  # F keeps this radius
        top = math.atan2(
            -float(start[2] - exit_top[2]), float(np.linalg.norm(_flat(start - exit_top)))
        )
        drop = float(exit_top[2]) - TABLE_CLEARANCE
        bottom = min(MAX_ANGLE, math.asin(min(max(drop / max(reach, 1e-6), 0.0), 1.0)))
        # F stops past the snap: where the bend presses the clip's push force
        # with the margin at the push tension, and a press beyond it
        far = c - exit_top
        sin_far = float(far[2]) / max(float(np.linalg.norm(far)), 1e-9)
        sin_snap = min(PRESS_MARGIN * clip.push_force / tension + sin_far, 1.0)
        snap = math.asin(max(sin_snap, -1.0))
        bottom = min(bottom, snap + 2.0 * PRESS_EXTRA)
        skip = self.overlapping(frozenset(n for n in (cable.last, clip.name) if n is not None))
        up = np.array([0.0, 0.0, 1.0])
        for out in (_unit(_flat(seat - c)), slot):
            for a in np.linspace(top, max(bottom, top), 9):
                point = exit_top + reach * (math.cos(a) * out - math.sin(a) * up)
                # the gripper and its tail: the cable pressed onto this clip
                # may rest on the next one's jaws once it is in (random board
                # 208802845's F1 snapped in so), a gripper pressing onto it may not
                hit = self.held_hit(cable, point, exit_top, skip)
                if hit is None and a <= snap:
                    # but not before: a span that rests on a fixture between
                    # the clip and the gripper bends there, not over the clip
                    # (random board 1996406324, seed 17: F4 held 176 mm past
                    # its exit, F5 under the span 124 mm on at the same
                    # height took 3.3 N, F4 0.45 N, and the cable slipped
                    # off F5's jaws beside F4)
                    hit = segment_collision(
                        exit_top, point, self.problem.fixtures, cable.spec.radius, skip
                    )
                if hit is not None:
                    return hit
        return None

    def clear_pivot_radius(
        self, cable: _Cable, clip: BoardFixture, exit_point: FloatArray, r: float
    ) -> float:
        """The largest gripper distance [m] past the exit, up to ``r``, whose push clears the board.

        ``MIN_LEAD`` where none does.
        """
        for radius in np.linspace(r, MIN_LEAD, 40):
            if self.pivot_collision(cable, clip, exit_point, float(radius)) is None:
                return float(radius)
        return MIN_LEAD

    def closest_press_radius(
        self, cable: _Cable, clip: BoardFixture, exit_point: FloatArray, r: float, needed: float
    ) -> float:
        """The largest gripper distance [m] past the exit, up to ``r``, where F presses enough."""
        for radius in np.linspace(r, MIN_LEAD, 60):
            if self.press_plan(cable, clip, exit_point, float(radius)) >= needed:
                return float(radius)
        return MIN_LEAD

    @staticmethod
    def turn_sign(c: FloatArray, start: FloatArray, end: FloatArray) -> float:
        """The shorter way (+1 counter-clockwise) from ``start`` to ``end`` about ``c``."""
        return 1.0 if _cross_z(_flat(start - c), _flat(end - c)) >= 0.0 else -1.0

    def plan_parallel_clip(
        self,
        cable: _Cable,
        clip: BoardFixture,
        slot: FloatArray,
        exit_point: FloatArray,
        other: Arm,
    ) -> None:
        seat = _vec(clip.position)
        drop = float(seat[2]) + JAW_TOP - PARALLEL_TABLE_CLEARANCE
        bend = min(MAX_ANGLE, math.atan2(max(drop, 0.0), 0.5 * SPAN))
        tension = push_tension(clip.push_force, self.problem.tension, self.robot.force_limit)
        press = 2.0 * tension * math.sin(bend)
        if press < PRESS_MARGIN * clip.push_force:
            raise self.fail(
                cable,
                f"the seat at z = {clip.position[2]:.3f} m leaves too little height for C to "
                f"press the cable in: {press:.1f} N of the {PRESS_MARGIN * clip.push_force:.1f} "
                "N needed",
            )
        snap = math.asin(min(1.0, PRESS_MARGIN * clip.push_force / (2.0 * tension)))
        least = self.near_arc(cable, seat, slot, 0.5 * SPAN, snap) + SPAN
        self.ensure_free(cable, least, "for a parallel clip", lead=MIN_LEAD)
        if other not in self.robot.sensors and cable.arm not in self.robot.sensors:
            raise self.fail(cable, "C needs a force sensor on one of the grippers")
        half = self.parallel_half_span(cable, seat, slot, snap)
        if half > MAX_HALF_SPAN:
            # held so far out that the grippers would stand too wide (the
            # near one by the fixed point): hand the cable over nearer first
            self.hand_over(cable, cable.s_contact + least, "to hold it over the clip for C")
            freed = self.other_arm_free(cable)
            if freed is None:
                raise self.fail(
                    cable, f"C needs the other gripper, but {self.why_other_busy(cable)}"
                )
            other = freed
            half = self.parallel_half_span(cable, seat, slot, snap)
        for point in (seat - half * slot, seat + half * slot):
            self.check_reach(cable, point, "holding the cable over the clip for C")
        bend = min(MAX_ANGLE, math.atan2(max(drop, 0.0), half))
        if 2.0 * tension * math.sin(bend) < PRESS_MARGIN * clip.push_force:
            raise self.fail(
                cable,
                f"C would hold the cable {2.0 * half:.3f} m wide over the clip (the gripper "
                f"holds {cable.free:.3f} m of it past its last fixed point), too wide to bend "
                "it in",
            )
        grasp = cable.at - 2.0 * half
        self.require_clear_pair(cable, clip, slot, half, grasp)
        line = _unit(_flat(cable.gripper - cable.contact))
        if float(line @ _unit(_flat(slot))) < math.cos(C_PAIR_TURN):
            # lay the line the pair grasps along over the clip first: C's
            # turn is then the slot's angle to it (C_ANGLE at most)
            self.swing_over_clip(cable, clip, "swing the cable over the clip for C")
        self.emit(
            cable, "grasp_tensioned", "grasp the cable with the other gripper", arm=other, at=grasp
        )
        self.emit(
            cable,
            "parallel_clipping",
            "press the cable into the clip with both grippers",
            clip=clip.name,
        )
        self.emit(
            cable, "release", "let go with the gripper on the near side of the clip", arm=other
        )
        self.parked[other] = seat - half * slot
        cable.gripper = seat + half * slot
        # the pull after the release draws the near span's slack through the
        # clip (it holds the cable across, not along): the cable then leaves
        # the clip as far along as the taut span reaches, which is where the
        # robot's model puts it, and where later grasps are measured from
        # (random board 1045612557: counted from the grasp, C into F7 left
        # 28 mm of its slack in the plan's arc lengths; with 36 mm by F9, the
        # near gripper of C into F10 held 45 mm of slack past peg F9, and the
        # cable left the peg)
        entry = seat - 0.5 * clip.length * slot
        cable.s_contact += float(np.linalg.norm(entry - cable.contact)) + clip.length
        cable.contact = exit_point
        cable.lay(clip.name)
        self.emit(
            cable,
            "single_arm_tension",
            "keep the cable taut from the clip",
            arm=cable.arm,
            force=self.problem.tension,
        )
        # ... and the far gripper with it, to where that span is taut (random
        # board 1695658280: planned from where C left it, 45 mm from F5's
        # exit with 100 mm of cable past it, the lift before the slide for F6
        # ended 58 mm further on, and the slide ran the gripper into W1's
        # clip F2: 14.2 N)
        out = cable.gripper - exit_point
        if float(np.linalg.norm(out)) < cable.free:
            cable.gripper = exit_point + _unit(out) * cable.free

    def require_clear_pair(
        self, cable: _Cable, clip: BoardFixture, slot: FloatArray, half: float, grasp: float
    ) -> None:
        """Fail where C's grippers, carried over the clip, would run into a fixture.

        Both grippers go straight from where they hold the taut cable (the
        far one at the cable's gripper, the near one ``grasp`` along the
        line from the last fixed point), no higher than they end, to ``half``
        either side of the seat, ``ABOVE`` over it; the free tail runs on
        beyond the far gripper.
        Random board 1652323633's C into F7 carried the far gripper's tail
        into peg F8 (66 N).
        """
        seat = _vec(clip.position)
        lift = np.array([0.0, 0.0, PARALLEL_ABOVE])
        line = cable.gripper - cable.contact
        near0 = cable.contact + line * (grasp - cable.s_contact) / max(cable.free, 1e-9)
        far0 = cable.gripper
        near1, far1 = seat - half * slot + lift, seat + half * slot + lift
        # the slide and the pull before C can leave the grippers lower than
        # planned (board 1652323633's far gripper: planned at 0.147 m, at
        # 0.091 m when C began): they are checked no higher than C holds them
        far0 = np.append(far0[:2], min(float(far0[2]), float(far1[2])))
        near0 = np.append(near0[:2], min(float(near0[2]), float(near1[2])))
        skip = self.overlapping(
            frozenset(n for n in (clip.name, cable.last, cable.fixture) if n is not None)
        )
        for k in range(1, 9):
            near = near0 + (near1 - near0) * (k / 8.0)
            far = far0 + (far1 - far0) * (k / 8.0)
            hit = gripper_collision(near, self.problem.fixtures, skip) or gripper_collision(
                far, self.problem.fixtures, skip
            )
            if hit is None:
                hit = tail_collision(far, near, self.problem.fixtures, cable.spec.radius, skip)
            if hit is not None:
                raise self.fail(
                    cable,
                    f"C's grippers, carried over {clip.name}, would run into {hit.fixture} "
                    f"({hit.by} at z = {hit.height:.3f} m, below {hit.needed:.3f} m)",
                )

    def near_arc(
        self, cable: _Cable, seat: FloatArray, slot: FloatArray, half: float, snap: float
    ) -> float:
        """Cable [m] the near gripper of C grasps past the last fixed point (see below).

        The straight distance from the fixed point to where that gripper
        is when the cable snaps in (``half`` [m] before the seat along the
        slot, bent down by ``snap`` [rad] from the jaws' top), plus
        ``NEAR_SLACK``, plus ``BEND_SLACK`` for its turn into the slot's
        line at that gripper (which holds it along the slot) and for its
        turn out of the last clip's slot; at least ``GRASP_MARGIN``.
        Random board 160974418: C into F4 after C into F3, the cable
        turning 88 deg out of F3's slot and 88 deg into F4's; counted
        with the turn out of F3 alone, the near span went taut on the way
        (14.2 N).
        """
        near = seat - half * slot
        near[2] = float(seat[2]) + JAW_TOP - half * math.tan(snap)
        straight = float(np.linalg.norm(near - cable.contact))
        way = _unit(_flat(near - cable.contact))
        bend = 1.0 - float(way @ _unit(_flat(slot)))  # into the slot, at the near gripper
        last = None if cable.last is None else self.fixtures.get(cable.last)
        if last is not None and last.kind == "clip":  # out of the last clip's slot
            bend += 1.0 - float(way @ _unit(_flat(cable.contact - _vec(last.position))))
        return max(straight + NEAR_SLACK + BEND_SLACK * bend, GRASP_MARGIN)

    def parallel_half_span(
        self, cable: _Cable, seat: FloatArray, slot: FloatArray, snap: float
    ) -> float:
        """Half the distance [m] between C's grippers that leaves the near span straight.

        C centres the cable between the grippers over the seat, the
        grippers ``2 h`` apart along the slot. With the gripper holding
        ``free`` of cable past the last fixed point, the other grasps
        ``free - 2 h`` past it, and the near span from the fixed point to
        that gripper must then be about straight (:meth:`near_arc`): held
        slack, the release leaves it lying loose, and the pull that
        follows drags the slack through the clip (which holds the cable
        across, not along; the 17 deg level anchor-clip scene: 82 mm of
        slack, D pulled the gripper 42 mm out and found the route longer
        than the model's rest length from the clip). ``free`` then fixes
        h, at least ``SPAN / 2`` (:meth:`ensure_free` slides out enough).
        """
        lo, hi = 0.5 * SPAN, 0.5 * cable.free
        if self.near_arc(cable, seat, slot, lo, snap) + 2.0 * lo >= cable.free:
            return lo
        for _ in range(60):  # near_arc changes by less than 1 per unit of h: monotonic
            mid = 0.5 * (lo + hi)
            if self.near_arc(cable, seat, slot, mid, snap) + 2.0 * mid > cable.free:
                hi = mid
            else:
                lo = mid
        return 0.5 * (lo + hi)

    # -- length: slide out and hand over

    def ensure_free(self, cable: _Cable, need: float, what: str, lead: float = LEAD) -> None:
        """Slide the cable out (E) until ``need`` [m] of it lies past the last fixed point.

        The slide goes ``lead - MIN_LEAD`` [m] beyond ``need``.
        """
        if cable.free >= need:
            return
        distance = need - cable.free
        if cable.at + distance > cable.spec.length - TAIL + 1e-9:
            total = cable.s_contact + need
            raise self.fail(
                cable,
                f"the cable is too short: {what} it needs {total:.3f} m of cable from its start "
                f"(the route so far {cable.s_contact:.3f} m plus {need:.3f} m), it is "
                f"{cable.spec.length:.3f} m long",
            )
        least = distance
        distance = min(distance + max(lead - MIN_LEAD, 0.0), cable.spec.length - TAIL - cable.at)
        ahead = _unit(cable.gripper - cable.contact)
        # the free tail hangs from the fingers: a slide that ends over a
        # fixture lays the tail on it (random board 303464894: the slide
        # out of F4 towards F5 ended 16 mm from the centre of F6 beyond; the
        # tail caught in F6's jaws, pulled the wrist to 11.5 N and was
        # dragged out of the fingers); the lead beyond what is needed gives
        # way first
        below = [
            f for f in self.problem.fixtures if f.name != cable.last and fixture_top(f) is not None
        ]
        for d in np.linspace(distance, least, 9):
            end = _flat(cable.gripper + ahead * float(d))
            if all(
                float(np.linalg.norm(end - _flat(_vec(f.position))))
                >= fixture_reach(f) + SLIDE_CLEAR
                for f in below
            ):
                distance = float(d)
                break
        else:
            distance = least
        if distance < MIN_SLIDE and least <= SLIDE_SKIP:
            return  # within what the plan knows of where the gripper holds the cable
        out = cable.gripper + ahead * distance
        self.check_reach(cable, out, "sliding the cable out")
        # checked from where the gripper really is (F leaves it low); the
        # fixture the slide brings cable towards is not checked: the slide
        # ends short of it, and the moves after it aim the cable over it
        start = cable.gripper if cable.pressed is None else cable.pressed
        skip = frozenset(n for n in (cable.last, cable.fixture) if n is not None)
        # the fingers must clear the fixture the slide brings cable towards
        # too: random board 1808415002's E after F2 slid the gripper 141 mm
        # along F2's slot, over F3 126 mm on, and pulled 25 N
        fingers = frozenset(n for n in (cable.last,) if n is not None)
        low = self.slide_end(cable, start, distance)
        if (
            self.path_collision(cable, cable.contact, start, [low], skip, fingers) is not None
            or self.hanging_tail_hit(cable, start, low, distance) is not None
        ):
            lifted = self.slide_lift(cable, start, distance, skip, fingers)
            if lifted is not None:
                self.emit_move(
                    cable, lifted, "lift the cable clear of the board before sliding it out"
                )
                start = lifted
                low = out = self.slide_end(cable, start, distance)
                self.check_reach(cable, out, "sliding the cable out")
        self.require_clear(
            cable, cable.contact, start, [low], "sliding the cable out", cable.fixture, True
        )
        hit = self.hanging_tail_hit(cable, start, low, distance)
        if hit is not None:
            raise self.fail(
                cable,
                f"sliding the cable out takes the {hit.by}, hanging from the gripper, over "
                f"{hit.fixture} (expected the gripper's way clear of every fixture the tail "
                "could hang onto)",
            )
        ahead_of = self.slide_end_hit(cable, start, low)
        if ahead_of is not None:
            raise self.fail(
                cable,
                f"sliding the cable out {what} ends short of {ahead_of.name}, where the tail "
                "hanging from the fingers lands (expected the slide to end at least "
                f"{SLIDE_CLEAR * 1e3:.0f} mm beyond the reach of every fixture ahead)",
            )
        self.emit(
            cable,
            "single_arm_sliding",
            f"slide out cable {what}",
            arm=cable.arm,
            distance=distance,
            friction_force=self.problem.friction_force,
        )
        self.emit(
            cable,
            "single_arm_tension",
            "pull the cable taut again",
            arm=cable.arm,
            force=self.problem.tension,
        )
        cable.at += distance
        cable.gripper = out

    def slide_lift(
        self,
        cable: _Cable,
        start: FloatArray,
        distance: float,
        skip: frozenset[str],
        gripper_skip: frozenset[str] | None = None,
    ) -> FloatArray | None:
        """A gripper point [m] about the last fixed point from which a slide clears the board.

        The gripper turns up about the last fixed point in steps of
        ``LIFT_STEP``, up to ``CLIP_RISE`` above the horizontal when the
        cable leaves a clip (steeper draws it up out of the jaws), else up
        to ``MAX_ANGLE``; the lowest rise whose lift and slide both clear
        every fixture and stay within reach. Where none does, the same
        rises turned aside about the vertical by ``SIDE_STEP`` steps up to
        ``SIDE_TURN`` (the smallest turn first): a fixture straight on along
        the slide, the next clip of the route, is passed beside. A lift that
        would pull the cable up off the peg it was last laid round
        (:meth:`lifts_off_peg`) is no candidate. None if none does.
        """
        c = cable.contact
        radius = float(np.linalg.norm(start - c))
        horizontal = _unit(_flat(start - c))
        last = self.fixtures.get(cable.last) if cable.last else None
        limit = CLIP_RISE if last is not None and last.kind == "clip" else MAX_ANGLE
        rise0 = math.atan2(float(start[2] - c[2]), float(np.linalg.norm(_flat(start - c))))
        rise0 = max(rise0, 0.0)
        turns = [0.0]
        for k in range(1, round(SIDE_TURN / SIDE_STEP) + 1):
            turns += [k * SIDE_STEP, -k * SIDE_STEP]
        for turn in turns:
            aside = _turn(horizontal, turn)
            rises = [] if turn == 0.0 else [rise0]  # straight on, unlifted: the slide that hit
            rise = rise0
            while rise < limit:
                rise = min(rise + LIFT_STEP, limit)
                rises.append(rise)
            for rise in rises:
                lifted = c + radius * (
                    math.cos(rise) * aside + math.sin(rise) * np.array([0.0, 0.0, 1.0])
                )
                out = self.slide_end(cable, lifted, distance)
                if (
                    self.robot.reach.contains([float(v) for v in lifted])
                    and self.robot.reach.contains([float(v) for v in out])
                    and self.lifts_off_peg(cable, lifted) is None
                    and self.path_collision(cable, c, start, [lifted, out], skip, gripper_skip)
                    is None
                    and self.hanging_tail_hit(cable, lifted, out, distance) is None
                    and self.slide_end_hit(cable, lifted, out) is None
                ):
                    return lifted
        return None

    def slide_end_hit(
        self, cable: _Cable, start: FloatArray, end: FloatArray
    ) -> BoardFixture | None:
        """The fixture (if any) ahead of a slide's end that the tail beyond the fingers lands on.

        A fixture within its reach plus ``SLIDE_CLEAR`` of the end, on the
        far side of it along the slide. Random board 1135846973 (seed 10):
        the slide out of F4 towards F5, turned aside to pass the board,
        ended 32 mm from F6's centre (planned on the straight way, 67 mm);
        the tail caught F6's jaws and the pull through the fingers rose to
        8 N.
        """
        way = _unit(_flat(end - start))
        for f in self.problem.fixtures:
            if f.name == cable.last or fixture_top(f) is None:
                continue
            w = _flat(_vec(f.position) - end)
            if float(np.linalg.norm(w)) < fixture_reach(f) + SLIDE_CLEAR and float(w @ way) > 0.0:
                return f
        return None

    def slide_end(self, cable: _Cable, start: FloatArray, distance: float) -> FloatArray:
        """Where E, started at ``start`` [m], ends after ``distance`` [m].

        E slides along the line from the model's contact through the
        gripper's start: after a clip (F, C) that contact is the clip's
        seat, not the slot's end the cable leaves by, and the line from the
        seat rises less. Random board 1874532039: planned from F5's exit
        through the lifted gripper, the slide was to pass F6 22 mm over its
        jaws; it slid from F5's seat (and from 2.4 mm under its lift, within
        the move's tolerance), passed 6 mm over them, the tail caught in
        F6's jaws and the wrist reached the protective stop (14.5 N).
        """
        last = self.fixtures.get(cable.last) if cable.last else None
        pivot = _vec(last.position) if last is not None and last.kind == "clip" else cable.contact
        return start + _unit(start - pivot) * distance

    def hand_over(self, cable: _Cable, at: float, what: str, nearest: float | None = None) -> None:
        """Hand the cable over: the other gripper grasps at ``at`` [m], the first lets go.

        The grippers grasp at least ``GRASP_MARGIN`` apart and from the last
        fixed point; where ``at`` is nearer the first gripper than that, the
        grasp goes that much nearer the fixed point, down to ``nearest`` [m]
        (arc length; None: no nearer than ``at``).

        Raises:
            RouteError: No grasp keeps those distances.
        """
        other = self.other_arm_free(cable)
        if other is None or other not in self.robot.sensors:
            raise self.fail(
                cable,
                f"the gripper holds the cable {cable.free:.3f} m from its last fixed point, too "
                f"far out {what}, and no hand-over is possible: {self.why_other_busy(cable)}",
            )
        at = max(at, cable.s_contact + GRASP_MARGIN)
        # the grippers grasp at least GRASP_MARGIN apart: a grasp needed
        # nearer the first gripper than that goes that much nearer the fixed
        # point (random board 973985212, seed 26: F1's push needed W1 held
        # 19 mm nearer, the hand-over was skipped, and the fingers, pivoting
        # down 25 mm from the next clip F3, pressed it at 15 N)
        least = max(at if nearest is None else nearest, cable.s_contact + GRASP_MARGIN)
        at = min(at, cable.at - GRASP_MARGIN)
        if at < least - 1e-9:
            raise self.fail(
                cable,
                f"the gripper holds the cable {cable.free:.3f} m from its last fixed point, too "
                f"far out {what}, and too near it for a hand-over (expected the other gripper "
                f"to grasp at least {GRASP_MARGIN:g} m from the first, between "
                f"{least - cable.s_contact:.3f} m and {at - cable.s_contact:.3f} m from the "
                "fixed point)",
            )
        grasp = cable.contact + _unit(cable.gripper - cable.contact) * (at - cable.s_contact)
        self.emit(
            cable,
            "grasp_tensioned",
            f"hand over: grasp nearer the last fixed point {what}",
            arm=other,
            at=at,
        )
        self.emit(cable, "release", "hand over: let go with the first gripper", arm=cable.arm)
        self.holder[cable.arm] = None
        self.parked[cable.arm] = cable.gripper.copy()
        cable.arm, cable.at, cable.gripper = other, at, grasp
        self.holder[other] = cable.spec.name
        self.emit(
            cable,
            "single_arm_tension",
            "pull the cable taut with the new gripper",
            arm=cable.arm,
            force=self.problem.tension,
        )
