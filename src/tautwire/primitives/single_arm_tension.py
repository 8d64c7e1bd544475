"""D - Single arm DLO Tension: tension the cable between a gripper and a fixed point."""

from __future__ import annotations

import math

import numpy as np

from tautwire.control import DualPose, Pose
from tautwire.errors import InvalidArgumentError
from tautwire.primitives.context import PrimitiveContext
from tautwire.primitives.outcome import Outcome
from tautwire.primitives.primitive import Primitive
from tautwire.robot import Arm, Command, Observation


def current_pose(obs: Observation) -> DualPose:
    """Both grippers' poses from an observation."""
    return DualPose(
        Pose(obs.left.position, obs.left.orientation),
        Pose(obs.right.position, obs.right.orientation),
    )


#: Weight of a new sample in the low-passed tension that success is judged on
#: (time constant 12 control periods, ~0.05 s at 4 ms).
SMOOTHING = 1.0 / 12.0


class SingleArmTension(Primitive):
    """Primitive D: hybrid control with force control along the cable.

    The projection P = f_hat f_hat^T on the gripper's linear block puts the
    direction towards the contact (f_g = p_c - p_g, the weight-compensated
    force's direction once taut) under the adaptive inverse-damping force
    controller k_f = lambda / k_hat (equ:force_controller); all other
    directions hold the start pose. k_hat is the online elasticity estimate
    and need not be right at the start.

    Success: the tension stays within ``tolerance`` of ``force`` for
    ``hold_time``. Failure: ``no_contact`` if the gripper travels
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
    ) -> None:
        super().__init__(timeout if duration is None else max(timeout, duration + 1.0))
        if arm not in ("left", "right"):
            raise InvalidArgumentError(f"arm must be 'left' or 'right', got {arm!r}")
        if not (force > 0.0 and math.isfinite(force)):
            raise InvalidArgumentError(f"force must be > 0 N, got {force}")
        self.arm: Arm = arm
        self.force = float(force)
        self.tolerance = float(tolerance)
        self.hold_time = float(hold_time)
        self.duration = duration
        self.max_travel = float(max_travel)
        self._desired: DualPose | None = None
        self._within_since: float | None = None
        self._start_position = np.zeros(3)
        self._ever_taut = False
        self._smoothed: float | None = None

    def on_start(self, obs: Observation, ctx: PrimitiveContext) -> None:
        """Remember the start; reset the success criteria."""
        ctx.estimator.learn_elasticity = True
        ctx.estimator.rotation = None
        self._desired = current_pose(obs)
        self._start_position = obs.gripper(self.arm).position.copy()
        self._within_since = None
        self._ever_taut = False
        self._smoothed = None

    def on_step(self, obs: Observation, ctx: PrimitiveContext) -> Command:
        """Update the model, run the hybrid controller, judge the outcome."""
        state = ctx.estimator.update(obs)
        assert self._desired is not None
        self._ever_taut |= state.taut
        tensions = (self.force, None) if self.arm == "left" else (None, self.force)
        forces = (state.force, None) if self.arm == "left" else (None, state.force)
        directions = (state.direction, None) if self.arm == "left" else (None, state.direction)
        twist = ctx.controller(
            current_pose(obs),
            self._desired,
            tensions,
            forces,
            ctx.estimator.elasticity.k_hat,
            directions,
        )
        self._judge(obs, state.tension)
        if self.outcome.done and self.outcome.status == "success":
            ctx.tension = self.force
        return Command(twist)

    def _judge(self, obs: Observation, tension: float) -> None:
        # judge the tension low-passed over ~0.05 s: single samples carry the
        # sensor's noise (and a hanging tail's swing), not the tension's level
        if self._smoothed is None:
            self._smoothed = tension
        else:
            self._smoothed += SMOOTHING * (tension - self._smoothed)
        tension = self._smoothed
        band = max(self.tolerance * self.force, 0.05)
        if abs(tension - self.force) <= band:
            if self._within_since is None:
                self._within_since = obs.time
        else:
            self._within_since = None
        held = self._within_since is not None and obs.time - self._within_since >= self.hold_time
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
