"""D - Single arm DLO Tension: tension the cable between a gripper and a fixed point."""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np

from tautwire.control import DualPose, Pose
from tautwire.control.force_controller import AdaptiveForceController
from tautwire.errors import InvalidArgumentError
from tautwire.model.vector3 import norm3
from tautwire.primitives.arm_control import current_pose, tension_twist, with_pose
from tautwire.primitives.clip_sensing import JAW_TOP
from tautwire.primitives.clip_tug import (
    TUG_REACHED_MIN,
    TUG_REACHED_SHARE,
    TUG_SETTLE,
    ClipTug,
    TugReading,
    lifted,
)
from tautwire.primitives.context import PrimitiveContext
from tautwire.primitives.low_pass import LowPass
from tautwire.primitives.model_edits import move_hold
from tautwire.primitives.model_estimator import TensionState
from tautwire.primitives.outcome import Outcome
from tautwire.primitives.primitive import Primitive
from tautwire.primitives.slack_watch import SlackWatch
from tautwire.primitives.tension_judge import TensionJudge
from tautwire.primitives.tool_axis import ToolAxis
from tautwire.primitives.travel_bound import TravelBound, route_to_fixed_point
from tautwire.robot import Arm, Command, Observation

#: Time constant [s] of the tension average that success is judged by.
JUDGE_TIME = 0.1
#: Once taut at the set point, a tension below this fraction of it for SLACK_TIME [s]
#: is a slip (robustness trial 42: a drifting bias pulled a stiff cable off its peg at
#: 0.4-0.7 N of a 2.5 N set point, and the gripper, chasing the bias, rose 0.5 m while
#: the fit read k as 1 N/m, which let the travel bound grow to 21 m).
SLACK_FRACTION = 1.0 / 3.0
SLACK_TIME = 1.0
#: The learning swing keeps the tension below this fraction of the force limit.
FORCE_LIMIT_RESERVE = 0.8


#: Speed [m/s] at which D draws slack through a clip (the model's route has
#: slack behind one, :func:`route_to_fixed_point`) while the tension is below
#: ``SLACK_PULL_BELOW`` of the set point: pulled with the gain of the taut
#: edge's stiffness, it crawls (random board 1627120487's last tension after
#: C into F4: 88 mm of slack behind the clip, 3 mm/s, the pull's direction at
#: 0.3 N wandering up and down, and 48 mm drawn in its 30 s).
SLACK_PULL_SPEED = 0.02
SLACK_PULL_BELOW = 0.5
#: Times D takes up slack anew when the tension, taut at its set point from a
#: clip, falls away: a clip holds the cable across its slot, not along it,
#: and a pull draws slack the model does not know of through it (random
#: board 1729667587, seed 30: C's near span let 45 mm slide through clip F2
#: into the sagging span before it; D's 3 N from F3 then drew it through F2
#: and F3 in slips of 13 mm, the tension at 0.1 N for a second each). The
#: route then runs through every clip behind the gripper to the next point
#: that truly holds the cable (:func:`route_to_fixed_point`), whose rest
#: length bounds the travel.
RETAKES = 3
#: Time [s] each retake adds to D's timeout. A retake does not learn k anew:
#: the model's rest length behind the clip is short by the slack drawn, and
#: a fit over it ran to ``learn_timeout`` (the board above: 14 s, then the
#: tug, and the 30 s ran out with the cable taut at its set point).
RETAKE_TIME = 8.0
#: Largest angle [rad] between the tool axis and the cable at which D starts learning k.
ALIGNED = math.radians(10.0)
#: How long [s] a turned gripper must stay aligned before D learns k.
ALIGNED_TIME = 0.2
#: Speed [m/s] at which the gripper swings aside for the tug about a clip and back.
TUG_SPEED = 0.02
#: Angle [rad] by which D swings the gripper aside about a clip's exit to tell
#: whether the clip holds the cable.
SWING = math.radians(5.0)
#: Longest wait [s] for the gripper to reach its tug set point.
TUG_LATE = 2.0


class SingleArmTension(Primitive):
    """Primitive D: hybrid control with force control along the cable.

    The projection P = f_hat f_hat^T on the gripper's linear block puts the
    direction towards the contact (f_g = p_c - p_g, the weight-compensated
    force's direction once taut) under the adaptive inverse-damping force
    controller k_f = lambda / k_hat (equ:force_controller); all other
    directions hold the start pose. k_hat is the online elasticity estimate
    and need not be right at the start.

    Learning k (equ:spring_measurement). D runs in three phases:

    1. *Approach*: pull the cable taut to ``force``, and turn the tool axis
       the cable leaves along, +x or -x
       (:class:`~tautwire.primitives.tool_axis.ToolAxis`), onto the cable by
       the shortest arc (a gripper may start at any yaw: a cable bent round
       a fingertip rubs the pad and pulls off the line). The elasticity
       estimate learns only once the tension has first come within
       ``tolerance`` of ``force`` with the tool axis within ``ALIGNED`` of
       the cable (for ``ALIGNED_TIME`` if it had to turn; the alignment
       goes on in every phase, on the low-passed direction): while the
       cable is pulled from slack, the chord lengthens mostly because the
       sag straightens out and the cable swings; those samples would fit a
       far softer spring (a 1000 N/m cable read as 250 N/m in Fig. 5a).
    2. *Learning*: the set point swings by ``learn_excitation`` (default
       +-20 %) of ``force``, f_d (1 + a sin(2 pi t / ``excitation_period``)),
       until k is known to ``stiffness_std`` (relative std of the fit,
       default 3 %), k_hat has moved by at most twice that over the last
       period, and at least ``min_learn_time`` has passed; or for
       ``learn_timeout`` at most. A persistent excitation: holding a
       constant tension, a stiff cable moves the gripper by micrometres,
       which the force noise and the cable's vibrations swamp. The swing's
       length amplitude a f_d / k_trusted is kept under ``max_swing`` (a soft
       cable needs no long stroke) and its peak under 80 % of the force
       limit. The swing changes amplitude only where the sine crosses zero.
    3. *Hold*: the swing drops to ``excitation`` (default half the
       tolerance, 5 %), which keeps k tracked and stays well inside the
       success band; success once the tension has stayed in the band for
       ``hold_time``.

    Measured (``bench/stiffness.py``, 80 scenes over the envelope of issue
    10: 0.15-1 m, 10-1500 N/m, slack 2-15 %, noise 0.03-0.1 N, 1.5-4 N, an
    anchor or a peg): D takes 3.5-10.5 s of simulated time (median 5.6 s;
    learning 2.4-7.4 s); on the anchors k_hat ends within 3.2 % of the
    cable's k in 46 of 47 (the 47th wrapped the cable round a finger pad
    while aligning the tool axis); Table I's D scenes take 3.6-7.6 s
    (median 5.1 s), k_hat within 1.9 % of k L / l in 30 of 30.

    The controller's gain uses the latest k_hat known to 20 %
    (:attr:`ElasticityEstimator.k_trusted`; before that, the prior), so a
    fit from the first few samples cannot make it unstable.

    Travel bound: the route from the gripper back to the fixed point
    behind it (through the contact estimates) may be at most its rest
    length plus the stretch at the force limit plus a margin
    (:class:`~tautwire.primitives.travel_bound.TravelBound`). Further, an
    intact cable would have reached the force limit: it has slipped
    through the fingers, and D fails at once rather than drive the gripper
    out of the workspace. A clip holds the cable across, not along: where
    the model's span behind a clip on the route is slack (the near span a
    parallel clip's release leaves), the route runs on through the clip to
    the next constrained point, and on success the model edit moves the
    clip's point along the cable by that slack (the span behind it now lies
    straight; :func:`~tautwire.primitives.travel_bound.route_to_fixed_point`).

    Success: the tension, averaged over ``JUDGE_TIME`` (0.1 s: the sensor's
    noise is not the tension leaving the band), stays within ``tolerance`` of
    ``force`` for ``hold_time`` in the hold phase. Failure: ``no_contact`` if
    the gripper travels ``max_travel`` (or past the travel bound) without the
    cable becoming taut; ``slipped`` past the travel bound after it was
    taut, or once the tension, taut at the set point before, stays below
    a third of it for 1 s; ``timeout``.

    Args:
        arm: The gripper that holds the cable (it carries the FT sensor).
        force: Desired tension f_d [N].
        tolerance: Allowed tension error, a fraction of ``force``.
        hold_time: How long [s] the tension must stay within tolerance.
        duration: If set, run for this long [s] regardless (experiments),
            then judge success by the last ``hold_time``.
        max_travel: Longest distance [m] to pull a slack cable.
        timeout: Longest run time [s].
        excitation: Amplitude of the set point's modulation outside the
            learning phase, a fraction of ``force`` in [0, ``tolerance``);
            default half the tolerance.
        excitation_period: Period [s] of the modulation, > 0.
        learn_excitation: Amplitude of the learning swing, a fraction of
            ``force`` in [0, 1); 0 skips the learning phase.
        stiffness_std: Relative std of k that ends the learning phase.
        min_learn_time: Shortest learning phase [s].
        learn_timeout: Longest learning phase [s]; then D holds with the k
            it has.
        max_swing: Largest length amplitude [m] of the learning swing.
    """

    name = "single_arm_tension"
    letter = "D"

    def __init__(
        self,
        arm: Arm,
        force: float,
        tolerance: float = 0.1,
        hold_time: float = 0.5,
        duration: float | None = None,
        max_travel: float = 0.3,
        timeout: float = 30.0,
        excitation: float | None = None,
        excitation_period: float = 2.0,
        learn_excitation: float = 0.2,
        stiffness_std: float = 0.03,
        min_learn_time: float = 2.0,
        learn_timeout: float = 15.0,
        max_swing: float = 0.02,
    ) -> None:
        super().__init__(timeout if duration is None else max(timeout, duration + 1.0))
        self._timeout = self.timeout  # before retakes add to it
        if arm not in ("left", "right"):
            raise InvalidArgumentError(f"arm must be 'left' or 'right', got {arm!r}")
        if not (force > 0.0 and math.isfinite(force)):
            raise InvalidArgumentError(f"force must be > 0 N, got {force}")
        if excitation is None:
            excitation = 0.5 * tolerance
        if not 0.0 <= excitation < tolerance:
            raise InvalidArgumentError(
                f"excitation must be in [0, tolerance = {tolerance}), got {excitation}"
            )
        if not (excitation_period > 0.0 and math.isfinite(excitation_period)):
            raise InvalidArgumentError(f"excitation_period must be > 0 s, got {excitation_period}")
        if not 0.0 <= learn_excitation < 1.0:
            raise InvalidArgumentError(
                f"learn_excitation must be in [0, 1), got {learn_excitation}"
            )
        if not (stiffness_std > 0.0 and math.isfinite(stiffness_std)):
            raise InvalidArgumentError(f"stiffness_std must be > 0, got {stiffness_std}")
        if not (0.0 <= min_learn_time <= learn_timeout and math.isfinite(learn_timeout)):
            raise InvalidArgumentError(
                "need 0 <= min_learn_time <= learn_timeout < inf s,"
                f" got {min_learn_time} and {learn_timeout}"
            )
        if not (max_swing > 0.0 and math.isfinite(max_swing)):
            raise InvalidArgumentError(f"max_swing must be > 0 m, got {max_swing}")
        self.arm: Arm = arm
        self.force = float(force)
        self.tolerance = float(tolerance)
        self.hold_time = float(hold_time)
        self.duration = duration
        self.max_travel = float(max_travel)
        self.excitation = float(excitation)
        self.excitation_period = float(excitation_period)
        self.learn_excitation = float(learn_excitation)
        self.stiffness_std = float(stiffness_std)
        self.min_learn_time = float(min_learn_time)
        self.learn_timeout = float(learn_timeout)
        self.max_swing = float(max_swing)
        self._judge_tension = TensionJudge(self.force, self.tolerance, self.hold_time, JUDGE_TIME)
        self._travel = TravelBound(15.0)
        self._slack = SlackWatch(SLACK_TIME, SLACK_FRACTION)
        self._desired: DualPose | None = None
        self._start_position = np.zeros(3)
        self._ever_taut = False
        self._phase = "approach"
        self._learn_start: float | None = None
        self._half_period = -1
        self._amplitude = self.excitation
        self._k_history: list[float] = []  # k_hat at the zeros of the learning swing
        #: Simulated time [s] the learning phase took (None before it ended).
        self.learn_time: float | None = None

    @property
    def phase(self) -> str:
        """``approach``, ``learning`` or ``hold``."""
        return self._phase

    def on_start(self, obs: Observation, ctx: PrimitiveContext) -> None:
        """Remember the start; reset the success criteria."""
        ctx.estimator.learn_elasticity = False  # until the tension is near f_d
        ctx.estimator.rotation = None
        self._desired = current_pose(obs)
        self._start_position = obs.gripper(self.arm).position.copy()
        self._through: tuple[tuple[int, float], ...] = ()  # clips the pull draws slack through
        self._judge_tension = TensionJudge(self.force, self.tolerance, self.hold_time, JUDGE_TIME)
        self._travel = TravelBound(ctx.limits.max_force)
        self._slack = SlackWatch(SLACK_TIME, SLACK_FRACTION)
        self._ever_taut = False
        self._phase = "approach"
        self._learn_start = None
        self._half_period = -1
        self._amplitude = self.excitation
        self._k_history = []
        self.learn_time = None
        self._axis = ToolAxis()
        self._cable: LowPass[np.ndarray] = LowPass()  # the cable's direction
        self._aligned_since: float | None = None
        self._taut_since: float | None = None
        self._tug: _Tug | None = None
        self._tugged = False
        self._tug_note = ""
        self._retakes = 0  # times the slack drawn through clips was taken up anew
        self.timeout = self._timeout
        self._k_start = ctx.estimator.elasticity.k_trusted  # the prior a retake returns to
        self._retake_clip = ""

    def on_step(self, obs: Observation, ctx: PrimitiveContext) -> Command:
        """Update the model, run the hybrid controller, judge the outcome."""
        state = ctx.estimator.update(obs)
        assert self._desired is not None
        self._ever_taut |= state.taut
        band = max(self.tolerance * self.force, 0.05)
        me = obs.gripper(self.arm)
        aligned = False
        if state.taut:
            # lay the tool axis the cable leaves along onto the cable (as G),
            # on the low-passed direction: a cable bent round a fingertip
            # pulls off the line, rubs the pad and makes the force jump
            cable = self._cable.update(obs.time, state.direction)
            wrench = obs.wrench(self.arm)  # which fingertip: decided from the whole wrench
            self._axis.observe(obs.time, me.orientation, wrench.force, wrench.torque)
            q = self._axis.target(me.orientation, cable)
            self._desired = with_pose(self._desired, self.arm, Pose(self._held_position(), q))
            aligned = self._axis.angle(me.orientation, cable) <= ALIGNED
        if not aligned:
            self._aligned_since = None
        elif self._aligned_since is None:
            self._aligned_since = obs.time
        if state.taut and self._taut_since is None:
            self._taut_since = obs.time
        # aligned from the first taut sample on, or for ALIGNED_TIME since
        settled = self._aligned_since is not None and (
            self._aligned_since == self._taut_since
            or obs.time - self._aligned_since >= ALIGNED_TIME
        )
        if self._phase == "approach" and settled and abs(state.tension - self.force) <= band:
            learn = self.learn_excitation > 0.0 and not self._retakes
            self._phase = "learning" if learn else "hold"
            self._learn_start = self.elapsed
            ctx.estimator.learn_elasticity = not self._retakes  # a retake keeps the prior
        self._schedule(ctx)
        if self._phase == "tug" and self._tug is not None:
            target = self._tug.step(obs.time, me.position, obs.wrench(self.arm).force, state)
            self._desired = with_pose(
                self._desired, self.arm, Pose(target, self._desired_orientation())
            )
        f_d = self.set_point(self.elapsed)
        pull, k_gain = state, None
        if self._phase == "approach" and self._through and state.tension < SLACK_PULL_BELOW * f_d:
            pull, k_gain = self._slack_pull(ctx, obs, state, f_d)
        twist = tension_twist(ctx, obs, self.arm, self._desired, f_d, pull, k_gain)
        self._judge(obs, state, ctx)
        if self.outcome.done and self.outcome.status == "success":
            ctx.tension = self.force
        return Command(twist)

    def _slack_pull(
        self, ctx: PrimitiveContext, obs: Observation, state: TensionState, f_d: float
    ) -> tuple[TensionState, float | None]:
        """The pull that draws the model's slack through a clip: along the route, briskly.

        Nothing stiff resists until the slack is through, so the force gain
        is that of a stiffness which moves the gripper at
        ``SLACK_PULL_SPEED`` at no tension (slowing as the tension rises;
        the loop stays first order once the cable comes taut, at the rate
        lambda k / k_gain), along the model's line from
        the contact to the gripper: the pull's measured direction at a few
        tenths of a newton is the free tail's weight and noise.

        Returns:
            The state with the model's direction, and the stiffness [N/m]
            for the force gain (None: the controller's own, where it is not
            the adaptive one, whose gain is lambda / k).
        """
        force = ctx.controller.force
        k_gain = (
            force.bandwidth * f_d / SLACK_PULL_SPEED
            if isinstance(force, AdaptiveForceController)
            else None
        )
        line = state.contact - obs.gripper(self.arm).position
        n = float(np.linalg.norm(line))
        if n > 1e-6:
            state = replace(state, direction=line / n)
        return state, k_gain

    def _desired_orientation(self) -> np.ndarray:
        """The orientation set point (unit quaternion) of the tensioning gripper."""
        assert self._desired is not None
        pose = self._desired.left if self.arm == "left" else self._desired.right
        return pose.orientation

    def _held_position(self) -> np.ndarray:
        """The position set point [m] of the tensioning gripper (motion control holds it)."""
        assert self._desired is not None
        return self._desired.left.position if self.arm == "left" else self._desired.right.position

    def set_point(self, elapsed: float) -> float:
        """Desired tension [N] ``elapsed`` s after the start, with the present swing."""
        phase = 2.0 * math.pi * elapsed / self.excitation_period
        return self.force * (1.0 + self._amplitude * math.sin(phase))

    def _schedule(self, ctx: PrimitiveContext) -> None:
        """At each zero of the sine: end the learning phase once k is known; pick the swing."""
        half = math.floor(2.0 * self.elapsed / self.excitation_period)
        if half == self._half_period:
            return
        self._half_period = half
        elasticity = ctx.estimator.elasticity
        if self._phase == "learning" and self._learn_start is not None:
            learnt = self.elapsed - self._learn_start
            self._k_history.append(elasticity.k_hat)
            # known to stiffness_std by its noise, and no longer moving: a
            # period ago it read the same (a cable still settling makes a
            # confident fit wander)
            k_now, k_before = self._k_history[-1], self._k_history[-3:][0]
            steady = (
                len(self._k_history) >= 3
                and abs(k_now - k_before) <= 2.0 * self.stiffness_std * k_now
            )
            known = steady and elasticity.is_ready(self.stiffness_std)
            # with a fixed duration, the last hold_time is judged after a small swing
            late = self.duration is not None and (
                self.elapsed + 0.5 * self.excitation_period + self.hold_time >= self.duration
            )
            if (known and learnt >= self.min_learn_time) or learnt >= self.learn_timeout or late:
                self._phase = "hold"
                self.learn_time = learnt
                self._judge_tension.reset()
        if self._phase != "learning":
            self._amplitude = 0.0 if self._phase == "tug" else self.excitation
            return
        if not self._k_history[:-1]:
            # the swing starts: fit it alone, not the samples of the cable coming taut
            elasticity.reset(k_initial=elasticity.k_trusted)
        # the peak stays under the force limit's reserve; a soft cable needs no long stroke
        by_limit = FORCE_LIMIT_RESERVE * ctx.limits.max_force / self.force - 1.0
        by_stroke = self.max_swing * elasticity.k_trusted / self.force
        self._amplitude = max(self.excitation, min(self.learn_excitation, by_limit, by_stroke))

    def _judge(self, obs: Observation, state: TensionState, ctx: PrimitiveContext) -> None:
        held = self._judge_tension.update(obs.time, state.tension)
        tension = self._judge_tension.smoothed or 0.0
        holding = self._phase == "hold"
        if self.duration is not None:
            if self.elapsed >= self.duration:
                self.outcome = (
                    Outcome.success(
                        f"tension {tension:.2f} N{self._k_note(ctx)}" + self._draw_through(ctx)
                    )
                    if held and holding
                    else Outcome.failure(
                        "timeout", f"tension {tension:.2f} N, set {self.force:g} N ({self._phase})"
                    )
                )
            return
        if held and holding and not self._tugged and self._start_tug(obs, ctx):
            return
        if self._phase == "tug" and self._tug is not None:
            reading = self._tug.reading
            if reading is not None and reading.distinct and not reading.holds:
                self.outcome = Outcome.failure(
                    "left_fixture",
                    f"the cable left {self._tug.clip}: {reading.describe()}; the pull"
                    " lines up with the point before it, so only the tug tells",
                )
                return
            if self._tug.done:
                assert reading is not None
                told = "held" if reading.distinct else "not told apart"
                self._tug_note = f"; at {self._tug.clip} {reading.describe()}: {told}"
                self._phase, self._tugged = "hold", True
                self._judge_tension.reset()
            return
        if held and holding:
            self.outcome = Outcome.success(
                f"tension {tension:.2f} N held {self.hold_time:g} s{self._k_note(ctx)}"
                + self._tug_note
                + self._draw_through(ctx)
                + self._retake_note()
            )
            return
        if self._phase != "approach" and self._slack.update(obs.time, state.tension, self.force):
            if self._retake(ctx):
                return
            self.outcome = Outcome.failure(
                "slipped",
                f"the tension fell to {state.tension:.2f} N, below {SLACK_FRACTION:.2g} of its"
                f" set point for {SLACK_TIME:g} s after the cable was taut at it: the cable no"
                " longer holds where the model says",
            )
            return
        travel = float(np.linalg.norm(obs.gripper(self.arm).position - self._start_position))
        if not self._ever_taut and travel > self.max_travel:
            self.outcome = Outcome.failure(
                "no_contact", f"pulled {travel:.2f} m and the cable never became taut"
            )
            return
        route = route_to_fixed_point(
            ctx.estimator, state, ctx.clips.keys(), through_all=self._retakes > 0
        )
        self._through = route.through if route is not None else ()
        if route is None:
            return
        length, rest = route.length, route.rest_length
        k_route = route.stiffness(ctx.estimator.elasticity.k_trusted)
        if self._travel.update(length, rest, tension, k_route):
            cause = "slipped" if self._ever_taut else "no_contact"
            self.outcome = Outcome.failure(
                cause,
                f"the route to the fixed point is {length:.3f} m, longer than its rest length"
                f" {rest:.3f} m and the stretch at the force limit allow"
                f" ({self._travel.allowed:.3f} m at k {self._travel.stiffness(k_route):.3g} N/m):"
                " the cable is no longer held where the model says",
            )

    def _start_tug(self, obs: Observation, ctx: PrimitiveContext) -> bool:
        """Start the tug about the clip the cable is taut against, if it is one; True if started.

        The tension's line cannot tell a clip from the point before it where
        the two lie on one line from the gripper: random board 1652323633
        (seed 0) slid out of clip F2 along the line from peg F1 through it;
        D's first pull drew the cable, sitting 2.3 mm up in the jaws' throat,
        out of F2 (it bent up over the clip, from F1's winding 29 mm higher),
        and D held 3 N against F1 and reported success. The tug swings the
        gripper aside about the clip's exit and reads what the pull turned
        about (:class:`_Tug`, :mod:`~tautwire.primitives.clip_tug`).
        """
        est = ctx.estimator
        c = est.contact_index
        if c is None:
            return False
        clip = est.graph.points[c]
        info = ctx.clips.get(clip.label) if clip.kind == "fixed" else None
        far = est.point_before(c)
        if info is None or far is None or far.kind == "gripper":
            return False
        me = obs.gripper(self.arm).position
        out = me - info.position
        out[2] = 0.0
        n = norm3(out)
        if n < 1e-3:
            return False
        out /= n
        exit_point = info.exit_towards(me)
        exit_point[2] += JAW_TOP
        self._tug = _Tug(clip.label, exit_point, far.position.copy(), out, me.copy(), obs.time)
        self._phase = "tug"
        return True

    def _retake(self, ctx: PrimitiveContext) -> bool:
        """Take up slack drawn through a clip anew (:data:`RETAKES`); whether D does.

        Only where the point the cable is taut from is a clip: the approach
        starts again, with the route (and its travel bound) running through
        every clip behind to the point that truly holds the cable, and the
        clip's tug is felt again once the tension holds.
        """
        c = ctx.estimator.contact_index
        if self._retakes >= RETAKES or c is None:
            return False
        point = ctx.graph.points[c]
        if point.kind != "fixed" or point.label not in ctx.clips:
            return False
        self._retakes += 1
        self._retake_clip = point.label
        self.timeout += RETAKE_TIME
        self._phase = "approach"
        self._slack = SlackWatch(SLACK_TIME, SLACK_FRACTION)
        self._judge_tension.reset()
        self._taut_since = self._aligned_since = None
        self._tug, self._tugged, self._tug_note = None, False, ""
        ctx.estimator.learn_elasticity = False
        # a fit over the slips learnt the clip's friction, not the cable (board
        # 1729667587: 5.1 N/m at a 4 % std): back to the prior D started with
        ctx.estimator.elasticity.reset(k_initial=self._k_start)
        return True

    def _retake_note(self) -> str:
        if not self._retakes:
            return ""
        times = "once" if self._retakes == 1 else f"{self._retakes} times"
        return f"; took up slack drawn through {self._retake_clip} {times}"

    def _draw_through(self, ctx: PrimitiveContext) -> str:
        """The model edit once taut: the slack the pull drew through clips is past them.

        Each clip on the route moves along the cable towards the fixed point
        by the slack of every span behind it (:func:`move_hold`; the farthest
        first): the spans behind lie straight now, the one before the gripper
        is longer.
        """
        through = self._through
        if not through:
            return ""
        g = ctx.estimator.gripper_index
        moved = []
        points = ctx.graph.points
        towards_start = g is None or through[0][0] < g
        # the farthest clip first; each moves by the slack behind it and beyond
        ordered = sorted(through, reverse=not towards_start)
        clips, drawn, total = [], [], 0.0
        for index, slack in ordered:
            total += slack
            clips.append(points[index])
            drawn.append(total)
        for clip, slack in zip(clips, drawn, strict=True):
            if slack <= 1e-4:
                continue
            points = ctx.graph.points
            index = next(k for k, p in enumerate(points) if p is clip)
            g = ctx.estimator.gripper_index
            sense = 1 if g is not None and index > g else -1  # towards the fixed point
            # the span behind lies straight now: its free points (where a
            # gripper let go) mark nothing
            while 0 < index + sense < len(points) - 1 and not points[index + sense].is_constrained:
                ctx.graph.remove_point(index + sense)
                index -= 1 if sense < 0 else 0
            move_hold(ctx.graph, index, sense * slack)
            moved.append(f"{1e3 * slack:.0f} mm through {clip.label}")
        self._through = ()
        return "; drew " + ", ".join(moved) if moved else ""

    def _k_note(self, ctx: PrimitiveContext) -> str:
        e = ctx.estimator.elasticity
        rel = e.std / e.k_hat if e.k_hat > 0.0 else math.inf
        return f"; k_hat {e.k_hat:.4g} N/m (std {100.0 * rel:.2g} %)"


class _Tug:
    """D's tug about a clip: rest, swing aside by ``SWING`` about its exit, read, come back.

    Aside, not up as F lifts: a cable in the jaws' throat rises as it is
    lifted and turns about a point behind the exit, much as a loose one
    does (random boards 1742396983 and 247036674, seed 11: clipped, lifted
    by 3 deg, the pull turned 1.3 deg against 2.9 about the exit and 0.7
    about the far contact; 1652323633 out of its clip 2.4 against 3.6 and
    2.0); across, the slot's walls hold it at the exit.

    Args:
        clip: The clip's label.
        exit_point: Its exit on the gripper's side, at the jaws' top [m].  # (3,)
        far: The constrained point before it [m].  # (3,)
        out: Unit horizontal direction from the clip to the gripper.  # (3,)
        rest: The gripper's position at rest [m].  # (3,)
        time: Now [s].
    """

    def __init__(
        self,
        clip: str,
        exit_point: np.ndarray,
        far: np.ndarray,
        out: np.ndarray,
        rest: np.ndarray,
        time: float,
    ) -> None:
        self.clip = clip
        self.exit = exit_point
        self.far = far
        self.rest = rest
        aside = np.array([-out[1], out[0], 0.0])
        self.aside = lifted(rest, exit_point, out, SWING, aside)
        self.pull = ClipTug(out, aside)
        self.stage = "rest"
        self.since = time
        self.reached: float | None = None
        #: The tug's reading (None until the gripper has rested swung aside).
        self.reading: TugReading | None = None

    @property
    def done(self) -> bool:
        """Whether the gripper is back at rest after the reading."""
        return self.stage == "done"

    def step(
        self, time: float, position: np.ndarray, force: np.ndarray, state: TensionState
    ) -> np.ndarray:
        """Add the measured force [N]; the gripper's position set point [m] now.

        The set point moves at ``TUG_SPEED`` between rest and aside; the
        gripper is there once its error across the pull (along it, force
        control sets the position) is under ``TUG_REACHED_SHARE`` of the
        lift; after ``TUG_LATE`` [s] there it rests all the same.
        """
        self.pull.update(time, force)
        if self.stage in ("rest", "done"):
            if self.stage == "rest" and time - self.since >= TUG_SETTLE:
                self.pull.mark_rest(position)
                self.stage, self.since = "aside", time
            return self.rest
        start, end = (self.rest, self.aside) if self.stage == "aside" else (self.aside, self.rest)
        span = norm3(end - start)
        share = min(1.0, TUG_SPEED * (time - self.since) / max(span, 1e-9))
        target: np.ndarray = start + share * (end - start)
        error = position - end
        error -= float(error @ state.direction) * state.direction
        near = max(TUG_REACHED_SHARE * span, TUG_REACHED_MIN)
        if share >= 1.0 and (
            norm3(error) < near or time - self.since >= span / TUG_SPEED + TUG_LATE
        ):
            self.reached = time if self.reached is None else self.reached
        if self.reached is not None and time - self.reached >= TUG_SETTLE:
            if self.stage == "aside":
                self.reading = self.pull.reading(position, self.exit, self.far)
                self.stage, self.since, self.reached = "back", time, None
            else:
                self.stage = "done"
        return target
