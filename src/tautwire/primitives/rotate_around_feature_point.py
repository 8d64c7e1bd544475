"""I - Rotate Around Feature Point: circle the estimated contact, cable taut."""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import ArrayLike

from tautwire.control import DualPose, Pose
from tautwire.errors import InvalidArgumentError
from tautwire.model.quaternion import multiply, rotate
from tautwire.model.vector3 import cross3, norm3
from tautwire.primitives.context import PrimitiveContext
from tautwire.primitives.outcome import Outcome
from tautwire.primitives.primitive import Primitive
from tautwire.primitives.single_arm_tension import current_pose
from tautwire.robot import Arm, Command, Observation


def _shortest_arc(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """The smallest rotation [w, x, y, z] that turns direction ``a`` onto ``b``."""
    a = a / norm3(a)
    b = b / norm3(b)
    c = float(a @ b)
    if c < -1.0 + 1e-9:  # opposite: half turn about any axis normal to a
        n = cross3(a, [1.0, 0.0, 0.0] if abs(a[0]) < 0.9 else [0.0, 1.0, 0.0])
        n /= norm3(n)
        return np.array([0.0, *n])
    v = cross3(a, b)
    q = np.array([1.0 + c, *v])
    out: np.ndarray = q / math.sqrt(float(q @ q))
    return out


def _rotate(v: np.ndarray, axis: np.ndarray, angle: float) -> np.ndarray:
    """Rodrigues' rotation of ``v`` about the unit ``axis`` by ``angle`` [rad]."""
    c, s = math.cos(angle), math.sin(angle)
    out: np.ndarray = v * c + cross3(axis, v) * s + axis * float(axis @ v) * (1.0 - c)
    return out


class RotateAroundFeaturePoint(Primitive):
    """Primitive I: move the gripper on a circle around the estimated contact.

    Motion control tracks a set point that runs ahead on the circle about the
    current contact estimate (so the gripper moves tangentially at
    ``speed`` times the radius and turns with the cable); force control along
    the cable keeps the tension (the radius is whatever the tension leaves).
    The contact filter and the model update live; when a contact change is
    declared the circle continues about the new contact.

    Success: the cable's direction (from the contact to the gripper, as the
    force measures it) has turned ``angle`` about ``axis``. Failure:
    ``slipped`` if the tension stays below a fifth of its set point for
    ``slack_time`` after having been taut; ``timeout``.

    Args:
        arm: The gripper that holds the cable (it carries the FT sensor).
        angle: Angle [rad] to turn, right-handed about ``axis``.
        axis: Rotation axis, world frame (default z).  # (3,)
        speed: Angular speed [rad/s].
        force: Tension set point [N]; default the context's (from D) or 3 N.
        about: Name of the fixture the rotation is about (a label only).
        slack_time: Longest time [s] the cable may be slack.
        timeout: Longest run time [s]; default three times the nominal time.
    """

    name = "rotate_around_feature_point"
    letter = "I"

    def __init__(
        self,
        arm: Arm,
        angle: float,
        axis: ArrayLike = (0.0, 0.0, 1.0),
        speed: float = 0.3,
        force: float | None = None,
        about: str | None = None,
        slack_time: float = 1.0,
        timeout: float | None = None,
    ) -> None:
        if arm not in ("left", "right"):
            raise InvalidArgumentError(f"arm must be 'left' or 'right', got {arm!r}")
        if not (math.isfinite(angle) and angle != 0.0):
            raise InvalidArgumentError(f"angle must be a non-zero number of rad, got {angle}")
        if not (speed > 0.0 and math.isfinite(speed)):
            raise InvalidArgumentError(f"speed must be > 0 rad/s, got {speed}")
        a = np.asarray(axis, dtype=float).reshape(3)
        if not np.all(np.isfinite(a)) or norm3(a) < 1e-9:
            raise InvalidArgumentError(f"axis must be a non-zero 3-vector, got {axis!r}")
        if force is not None and not (force > 0.0 and math.isfinite(force)):
            raise InvalidArgumentError(f"force must be > 0 N, got {force}")
        nominal = abs(angle) / speed
        super().__init__(timeout if timeout is not None else 3.0 * nominal + 5.0)
        self.arm: Arm = arm
        self.angle = float(angle)
        self.axis = a / norm3(a)
        self.speed = float(speed)
        self.force = force
        self.about = about
        self.slack_time = float(slack_time)
        self.turned = 0.0  # angle [rad] the cable's direction has turned so far
        self._previous: np.ndarray | None = None
        self._slack_since: float | None = None
        self._ever_taut = False

    def on_start(self, obs: Observation, ctx: PrimitiveContext) -> None:
        """Remember the start; reset the success criteria."""
        if self.force is None:
            self.force = ctx.tension if ctx.tension is not None else 3.0
        ctx.estimator.learn_elasticity = False
        ctx.estimator.rotation = (self.axis, math.copysign(1.0, self.angle))
        self.turned = 0.0
        self._previous = None
        self._slack_since = None
        self._ever_taut = False

    def on_step(self, obs: Observation, ctx: PrimitiveContext) -> Command:
        """Update the model, run the hybrid controller, judge the outcome."""
        assert self.force is not None
        state = ctx.estimator.update(obs)
        me = obs.gripper(self.arm)
        # the angle turned is the cable direction's: it does not jump when the
        # contact estimate does, and its noise does not add up (increments telescope)
        radial = -state.direction
        radial = radial - self.axis * float(self.axis @ radial)
        if state.taut:
            self._track_angle(radial)
        # set point ahead on the circle: P control with gain k_p then moves
        # tangentially at speed * radius (feed-forward through the set point)
        offset = me.position - state.contact
        radius = float(norm3(offset - self.axis * float(self.axis @ offset)))
        speed = self.speed
        limit = 0.9 * float(min(ctx.limits.max_linear_speed))
        if radius * speed > limit:  # stay within the speed limit: slower, not off the circle
            speed = limit / radius
        step = math.copysign(speed, self.angle) / ctx.controller.motion.k_p
        target = state.contact + _rotate(me.position - state.contact, self.axis, step)
        # keep the tool x-axis along the cable (contact -> gripper), as measured
        q_target = me.orientation
        if state.taut:
            x_axis = rotate(me.orientation, [1.0, 0.0, 0.0])
            q_target = multiply(_shortest_arc(x_axis, -state.direction), me.orientation)
        current = current_pose(obs)
        mine = Pose(target, q_target)
        desired = (
            DualPose(mine, current.right) if self.arm == "left" else DualPose(current.left, mine)
        )
        tensions = (self.force, None) if self.arm == "left" else (None, self.force)
        forces = (state.force, None) if self.arm == "left" else (None, state.force)
        directions = (state.direction, None) if self.arm == "left" else (None, state.direction)
        twist = ctx.controller(
            current, desired, tensions, forces, ctx.estimator.elasticity.k_hat, directions
        )
        self._judge(obs, state.tension, state.taut)
        return Command(twist)

    def _track_angle(self, radial: np.ndarray) -> None:
        if self._previous is not None and norm3(radial) > 1e-6:
            cross = float(self.axis @ cross3(self._previous, radial))
            dot = float(self._previous @ radial)
            self.turned += math.atan2(cross, dot)
        if norm3(radial) > 1e-6:
            self._previous = radial.copy()

    def _judge(self, obs: Observation, tension: float, taut: bool) -> None:
        assert self.force is not None
        self._ever_taut |= taut
        if self.turned * math.copysign(1.0, self.angle) >= abs(self.angle):
            self.outcome = Outcome.success(
                f"turned {math.degrees(self.turned):.0f} deg about {self.about or 'the contact'}"
            )
            return
        if self._ever_taut and tension < 0.2 * self.force:
            if self._slack_since is None:
                self._slack_since = obs.time
            elif obs.time - self._slack_since > self.slack_time:
                self.outcome = Outcome.failure(
                    "slipped", f"the cable went slack ({tension:.2f} N) while rotating"
                )
        else:
            self._slack_since = None
