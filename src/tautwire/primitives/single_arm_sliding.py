"""E - Single arm DLO Sliding: let the cable slide through the gripper, away from a fixed point."""

from __future__ import annotations

import numpy as np

from tautwire.control import Pose
from tautwire.primitives.arm_control import current_pose, tension_twist, with_pose
from tautwire.primitives.context import PrimitiveContext
from tautwire.primitives.model_estimator import TensionState
from tautwire.primitives.sliding import SlidingPrimitive
from tautwire.robot import Arm, Observation


class SingleArmSliding(SlidingPrimitive):
    """Primitive E: the gripper moves away from the contact, the cable slides through it.

    Individual control: the gripper moves along the cable (from the contact
    towards the gripper, as estimated at the start) at ``speed``; P = 0, the
    tension is set by the grip force (see :class:`SlidingPrimitive`). The
    other gripper holds its pose.

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
        """Hold the start pose while tensioning."""
        self._hold = current_pose(obs)
        super().on_start(obs, ctx)

    def begin(self, obs: Observation, ctx: PrimitiveContext, state: TensionState) -> None:
        """The sliding line: from the contact through the gripper's start."""
        me = obs.gripper(self.arm)
        away = me.position - state.contact
        self._start = me.position.copy()
        self._away = away / max(float(np.linalg.norm(away)), 1e-9)
        self._start_pose = current_pose(obs)

    def tension_motion(
        self, obs: Observation, ctx: PrimitiveContext, state: TensionState
    ) -> np.ndarray:
        """D's hybrid control with f_d = f_slid, holding the start pose otherwise."""
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
