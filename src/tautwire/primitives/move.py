"""Move: bring a gripper to a pose between primitives, keeping its cable taut.

Not one of the paper's nine primitives: routing needs motions between them
(SCENARIO.md, "Moves between primitives"): sweeping a held cable onto a peg,
bringing it over a clip, lifting or re-posing a gripper, handing over.
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Sequence

import numpy as np
from numpy.typing import NDArray

from tautwire.control import Pose, quaternion_error
from tautwire.errors import InvalidArgumentError
from tautwire.model.quaternion import as_quaternion
from tautwire.primitives.arm_control import current_pose, tension_twist, with_pose
from tautwire.primitives.context import PrimitiveContext
from tautwire.primitives.low_pass import LowPass
from tautwire.primitives.model_estimator import LEAVE_RUN
from tautwire.primitives.outcome import Outcome
from tautwire.primitives.primitive import Primitive
from tautwire.primitives.slack_watch import SlackWatch
from tautwire.primitives.tool_axis import ToolAxis
from tautwire.robot import Arm, Command, Observation

FloatArray = NDArray[np.float64]

#: Speed [m/s] the timeout allows for the distance to go (the limits allow 0.1 m/s).
TIMEOUT_SPEED = 0.02
#: Time [s] the timeout allows on top of the travel.
TIMEOUT_MARGIN = 8.0
#: A taut move ends with the low-passed tension at least this fraction of its set point.
TENSION_FRACTION = 0.5
#: Horizontal clearance [m] beyond a peg's radius inside which a gripper passing
#: the peg below ``PEG_ABOVE`` over its top would strike it with its fingers or
#: the cable they hold (the planner plans with the same clearance).
PEG_CLEARANCE = 0.02
#: Height [m] over a peg's top at which the tool centre point passes it (the pads
#: reach 8 mm below it).
PEG_ABOVE = 0.015
#: Share of a taut move's speed across the cable that the force loop must
#: take up along it: the error of the measured direction (about 4 deg; the
#: free tail dragged over the board turns the pull aside as the gripper
#: swings it). The gripper crosses the cable at most as fast as the loop,
#: at half the set point's error, takes up that share (:meth:`Move.taut_speed`):
#: a stiff span holds its tension over a fraction of a millimetre. Random
#: board 477145308's W2 (k_hat 2589 N/m, a 0.24 m span of a 759 N cable):
#: swung at 87 mm/s, its tension fell from 2.9 to 0.3 N within 0.2 s and
#: the move ended slack; at 40 mm/s it held.
DIRECTION_LEAK = 0.07
#: Slowest speed [m/s] the cap leaves a taut move (above ``TIMEOUT_SPEED``).
MIN_TAUT_SPEED = 0.025
#: Longest time [s] a taut, observed move holds still at its target for the
#: contact filter's leave check (``LEAVE_RUN`` iterations, twice that while
#: lines say the cable left: 0.4-0.8 s at the runs' 0.04 s filter period).
SETTLE_TIME = 1.0


def peg_detour(
    start: FloatArray,
    target: FloatArray,
    pegs: dict[str, tuple[FloatArray, float, float]],
    skip: frozenset[str] = frozenset(),
) -> list[FloatArray]:
    """Way points [m] that take a gripper from ``start`` to ``target`` over the pegs in its way.

    A peg is in the way where the straight path passes within its radius
    plus :data:`PEG_CLEARANCE` of its axis (horizontally) lower than
    :data:`PEG_ABOVE` over its top, neither end lying within that reach (a
    move that starts or ends by a peg is placed there on purpose). The
    detour rises at the start to the highest such height, crosses at it and
    comes down onto the target. Random board 787338652: the planner expected
    the left gripper 142 mm high after E and D, it stood at 97 mm, and the
    straight move on passed 14 mm from peg F3's axis at its top's height;
    the held cable struck the peg, the fingers were forced 2 mm apart and
    the wrist read 12 N (15.4 N true).

    Args:
        start: The tool centre point [m] where the move begins.  # (3,)
        target: Where it ends [m].  # (3,)
        pegs: name -> (axis point [m] (3,), radius [m], top height [m]).
        skip: Pegs not checked (one the move sweeps the cable onto).

    Returns:
        The way points before ``target`` (none if the path is clear).
    """
    a, b = start[:2], target[:2]
    ab = b - a
    n2 = float(ab @ ab)
    height = -math.inf
    for name, (axis, radius, top) in pegs.items():
        if name in skip:
            continue
        p = axis[:2]
        reach = radius + PEG_CLEARANCE
        if min(float(np.linalg.norm(a - p)), float(np.linalg.norm(b - p))) < reach:
            continue
        t = 0.0 if n2 < 1e-12 else min(1.0, max(0.0, float((p - a) @ ab) / n2))
        if float(np.linalg.norm(a + t * ab - p)) >= reach:
            continue
        z = float(start[2]) + t * float(target[2] - start[2])
        if z < top + PEG_ABOVE:
            height = max(height, top + PEG_ABOVE)
    if height == -math.inf:
        return []
    up = start.copy()
    up[2] = max(float(start[2]), height)
    over = target.copy()
    over[2] = max(float(target[2]), height)
    return [up, over]


class Move(Primitive):
    """Move the gripper on ``arm`` to ``to`` (or by ``by``), optionally turning it.

    With ``taut`` and a gripper that holds a cable and senses it, the cable
    stays under its tension on the way: D's hybrid control, force control
    along the cable (towards the contact it is taut against, measured by
    the force), motion control across it (equ:HybridMFC_combination). The
    target is then reached across the cable; along it the tension decides
    where the gripper stands (the cable's length does, not the target).
    An observed move without an ``orientation`` or a ``catch`` turns the
    tool along the cable as it swings it (G's rule: the shortest arc onto
    the measured direction, paused while the tension is above
    ``PAUSE_TENSION`` times its set point), and leaves the turn out of its
    success test (G after it finishes the turn): a move that kept the
    tool's orientation left random board 1695658280's G 85 deg to turn
    against a cable resting on a clip. A sweep onto a peg keeps the
    orientation (following there, the shipped harness's winding about P2
    after it failed at seed 4).
    Without ``taut``, or with a gripper that holds no cable, it is plain
    motion control to the target pose. The other gripper holds its pose.
    Where the straight way passes a peg of the board design lower than its
    top (the planner plans from where it expects the gripper, which E and
    D may leave tens of millimetres off), the gripper rises first, crosses
    over and comes down onto the target (:func:`peg_detour`).

    Preconditions: with ``taut``, a gripper that holds a cable must be the
    context's sensing gripper (its force is what keeps the tension).
    Model edits: none (the estimator maps the gripper's new position onto
    the path graph; contacts the cable comes to bear on are found as in
    every primitive, unless ``observe`` is off), except with ``catch``: on
    success the named peg enters the model as the sensing gripper's
    contact, at its design position and as uncertain as the design, once
    the gripper moves on with its lines observed (the next primitive's
    lines estimate it or drop it:
    :meth:`~tautwire.primitives.model_estimator.ModelEstimator.expect_peg`).

    Success: the position error (with ``taut``: its part across the
    cable) is within ``tolerance``, the orientation within
    ``angle_tolerance``, and with ``taut`` the cable is still taut (the
    low-passed tension at least half its set point); a taut move whose
    lines are observed then holds still at its target for ``LEAVE_RUN``
    contact-filter iterations (0.4 s), longer while lines say the cable
    left its contact (up to twice that), so that a cable the move drew out
    of a clip fails this move (``left_fixture``), not the next one: random
    board 355974382 (seed 15) reported a move over F7 as a success with the
    cable already out of F6, and the next step's lines found it. A cable
    the move lifts up a peg and off its top leaves the model the same way,
    the peg dropped (its lines, tangent to the peg, are watched for that
    alone), and the move may still succeed: the model then says where the
    cable is. Failure:
    ``slipped`` if a taut cable stays slack for a second;
    ``left_fixture`` if the lines show the cable left a clip;
    ``precondition``; ``timeout``.

    Args:
        arm: The gripper to move.
        to: Target tool centre point [m], world frame.  # (3,)
        by: Offset [m] from the start position (instead of ``to``).  # (3,)
        orientation: Target orientation [w, x, y, z]; default the start's.
        taut: Keep the held cable under tension on the way.
        force: Tension set point [N]; default the context's (from D) or 2 N.
        tolerance: Largest remaining position error [m].
        angle_tolerance: Largest remaining orientation error [rad].
        timeout: Longest run time [s]; default from the distance to go.
        observe: Let the contact filter take the move's force lines. Off
            where the move makes the cable bear on a new fixture on
            purpose (sweeping it onto a peg): while the bend there grows
            from nothing, the lines turn away from the contact the filter
            holds too slowly for a change to show, and would pull its
            estimate off; the primitive after the move estimates the new
            contact.
        catch: The peg of the board design that the move sweeps the
            cable onto (the planner's catch, with ``observe`` off).
    """

    name = "move"
    letter = ""

    def __init__(
        self,
        arm: Arm,
        to: Sequence[float] | None = None,
        by: Sequence[float] | None = None,
        orientation: Sequence[float] | None = None,
        taut: bool = True,
        force: float | None = None,
        tolerance: float = 0.003,
        angle_tolerance: float = math.radians(2.0),
        timeout: float | None = None,
        observe: bool = True,
        catch: str | None = None,
    ) -> None:
        super().__init__(20.0 if timeout is None else timeout)
        if arm not in ("left", "right"):
            raise InvalidArgumentError(f"arm must be 'left' or 'right', got {arm!r}")
        if (to is None) == (by is None):
            raise InvalidArgumentError("a move takes exactly one of 'to' and 'by'")
        goal = np.asarray(to if to is not None else by, dtype=float).reshape(-1)
        if goal.shape != (3,) or not np.all(np.isfinite(goal)):
            raise InvalidArgumentError(f"'to' or 'by' must be 3 finite numbers [m], got {goal}")
        if force is not None and not (force > 0.0 and math.isfinite(force)):
            raise InvalidArgumentError(f"force must be > 0 N, got {force}")
        if not (tolerance > 0.0 and angle_tolerance > 0.0):
            raise InvalidArgumentError("tolerance and angle_tolerance must be > 0")
        self.arm: Arm = arm
        self._goal = goal
        self._absolute = to is not None
        self.orientation = None if orientation is None else as_quaternion(orientation)
        self.taut = bool(taut)
        self.force = force
        self.tolerance = float(tolerance)
        self.angle_tolerance = float(angle_tolerance)
        self._own_timeout = timeout is None
        self.observe = bool(observe)
        self.catch = catch
        self.target = np.zeros(3)
        self.error = math.inf  # remaining position error [m] (across the cable when taut)
        self.via: list[FloatArray] = []  # way points [m] over pegs in the way, before the target
        self._holds = False

    def on_start(self, obs: Observation, ctx: PrimitiveContext) -> None:
        """Fix the target pose; check that a taut cable is sensed by this gripper."""
        me = obs.gripper(self.arm)
        self.target = self._goal.copy() if self._absolute else me.position + self._goal
        q = me.orientation if self.orientation is None else self.orientation
        self._q_target = np.asarray(q, dtype=float)
        est = ctx.estimator
        pegs = {
            name: (axis, radius, ctx.pegs[name][1])
            for name, (axis, radius) in est.round_fixtures.items()
            if name in ctx.pegs
        }
        skip = frozenset(n for n in (self.catch,) if n is not None)
        self.via = peg_detour(me.position, self.target, pegs, skip)
        if self._own_timeout:
            path = [me.position, *self.via, self.target]
            distance = sum(float(np.linalg.norm(q1 - q0)) for q0, q1 in itertools.pairwise(path))
            self.timeout = TIMEOUT_MARGIN + distance / TIMEOUT_SPEED
        self._hold = current_pose(obs)
        self._holds = ctx.graph.index_of("gripper", self.arm) is not None
        self._sensing = self._holds and est.arm == self.arm
        if self.taut and self._holds and not self._sensing:
            self.outcome = Outcome.failure(
                "precondition",
                f"the {self.arm} gripper holds the cable but does not sense it "
                f"(the {est.arm} gripper does): it cannot keep it taut",
            )
            return
        if self.catch is not None and self.catch not in est.round_fixtures:
            self.outcome = Outcome.failure(
                "precondition", f"{self.catch} is not a peg of the board design: nothing to catch"
            )
            return
        if not self.observe:
            est.observe_contacts = False
        if self._sensing:
            est.learn_elasticity = False  # the motion runs across the cable
            est.rotation = None
        if self.force is None:
            self.force = ctx.tension if ctx.tension is not None else 2.0
        self._tension: LowPass[float] = LowPass()
        self._slack = SlackWatch(1.0)
        self._axis = ToolAxis()
        self._arrived: tuple[float, int] | None = None  # (time, filter iterations) at the target

    def _settling(self, time: float, ctx: PrimitiveContext) -> bool:
        """Whether a taut, observed move still holds still at its target for the leave check.

        At most ``SETTLE_TIME`` [s]: where the filter takes no lines (a peg
        contact, contacts not observed) its iterations do not advance.
        """
        est = ctx.estimator
        if not (self.keeps_tension and self.observe and est.observe_contacts):
            return False
        if self._arrived is None:
            self._arrived = (time, est.iterations)
        if time - self._arrived[0] >= SETTLE_TIME:
            return False
        run = est.iterations - self._arrived[1]
        return run < LEAVE_RUN or (est.leaving > 0 and run < 2 * LEAVE_RUN)

    def taut_speed(self, ctx: PrimitiveContext) -> float:
        """The fastest [m/s] the gripper may cross its taut cable.

        Along the cable the force loop moves the gripper at k_f (f_d - f)
        (k_f = lambda / k_hat, equ:force_controller); crossing the cable at
        v, a direction error leaks ``DIRECTION_LEAK`` v along it. The loop
        takes that up with a tension error of half the set point where
        v <= f_d k_f / (2 ``DIRECTION_LEAK``): on a soft span the arm's
        speed limit binds first, on a stiff one this does.
        """
        assert self.force is not None
        gain = ctx.controller.force.gain(ctx.estimator.elasticity.k_trusted)
        limit = ctx.limits.max_linear_speed[0 if self.arm == "left" else 1]
        return max(MIN_TAUT_SPEED, min(0.5 * self.force * gain / DIRECTION_LEAK, float(limit)))

    def _carrot(self, me: FloatArray, goal: FloatArray, ctx: PrimitiveContext) -> FloatArray:
        """The set point [m] towards ``goal`` that keeps the approach within :meth:`taut_speed`.

        The position controller runs at k_p (its error) [m/s]: a set point
        at most ``taut_speed / k_p`` ahead of the gripper.
        """
        ahead = self.taut_speed(ctx) / ctx.controller.motion.k_p
        way = goal - me
        distance = float(np.linalg.norm(way))
        if distance <= ahead:
            return goal
        carrot: FloatArray = me + way * (ahead / distance)
        return carrot

    @property
    def keeps_tension(self) -> bool:
        """Whether the move keeps a held cable taut (force control along it)."""
        return self.taut and self._sensing

    def on_step(self, obs: Observation, ctx: PrimitiveContext) -> Command:
        """Drive towards the target (tension along the cable), judge."""
        if self.outcome.done:  # refused at the start
            return Command()
        assert self.force is not None
        me = obs.gripper(self.arm)
        goal = self.via[0] if self.via else self.target
        error = goal - me.position
        state = ctx.estimator.update(obs) if self._sensing else None
        follows = (
            self.orientation is None
            and self.observe
            and self.catch is None
            and state is not None
            and self.keeps_tension
        )
        if follows and state is not None and state.taut:
            # the tool turns along the cable as the cable turns (G's rule)
            _, along = self._axis.follow(
                obs.time, me.orientation, state.direction, state.tension, self.force
            )
            if along is not None:
                self._q_target = along
        aim = goal
        if state is not None and self.keeps_tension:
            aim = self._carrot(me.position, goal, ctx)
        desired = with_pose(self._hold, self.arm, Pose(aim, self._q_target))
        if state is not None and self.keeps_tension:
            twist = tension_twist(ctx, obs, self.arm, desired, self.force, state)
            d = state.direction
            error = error - d * float(d @ error)  # across the cable
            tension = self._tension.update(obs.time, state.tension)
            taut_enough = state.taut and tension >= TENSION_FRACTION * self.force
            if self._slack.update(obs.time, state.tension, self.force):
                self.outcome = Outcome.failure("slipped", "the cable went slack while moving")
                return Command()
        else:
            twist = ctx.controller(current_pose(obs), desired)
            taut_enough = True
        self.error = float(np.linalg.norm(error))
        if self.via:
            if self.error <= self.tolerance:
                self.via.pop(0)  # over the peg: on to the next way point
            return Command(twist)
        turn = 2.0 * math.asin(
            min(1.0, float(np.linalg.norm(quaternion_error(self._q_target, me.orientation))))
        )
        turned = follows or turn <= self.angle_tolerance  # a follower's turn is G's job
        if self.error <= self.tolerance and turned and taut_enough:
            if self._settling(obs.time, ctx):
                return Command(twist)
            how = " across the cable, taut" if self.keeps_tension else ""
            caught = ""
            if self.catch is not None and self._sensing:
                ctx.estimator.expect_peg(self.catch, me.position)
                caught = f"; {self.catch} expected as the contact once the gripper moves on"
            self.outcome = Outcome.success(
                f"the {self.arm} gripper is {1e3 * self.error:.1f} mm from its target{how}{caught}"
            )
        return Command(twist)
