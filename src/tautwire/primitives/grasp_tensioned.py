"""H - Grasp a Tensioned DLO: the second gripper grasps the taut cable along its edge."""

from __future__ import annotations

import math

import numpy as np

from tautwire.control import Pose
from tautwire.errors import InvalidArgumentError
from tautwire.model.interpolation import lerp
from tautwire.model.quaternion import turn_x_onto_line
from tautwire.model.tension import G as GRAVITY
from tautwire.primitives.arm_control import current_pose, tension_twist, with_pose
from tautwire.primitives.context import PrimitiveContext
from tautwire.primitives.low_pass import LowPass
from tautwire.primitives.model_edits import add_on_sensing_edge
from tautwire.primitives.outcome import Outcome
from tautwire.primitives.primitive import Primitive
from tautwire.robot import Arm, Command, GripperCommand, Observation

FloatArray = np.ndarray

#: Height [m] above the cable from which the open fingers descend onto it.
APPROACH_HEIGHT = 0.04
#: Position error [m] at which an approach waypoint counts as reached.
REACHED = 0.003
#: Speed [m/s] of the final descent onto the cable.
DESCENT_SPEED = 0.03
#: Lowest height [m] above the board at which the free gripper travels to
#: the goal, and its clearance [m] over the sensing gripper (the taut
#: cable runs no higher): random board 1695658280's left gripper, freed
#: low at a clip, went straight for W2 across the board and pulled 27 N.
TRAVEL_HEIGHT = 0.15
TRAVEL_CLEARANCE = 0.04
#: Horizontal distance [m] to the goal within which the gripper goes straight.
NEAR = 0.05
#: Vertical std [m] of the model's chord at the goal above which the goal's
#: height comes from the measured pull's line instead (see ``_line_height``).
LINE_HEIGHT_STD = 0.002
#: Time constant [s] of the low-pass on the measured direction read for that line.
LINE_TIME_CONSTANT = 0.25


class GraspTensioned(Primitive):
    """Primitive H: grasp the cable at arc length ``at`` with the free gripper.

    The sensing gripper keeps the cable taut (D's force control). The goal
    is the model's interpolated feature point at ``at`` (paper: position by
    linear interpolation between the edge's end points, with the sag of a
    taut span, rho g a^2 delta (1 - delta) / (2 f), added below the chord),
    recomputed every period as the model updates. Where the model's
    contact is uncertain in height (a peg claimed at its design position,
    10 mm std), the chord's height at the goal comes from the measured pull
    instead: the weight-compensated force points from the sensing gripper
    along the chord to where the cable really leaves the contact
    (:meth:`_line_height`). The free gripper opens,
    rises to ``TRAVEL_HEIGHT`` (and ``TRAVEL_CLEARANCE`` over the sensing
    gripper, above which the taut cable does not run) where the goal is more
    than ``NEAR`` away horizontally, travels over it there, moves above the
    goal with its x-axis along the cable, descends onto it and closes. The
    grasp is confirmed by the fingers' opening (they stop on the cable
    instead of closing fully). The model then gets a gripper
    point at ``at``, which becomes the far end of the sensing gripper's edge.

    Success: the fingers closed on the cable and the sensing gripper still
    feels tension. Failure: ``missed`` if the fingers close on nothing;
    ``precondition`` if ``at`` does not lie on the sensing gripper's taut
    edge; ``slipped`` if the tension vanishes; ``timeout``.

    Args:
        arm: The gripper that grasps (not the one that holds the cable).
        at: Arc length [m] from the cable's start at which to grasp.
        force: Tension [N] the sensing gripper keeps; default the context's.
        timeout: Longest run time [s].
    """

    name = "grasp_tensioned"
    letter = "H"

    def __init__(
        self, arm: Arm, at: float, force: float | None = None, timeout: float = 20.0
    ) -> None:
        super().__init__(timeout)
        if arm not in ("left", "right"):
            raise InvalidArgumentError(f"arm must be 'left' or 'right', got {arm!r}")
        if not (at >= 0.0 and math.isfinite(at)):
            raise InvalidArgumentError(f"at must be an arc length >= 0 m, got {at}")
        self.arm: Arm = arm
        self.at = float(at)
        self.force = force
        self.phase = "approach"
        self.goal = np.zeros(3)
        self._line: FloatArray | None = None  # the low-passed pull's direction while taut

    def on_start(self, obs: Observation, ctx: PrimitiveContext) -> None:
        """Check that ``at`` lies on the sensing gripper's taut edge."""
        if self.force is None:
            self.force = ctx.tension if ctx.tension is not None else 2.0
        ctx.estimator.learn_elasticity = False
        ctx.estimator.rotation = None
        self.phase = "approach"
        self._phase_since = obs.time
        self._tension: LowPass[float] = LowPass()
        self._direction: LowPass[FloatArray] = LowPass(LINE_TIME_CONSTANT)
        self._line = None
        self._hold = current_pose(obs)
        me = obs.gripper(self.arm).position
        self._start = me.copy()
        self._travel_z = max(float(me[2]), TRAVEL_HEIGHT)
        est = ctx.estimator
        if self.arm == est.arm:
            self.outcome = Outcome.failure(
                "precondition", f"the {self.arm} gripper already holds the cable"
            )
            return
        g, c = est.gripper_index, est.contact_index
        s = ctx.graph.arc_lengths()
        if c is None:
            self.outcome = Outcome.failure("precondition", "the cable is taut against nothing")
            return
        lo, hi = sorted((float(s[c]), float(s[g])))
        if not lo + 0.02 < self.at < hi - 0.02:
            self.outcome = Outcome.failure(
                "precondition",
                f"at = {self.at:g} m is not on the taut edge [{lo:.3f}, {hi:.3f}] m",
            )
            return
        # far across the board: up first, over, then down onto the cable
        goal, _ = self._goal(ctx, ctx.tension or 0.0, obs.gripper(self.arm).orientation)
        if float(np.hypot(*(goal - me)[:2])) > NEAR:
            self.phase = "rise"

    def _goal(
        self, ctx: PrimitiveContext, tension: float, orientation: FloatArray
    ) -> tuple[FloatArray, FloatArray]:
        """The interpolated feature point at ``at``: position [m] and grasp orientation.

        The orientation is the grasping gripper's ``orientation`` turned by
        the shortest arc that lays its tool x-axis, either sense, along the
        cable (the fingers hold it as well either way).
        """
        graph = ctx.graph
        i, delta = graph.locate(self.at)
        a, b = graph.points[i].position, graph.points[i + 1].position
        p = lerp(a, b, delta)
        height = self._line_height(ctx, i, delta, p)
        if height is not None:
            p[2] = height
        span = float(np.hypot(*(b - a)[:2]))
        if tension > 0.1:
            p[2] -= graph.mass_per_length * GRAVITY * span**2 * delta * (1 - delta) / (2 * tension)
        along = b - a
        along[2] = 0.0
        return p, turn_x_onto_line(orientation, along)

    def _line_height(
        self, ctx: PrimitiveContext, i: int, delta: float, p: FloatArray
    ) -> float | None:
        """The chord's height [m] at ``p`` along the measured pull, where the model's is uncertain.

        The model's chord runs from its contact to the sensing gripper; a
        contact whose height the model does not know well (std ``sigma``)
        leaves the chord ``(1 - w) sigma`` uncertain at the goal, ``w`` the
        goal's fraction of the way from the contact to the gripper. Above
        ``LINE_HEIGHT_STD`` the height comes from the line through the
        sensing gripper along the low-passed weight-compensated pull (the
        chord's direction to where the cable leaves the contact), at the
        goal's horizontal distance. Random board 1045612557: C into F10
        after peg F9 (claimed at its design position, 10 mm std), the model
        put the grasp 5.5 mm above the cable and the fingers' lower lips
        pushed it out as they closed (``missed``, 14.6 N true).

        Returns:
            The height [m], or None (the model's chord is kept).
        """
        if self._line is None:
            return None
        g = ctx.estimator.gripper_index
        if g is None or g not in (i, i + 1):
            return None
        contact = ctx.graph.points[i + 1 if g == i else i]
        if contact.covariance is None:
            return None
        weight = delta if g == i else 1.0 - delta  # the contact's share of the goal
        if weight * math.sqrt(max(float(contact.covariance[2, 2]), 0.0)) <= LINE_HEIGHT_STD:
            return None
        grip = ctx.graph.points[g].position
        u = self._line
        run = math.hypot(float(u[0]), float(u[1]))
        if run < 0.3:  # steeper than 73 deg: the horizontal distance says little
            return None
        d = math.hypot(*(p - grip)[:2])
        return float(grip[2]) + float(u[2]) * d / run

    def on_step(self, obs: Observation, ctx: PrimitiveContext) -> Command:
        """Keep the tension, approach, descend, close, confirm, record."""
        assert self.force is not None
        state = ctx.estimator.update(obs)
        if self.outcome.done:
            return Command()
        if state.taut:
            self._line = self._direction.update(obs.time, state.direction)
        sensing = ctx.estimator.arm
        tension = self._tension.update(obs.time, state.tension)  # the fingers shake the cable
        me = obs.gripper(self.arm)
        goal, q = self._goal(ctx, state.tension, me.orientation)
        self.goal = goal
        fingers = GripperCommand("open")
        if self.phase in ("rise", "traverse"):
            travel = max(
                self._travel_z,
                float(goal[2]) + APPROACH_HEIGHT,
                float(obs.gripper(sensing).position[2]) + TRAVEL_CLEARANCE,
            )
            self._travel_z = travel
            if self.phase == "rise":
                target = np.array([self._start[0], self._start[1], travel])
            else:
                target = np.array([goal[0], goal[1], travel])
            if float(np.linalg.norm(me.position - target)) < 2.0 * REACHED:
                self.phase = "traverse" if self.phase == "rise" else "approach"
                self._phase_since = obs.time
        elif self.phase == "approach":
            target = goal + np.array([0.0, 0.0, APPROACH_HEIGHT])
            if float(np.linalg.norm(me.position - target)) < REACHED:
                self.phase, self._phase_since = "descend", obs.time
        elif self.phase == "descend":
            depth = min(DESCENT_SPEED * (obs.time - self._phase_since), APPROACH_HEIGHT)
            target = goal + np.array([0.0, 0.0, APPROACH_HEIGHT - depth])
            if depth >= APPROACH_HEIGHT and float(np.linalg.norm(me.position - goal)) < 0.0015:
                self.phase, self._phase_since = "close", obs.time
        else:
            target = me.position
            fingers = GripperCommand("hold")
            if obs.time - self._phase_since >= 0.2:
                self._confirm(obs, ctx, tension)
        desired = with_pose(self._hold, self.arm, Pose(target, q))
        twist = tension_twist(ctx, obs, sensing, desired, self.force, state)
        if self.phase == "close":  # hold still while the fingers close
            k = 0 if self.arm == "left" else 6
            twist[k : k + 6] = 0.0
        if self.arm == "left":
            return Command(twist, left=fingers)
        return Command(twist, right=fingers)

    def _confirm(self, obs: Observation, ctx: PrimitiveContext, tension: float) -> None:
        assert self.force is not None
        opening = obs.gripper(self.arm).opening
        if opening < 1e-4:
            error = float(np.linalg.norm(obs.gripper(self.arm).position - self.goal))
            self.outcome = Outcome.failure(
                "missed",
                f"the {self.arm} fingers closed on nothing at the model's point"
                f" ({1e3 * error:.1f} mm from it)",
            )
            return
        if tension < 0.2 * self.force:
            self.outcome = Outcome.failure("slipped", "the cable went slack while grasping")
            return
        add_on_sensing_edge(
            ctx.estimator, self.at, obs.gripper(self.arm).position, "gripper", self.arm
        )
        self.outcome = Outcome.success(
            f"grasped at {self.at:.3f} m, fingers {1e3 * opening:.1f} mm apart"
        )
