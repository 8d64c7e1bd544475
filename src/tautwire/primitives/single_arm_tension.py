"""D - Single arm DLO Tension: tension the cable between a gripper and a fixed point."""

from __future__ import annotations

import math

import numpy as np

from tautwire.control import DualPose
from tautwire.errors import InvalidArgumentError
from tautwire.primitives.arm_control import current_pose, tension_twist
from tautwire.primitives.context import PrimitiveContext
from tautwire.primitives.outcome import Outcome
from tautwire.primitives.primitive import Primitive
from tautwire.primitives.tension_judge import TensionJudge
from tautwire.robot import Arm, Command, Observation

#: Time constant [s] of the tension average that success is judged by.
JUDGE_TIME = 0.1


class SingleArmTension(Primitive):
    """Primitive D: hybrid control with force control along the cable.

    The projection P = f_hat f_hat^T on the gripper's linear block puts the
    direction towards the contact (f_g = p_c - p_g, the weight-compensated
    force's direction once taut) under the adaptive inverse-damping force
    controller k_f = lambda / k_hat (equ:force_controller); all other
    directions hold the start pose. k_hat is the online elasticity estimate
    and need not be right at the start.

    Learning k (equ:spring_measurement). Two things make a cable's stiffness
    observable from the wrist alone, and D provides both:

    * The elasticity estimate learns only once the tension has first come
      within ``tolerance`` of ``force``. While the cable is pulled from slack,
      the chord lengthens mostly because the sag straightens out and the
      cable swings; those samples would fit a far softer spring (a 1000 N/m
      cable read as 250 N/m in Fig. 5a).
    * Once there, the set point is modulated by a slow sine,
      f_d (1 + ``excitation`` sin(2 pi t / ``excitation_period``)): a
      persistent excitation. Holding a constant tension, a stiff cable moves
      the gripper by micrometres, which the force noise and the cable's
      transverse vibrations swamp; the paper notes that k estimates improve
      with larger oscillation. The default, half the tolerance (5 %), swings
      a 1000 N/m cable at 2 N by +-0.1 mm, enough for k to within a few per
      cent in 2-4 s, and stays well inside the success band. 0 turns it off.

    The controller's gain uses the latest k_hat known to 20 %
    (:attr:`ElasticityEstimator.k_trusted`; before that, the prior), so a
    fit from the first few samples cannot make it unstable.

    Success: the tension, averaged over ``JUDGE_TIME`` (0.1 s: the sensor's
    noise is not the tension leaving the band), stays within ``tolerance`` of
    ``force`` for ``hold_time``. Failure: ``no_contact`` if the gripper travels
    ``max_travel`` without the cable becoming taut; ``timeout``.

    Args:
        arm: The gripper that holds the cable (it carries the FT sensor).
        force: Desired tension f_d [N].
        tolerance: Allowed tension error, a fraction of ``force``.
        hold_time: How long [s] the tension must stay within tolerance.
        duration: If set, run for this long [s] regardless (experiments),
            then judge success by the last ``hold_time``.
        max_travel: Longest distance [m] to pull a slack cable.
        timeout: Longest run time [s].
        excitation: Amplitude of the set point's modulation, a fraction of
            ``force`` in [0, ``tolerance``); default half the tolerance.
        excitation_period: Period [s] of the modulation, > 0.
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
        timeout: float = 10.0,
        excitation: float | None = None,
        excitation_period: float = 2.0,
    ) -> None:
        super().__init__(timeout if duration is None else max(timeout, duration + 1.0))
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
        self.arm: Arm = arm
        self.force = float(force)
        self.tolerance = float(tolerance)
        self.hold_time = float(hold_time)
        self.duration = duration
        self.max_travel = float(max_travel)
        self.excitation = float(excitation)
        self.excitation_period = float(excitation_period)
        self._learning = False
        self._judge_tension = TensionJudge(self.force, self.tolerance, self.hold_time, JUDGE_TIME)
        self._desired: DualPose | None = None
        self._start_position = np.zeros(3)
        self._ever_taut = False

    def on_start(self, obs: Observation, ctx: PrimitiveContext) -> None:
        """Remember the start; reset the success criteria."""
        ctx.estimator.learn_elasticity = False  # until the tension is near f_d
        ctx.estimator.rotation = None
        self._learning = False
        self._desired = current_pose(obs)
        self._start_position = obs.gripper(self.arm).position.copy()
        self._judge_tension = TensionJudge(self.force, self.tolerance, self.hold_time, JUDGE_TIME)
        self._ever_taut = False

    def on_step(self, obs: Observation, ctx: PrimitiveContext) -> Command:
        """Update the model, run the hybrid controller, judge the outcome."""
        state = ctx.estimator.update(obs)
        assert self._desired is not None
        self._ever_taut |= state.taut
        band = max(self.tolerance * self.force, 0.05)
        if not self._learning and state.taut and abs(state.tension - self.force) <= band:
            self._learning = True
            ctx.estimator.learn_elasticity = True
        f_d = self.set_point(self.elapsed)
        twist = tension_twist(ctx, obs, self.arm, self._desired, f_d, state)
        self._judge(obs, state.tension)
        if self.outcome.done and self.outcome.status == "success":
            ctx.tension = self.force
        return Command(twist)

    def set_point(self, elapsed: float) -> float:
        """Desired tension [N] ``elapsed`` s after the start, with the excitation."""
        phase = 2.0 * math.pi * elapsed / self.excitation_period
        return self.force * (1.0 + self.excitation * math.sin(phase))

    def _judge(self, obs: Observation, tension: float) -> None:
        held = self._judge_tension.update(obs.time, tension)
        tension = self._judge_tension.smoothed or 0.0
        if self.duration is not None:
            if self.elapsed >= self.duration:
                self.outcome = (
                    Outcome.success(f"tension {tension:.2f} N")
                    if held
                    else Outcome.failure(
                        "timeout", f"tension {tension:.2f} N, set {self.force:g} N"
                    )
                )
            return
        if held:
            self.outcome = Outcome.success(f"tension {tension:.2f} N held {self.hold_time:g} s")
            return
        travel = float(np.linalg.norm(obs.gripper(self.arm).position - self._start_position))
        if not self._ever_taut and travel > self.max_travel:
            self.outcome = Outcome.failure(
                "no_contact", f"pulled {travel:.2f} m and the cable never became taut"
            )
