"""E - Single arm DLO Sliding: let the cable slide through the gripper, away from a fixed point."""

from __future__ import annotations

import numpy as np

from tautwire.control import Pose
from tautwire.primitives.arm_control import current_pose, tension_twist, with_pose
from tautwire.primitives.context import PrimitiveContext
from tautwire.primitives.low_pass import LowPass
from tautwire.primitives.model_estimator import TensionState
from tautwire.primitives.single_arm_tension import ALIGNED, ALIGNED_TIME
from tautwire.primitives.sliding import SlidingPrimitive
from tautwire.primitives.tool_axis import ToolAxis
from tautwire.robot import Arm, Observation


class SingleArmSliding(SlidingPrimitive):
    """Primitive E: the gripper moves away from the contact, the cable slides through it.

    Individual control: the gripper moves along the cable (from the contact
    towards the gripper, as estimated at the start) at ``speed``; P = 0, the
    tension is set by the grip force (see :class:`SlidingPrimitive`). The
    other gripper holds its pose.

    A gripper may start at any yaw. While the cable is tensioned for
    sliding (D's hybrid control with f_d = f_slid), the tool axis the cable
    leaves along, +x or -x, decided from the whole wrench
    (:meth:`~tautwire.primitives.tool_axis.ToolAxis.observe`), turns onto the
    low-passed cable direction by the shortest arc, as in D; the slide
    starts only once it has stayed within ``ALIGNED`` of the cable (for
    ``ALIGNED_TIME`` if it had to turn), and the gripper then keeps that
    axis on the sliding line. After D the gripper is aligned already.

    Args:
        arm: The gripper the cable slides through (it carries the sensor).
        distance: Travel [m] along the cable.
        friction_force: Desired sliding friction f_slid [N].
        **kwargs: See :class:`SlidingPrimitive`.
    """

    name = "single_arm_sliding"
    letter = "E"

    def __init__(self, arm: Arm, distance: float, friction_force: float, **kwargs: float) -> None:
        super().__init__(arm, distance, friction_force, **kwargs)
        self.arm: Arm = arm

    def on_start(self, obs: Observation, ctx: PrimitiveContext) -> None:
        """Hold the start position while tensioning; the tool axis is to be decided."""
        self._hold = current_pose(obs)
        self._axis = ToolAxis()
        self._cable: LowPass[np.ndarray] = LowPass()  # the cable's direction
        self._aligned_since: float | None = None
        self._taut_since: float | None = None
        super().on_start(obs, ctx)

    def aligned(self, obs: Observation, ctx: PrimitiveContext, state: TensionState) -> bool:
        """Turn the tool axis onto the low-passed cable direction; whether it has settled there.

        Aligned from the first taut sample on, or for ``ALIGNED_TIME``.
        """
        if not state.taut:
            self._aligned_since = None
            return False
        if self._taut_since is None:
            self._taut_since = obs.time
        me = obs.gripper(self.arm)
        cable = self._cable.update(obs.time, state.direction)
        wrench = obs.wrench(self.arm)  # which fingertip: decided from the whole wrench
        self._axis.observe(obs.time, me.orientation, wrench.force, wrench.torque)
        target = Pose(self._held_position(), self._axis.target(me.orientation, cable))
        self._hold = with_pose(self._hold, self.arm, target)
        if self._axis.angle(me.orientation, cable) > ALIGNED:
            self._aligned_since = None
            return False
        if self._aligned_since is None:
            self._aligned_since = obs.time
        return (
            self._aligned_since == self._taut_since
            or obs.time - self._aligned_since >= ALIGNED_TIME
        )

    def _held_position(self) -> np.ndarray:
        """The position set point [m] of the sliding gripper while tensioning."""
        return self._hold.left.position if self.arm == "left" else self._hold.right.position

    def begin(self, obs: Observation, ctx: PrimitiveContext, state: TensionState) -> None:
        """The sliding line: from the contact through the gripper's start; the axis along it."""
        me = obs.gripper(self.arm)
        away = me.position - state.contact
        self._start = me.position.copy()
        self._away = away / max(float(np.linalg.norm(away)), 1e-9)
        self._start_pose = current_pose(obs)
        if self._axis.sign is not None:  # the axis decided while taut: keep it on the line
            q = self._axis.target(me.orientation, -self._away)
            self._start_pose = with_pose(self._start_pose, self.arm, Pose(self._start, q))

    def tension_motion(
        self, obs: Observation, ctx: PrimitiveContext, state: TensionState, aligned: bool
    ) -> np.ndarray:
        """D's hybrid control with f_d = f_slid, the tool axis turning onto the cable."""
        return tension_twist(ctx, obs, self.arm, self._hold, self.friction_force, state)

    def travel(self, obs: Observation) -> float:
        """Distance [m] moved along the sliding line."""
        return float((obs.gripper(self.arm).position - self._start) @ self._away)

    def motion(
        self, obs: Observation, ctx: PrimitiveContext, state: TensionState, moving: bool
    ) -> np.ndarray:
        """A set point that runs ahead on the sliding line at ``speed``."""
        k_p = ctx.controller.motion.k_p
        if moving:
            # the P controller's lag is speed / k_p: lead the set point by it
            ahead = min(self.travel(obs) + self.speed / k_p, self.distance + 1e-3)
        else:
            ahead = self.travel(obs)
        target = Pose(
            self._start + ahead * self._away,
            self._start_pose[0 if self.arm == "left" else 1].orientation,
        )
        return ctx.controller(current_pose(obs), with_pose(self._start_pose, self.arm, target))

    def hold_shift(self, ctx: PrimitiveContext) -> tuple[int, float]:
        """The gripper's point moves away from its contact along the arc."""
        g = ctx.estimator.gripper_index
        c = ctx.estimator.contact_index
        return g, (1.0 if c is None or c < g else -1.0)
