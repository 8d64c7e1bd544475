"""G - Gripper Alignment: turn the gripper's x-axis along the taut cable."""

from __future__ import annotations

import math

from tautwire.control import Pose
from tautwire.errors import InvalidArgumentError
from tautwire.primitives.arm_control import current_pose, tension_twist, with_pose
from tautwire.primitives.context import PrimitiveContext
from tautwire.primitives.model_edits import drop_new_points
from tautwire.primitives.outcome import Outcome
from tautwire.primitives.primitive import Primitive
from tautwire.primitives.slack_watch import SlackWatch
from tautwire.primitives.tool_axis import ToolAxis
from tautwire.robot import Arm, Command, Observation


class GripperAlignment(Primitive):
    """Primitive G: align the tool x-axis with the cable direction measured by the force.

    The paper: "the gripper is aligned along the DLO to achieve the most
    stretched DLO orientation; any bending will degrade the linear
    approximation". While D's force control keeps the tension along the
    cable, the orientation set point is the current one turned by the
    shortest arc from the tool axis the cable leaves along, +x or -x
    (:class:`~tautwire.primitives.tool_axis.ToolAxis`), onto the cable's
    direction (the low-passed weight-compensated force's): never a half
    turn. The position holds. While the tension is above
    ``PAUSE_TENSION`` times its set point the orientation holds too, until
    the force control has let the cable out.

    Success: the angle between that tool axis and the cable stays below
    ``tolerance`` for ``hold_time``. Failure: ``slipped`` if the cable goes
    slack; ``not_aligned`` at the timeout.

    Preconditions: the gripper holds the cable taut and senses it. Model
    edits: none. Turning in place moves the force's line by millimetres
    about the fingers, which the contact filter can read as a new contact
    next to the gripper: a contact point added while G runs is dropped when
    it ends (the cable's contacts are what they were before).

    Args:
        arm: The gripper to align (it carries the sensor).
        force: Tension set point [N]; default the context's (from D) or 2 N.
        tolerance: Largest remaining angle [rad].
        hold_time: How long [s] the angle must stay below ``tolerance``.
        timeout: Longest run time [s].
    """

    name = "gripper_alignment"
    letter = "G"

    def __init__(
        self,
        arm: Arm,
        force: float | None = None,
        tolerance: float = math.radians(3.0),
        hold_time: float = 0.3,
        timeout: float = 8.0,
    ) -> None:
        super().__init__(timeout)
        if arm not in ("left", "right"):
            raise InvalidArgumentError(f"arm must be 'left' or 'right', got {arm!r}")
        if force is not None and not (force > 0.0 and math.isfinite(force)):
            raise InvalidArgumentError(f"force must be > 0 N, got {force}")
        self.arm: Arm = arm
        self.force = force
        self.tolerance = float(tolerance)
        self.hold_time = float(hold_time)
        self.angle = math.pi  # remaining angle [rad] between tool x and the cable

    def on_start(self, obs: Observation, ctx: PrimitiveContext) -> None:
        """Remember the start position; reset the criteria."""
        if self.force is None:
            self.force = ctx.tension if ctx.tension is not None else 2.0
        ctx.estimator.learn_elasticity = False
        ctx.estimator.rotation = None
        self._hold = current_pose(obs)
        self._within_since: float | None = None
        self._slack = SlackWatch(1.0)
        self._axis = ToolAxis()
        self._known = [id(p) for p in ctx.graph.points]

    def on_step(self, obs: Observation, ctx: PrimitiveContext) -> Command:
        """Keep the tension, turn towards the cable, judge."""
        assert self.force is not None
        state = ctx.estimator.update(obs)
        me = obs.gripper(self.arm)
        q_target = me.orientation
        if state.taut:
            self.angle, turned = self._axis.follow(
                obs.time, me.orientation, state.direction, state.tension, self.force
            )
            if turned is not None:
                q_target = turned
        mine = Pose(self._hold[0 if self.arm == "left" else 1].position, q_target)
        desired = with_pose(self._hold, self.arm, mine)
        twist = tension_twist(ctx, obs, self.arm, desired, self.force, state)
        self._judge(obs, state.tension, state.taut)
        if self.outcome.done:  # G never edits contacts
            drop_new_points(ctx.graph, self._known)
        return Command(twist)

    def _judge(self, obs: Observation, tension: float, taut: bool) -> None:
        assert self.force is not None
        if taut and self.angle <= self.tolerance:
            if self._within_since is None:
                self._within_since = obs.time
            elif obs.time - self._within_since >= self.hold_time:
                self.outcome = Outcome.success(
                    f"tool x-axis {math.degrees(self.angle):.1f} deg from the cable"
                )
                return
        else:
            self._within_since = None
        if self._slack.update(obs.time, tension, self.force):
            self.outcome = Outcome.failure("slipped", "the cable went slack while aligning")
        if self.elapsed >= self.timeout - 1e-9 and not self.outcome.done:
            self.outcome = Outcome.failure(
                "not_aligned",
                f"the tool x-axis is still {math.degrees(self.angle):.1f} deg from the cable",
            )
