"""What the sliding primitives (B and E) share: friction-controlled sliding.

One gripper loosens its grip so that the cable slides through its fingers
while the grippers part (or the gripper moves away from a fixed point). The
tension in the cable is then the friction in that gripper, and the
gripping-force PI controller (equ:Gripping_Force_Controller) sets the grip
force so that it equals the desired sliding friction f_slid; the integral
absorbs the unknown friction coefficient. After ``distance`` the gripper
grips firmly again, and the model records how much cable slid through
(edge lengths at rest: the travel minus the change of the elastic stretch).

The sliding gripper's tool axis must lie along the cable first: a cable
bent round a fingertip presses on the fingertip's edge as well as on the
pads, so its friction is not 2 mu F_grip, and its tension reads wrong. The
tensioning before the slide therefore ends only once the subclass says the
grippers are aligned (:meth:`SlidingPrimitive.aligned`).
"""

from __future__ import annotations

import math
from abc import abstractmethod
from typing import Literal

import numpy as np

from tautwire.control import GripForceController
from tautwire.errors import InvalidArgumentError
from tautwire.primitives.context import PrimitiveContext
from tautwire.primitives.low_pass import LowPass
from tautwire.primitives.model_edits import move_hold, rescale_elasticity
from tautwire.primitives.model_estimator import TensionState
from tautwire.primitives.outcome import Outcome
from tautwire.primitives.primitive import Primitive
from tautwire.primitives.slack_watch import SlackWatch
from tautwire.primitives.tension_judge import TensionJudge
from tautwire.robot import Arm, Command, GripperCommand, Observation

#: Friction coefficient assumed for the first grip force (the integral of the
#: PI controller finds the real one).
NOMINAL_FRICTION = 0.5
#: Fraction of the nominal grip force to start with (low: the cable starts
#: sliding at once instead of stretching against a grip that is too firm).
START_GRIP = 0.7
#: Fraction of the nominal grip force below which the grip never goes while
#: sliding (:class:`~tautwire.control.GripForceController`'s floor): under a
#: tension spike (the cable caught beyond the gripper, stick-slip round a
#: peg) the PI law drove the grip to 0.0-0.4 N, the fingers opened over their
#: lips and the cable dropped out (random boards 1548504588 and 1385678398).
#: At the nominal friction the floor still lets the tension fall to half of
#: f_slid; at a friction up to twice the nominal one it stays at f_slid.
MIN_GRIP = 0.5
#: Cable [m] that must remain beyond the sliding gripper at the end.
MIN_BEYOND = 0.02

Phase = Literal["tension", "slide", "regrip"]


class SlidingPrimitive(Primitive):
    """Base of B and E: slide ``distance`` at friction ``friction_force``.

    Subclasses give the motion (:meth:`motion`), the tensioning before it
    (:meth:`tension_motion`, which also lays the tool axes along the cable),
    whether the tool axes lie along the cable (:meth:`aligned`), the travel
    so far (:meth:`travel`) and which grasp point moves (:meth:`hold_shift`).

    Phases: *tension* (firm grip, the tension brought to ``friction_force``
    and held within 15 % for 0.2 s, aligned all that time), *slide*,
    *regrip*.

    Success: the grippers travelled ``distance`` with the cable sliding
    (low-passed tension within ``tolerance`` of ``friction_force`` on average
    after the first ``settle_time``), and the firm grip closed on the cable
    again. Failure: ``slipped`` if the tension vanishes for ``slack_time``
    while sliding (the cable left the gripper); ``missed`` if the fingers
    close on nothing; ``precondition`` if too little cable is left beyond the
    sliding gripper; ``timeout``.

    Args:
        slide_arm: The gripper the cable slides through.
        distance: Travel [m] along the cable.
        friction_force: Desired sliding friction f_slid [N].
        speed: Sliding speed [m/s].
        tolerance: Allowed mean error of the sliding tension, a fraction.
        settle_time: Time [s] given to the PI controller before judging.
        slack_time: Longest time [s] the tension may vanish while sliding.
        timeout: Longest run time [s]; default three times the nominal time.
    """

    def __init__(
        self,
        slide_arm: Arm,
        distance: float,
        friction_force: float,
        speed: float = 0.04,
        tolerance: float = 0.3,
        settle_time: float = 0.5,
        slack_time: float = 0.5,
        timeout: float | None = None,
    ) -> None:
        if slide_arm not in ("left", "right"):
            raise InvalidArgumentError(f"arm must be 'left' or 'right', got {slide_arm!r}")
        for name, value in (("distance", distance), ("friction_force", friction_force)):
            if not (value > 0.0 and math.isfinite(value)):
                raise InvalidArgumentError(f"{name} must be > 0, got {value}")
        if not (speed > 0.0 and math.isfinite(speed)):
            raise InvalidArgumentError(f"speed must be > 0 m/s, got {speed}")
        super().__init__(timeout if timeout is not None else 3.0 * distance / speed + 5.0)
        self.slide_arm: Arm = slide_arm
        self.distance = float(distance)
        self.friction_force = float(friction_force)
        self.speed = float(speed)
        self.tolerance = float(tolerance)
        self.settle_time = float(settle_time)
        self.slack_time = float(slack_time)
        self.grip = GripForceController()
        self.phase: Phase = "tension"
        self.slid = 0.0  # rest length [m] of cable that slid through, once done

    def on_start(self, obs: Observation, ctx: PrimitiveContext) -> None:
        """Loosen the grip to the nominal sliding grip; remember the start."""
        ctx.estimator.learn_elasticity = False
        ctx.estimator.rotation = None
        nominal = self.friction_force / (2.0 * NOMINAL_FRICTION)
        self.grip = GripForceController(
            initial_grip_force=START_GRIP * nominal, min_grip_force=MIN_GRIP * nominal
        )
        self.phase = "tension"
        self._tension_judge = TensionJudge(self.friction_force, 0.15, 0.2)
        self._slide_start = 0.0
        self.slid = 0.0
        self._tension: LowPass[float] = LowPass()
        self._judged: list[float] = []
        self._sliding: list[float] = []  # every slide sample, the settling included
        self._slack = SlackWatch(self.slack_time)
        self._regrip_at = 0.0
        state = ctx.estimator.update(obs)
        self._start_tension = state.tension
        self.begin(obs, ctx, state)
        index, sense = self.hold_shift(ctx)
        left = _free_beyond(ctx, index, sense)
        if left < self.distance + MIN_BEYOND:
            self.outcome = Outcome.failure(
                "precondition",
                f"only {left:.3f} m of cable is beyond the {self.slide_arm} gripper,"
                f" too little to slide {self.distance:g} m",
            )

    @abstractmethod
    def begin(self, obs: Observation, ctx: PrimitiveContext, state: TensionState) -> None:
        """Hook: remember what the motion needs at the start."""

    @abstractmethod
    def aligned(self, obs: Observation, ctx: PrimitiveContext, state: TensionState) -> bool:
        """Hook: whether the holding grippers' tool axes lie along the cable (once per period)."""

    @abstractmethod
    def tension_motion(
        self, obs: Observation, ctx: PrimitiveContext, state: TensionState, aligned: bool
    ) -> np.ndarray:
        """Hook: the individual twist (12,) that brings the tension to f_slid, firmly gripped.

        It also turns the tool axes onto the cable; ``aligned``: whether
        they lie along it (:meth:`aligned` this period).
        """

    @abstractmethod
    def motion(
        self, obs: Observation, ctx: PrimitiveContext, state: TensionState, moving: bool
    ) -> np.ndarray:
        """Hook: the individual twist (12,) [m/s, rad/s]: sliding if ``moving``, else holding."""

    @abstractmethod
    def travel(self, obs: Observation) -> float:
        """Hook: how far [m] the grippers have travelled along the cable."""

    @abstractmethod
    def hold_shift(self, ctx: PrimitiveContext) -> tuple[int, float]:
        """Hook: (graph index of the sliding gripper's point, +1 or -1 along the arc)."""

    def on_step(self, obs: Observation, ctx: PrimitiveContext) -> Command:
        """Slide under grip-force control, then grip again and update the model."""
        state = ctx.estimator.update(obs)
        if self.outcome.done:
            return Command()
        tension = state.tension
        smoothed = self._tension.update(obs.time, tension)
        if self.phase == "tension":
            # first the tension that the sliding will keep, with a firm grip:
            # a soft cable would otherwise slide slack for most of the way;
            # and the tool axes along the cable, or the friction is not 2 mu F_grip
            aligned = self.aligned(obs, ctx, state)
            if not aligned:
                self._tension_judge.reset()
            elif self._tension_judge.update(obs.time, tension):
                self.phase = "slide"
                self._slide_start = obs.time
                self._start_tension = tension
                self.begin(obs, ctx, state)
            twist = self.tension_motion(obs, ctx, state, aligned)
            return self._command(twist, GripperCommand("hold"))
        if self.phase == "slide":
            travelled = self.travel(obs)
            moving = travelled < self.distance
            grip = self.grip.update(self.friction_force, tension, ctx.control_period)
            self._sliding.append(smoothed)
            if obs.time - self._slide_start > self.settle_time:
                self._judged.append(smoothed)
                if self._slack.update(obs.time, tension, self.friction_force):
                    self.outcome = Outcome.failure(
                        "slipped", f"the tension vanished ({tension:.2f} N) while sliding"
                    )
            if not moving:
                self.phase = "regrip"
                self._regrip_at = obs.time
                self._travelled = travelled
            twist = self.motion(obs, ctx, state, moving)
            mode = GripperCommand("grip_force", grip)
            if not moving:
                mode = GripperCommand("hold")
            return self._command(twist, mode)
        # regrip: hold still with a firm grip, then judge and record
        twist = self.motion(obs, ctx, state, False)
        if obs.time - self._regrip_at >= 0.1:
            self._finish(obs, ctx, tension)
        return self._command(twist, GripperCommand("hold"))

    def _command(self, twist: np.ndarray, slide_grip: GripperCommand) -> Command:
        if self.slide_arm == "left":
            return Command(twist, left=slide_grip)
        return Command(twist, right=slide_grip)

    def _finish(self, obs: Observation, ctx: PrimitiveContext, tension: float) -> None:
        if obs.gripper(self.slide_arm).opening < 1e-4:
            self.outcome = Outcome.failure(
                "missed", f"the {self.slide_arm} gripper closed on nothing after sliding"
            )
            return
        # a slide shorter than the settling is judged on all of it (random
        # board 1652323633's 1.1 mm slide judged nothing and read "nan N")
        judged = self._judged or self._sliding
        mean = float(np.mean(judged)) if judged else float("nan")
        if not abs(mean - self.friction_force) <= self.tolerance * self.friction_force:
            self.outcome = Outcome.failure(
                "slipped" if not mean > self.friction_force else "timeout",
                f"the sliding tension averaged {mean:.2f} N, wanted {self.friction_force:g} N",
            )
            return
        # rest length that slid: the travel minus the change of the elastic stretch
        k = ctx.estimator.elasticity.k_trusted
        stretch_change = (tension - self._start_tension) / k if k > 0.0 else 0.0
        self.slid = max(self._travelled - stretch_change, 0.0)
        index, sense = self.hold_shift(ctx)
        edge = ctx.graph.edges[index - 1 if sense > 0 else index]
        before = edge.length
        try:
            move_hold(ctx.graph, index, sense * self.slid)
        except InvalidArgumentError as exc:
            self.outcome = Outcome.failure("precondition", str(exc))
            return
        if edge.length > 0.0 and before > 0.0:
            rescale_elasticity(ctx.estimator, before / edge.length)
        self.outcome = Outcome.success(
            f"slid {self.slid:.3f} m at {mean:.2f} N (wanted {self.friction_force:g} N)"
        )


def _free_beyond(ctx: PrimitiveContext, index: int, sense: float) -> float:
    """Cable [m] beyond the gripper at graph ``index``, up to the next constrained point.

    Free points on the way (where a gripper let go: a hand-over's release)
    hold nothing back: random board 208802845's slide after a hand-over
    read only the 0.089 m to the point the first gripper had released, of
    0.87 m beyond.
    """
    points, edges = ctx.graph.points, ctx.graph.edges
    step = 1 if sense > 0 else -1
    left, k = 0.0, index
    while 0 <= k + step < len(points):
        left += edges[k if step > 0 else k - 1].length
        k += step
        if points[k].is_constrained:
            break
    return left
