"""C - Parallel DLO Clipping: press the cable between the grippers into a clip."""

from __future__ import annotations

import math

import numpy as np

from tautwire.control import CoordinatedPose, DualPose, Pose, coordinated_pose
from tautwire.estimation.force_line import line_point
from tautwire.model.quaternion import multiply, orientation_along, rotate
from tautwire.model.vector3 import norm3
from tautwire.primitives.arm_control import current_pose
from tautwire.primitives.clip_sensing import ClipHeight, push_tension
from tautwire.primitives.context import ClipInfo, PrimitiveContext
from tautwire.primitives.low_pass import LowPass
from tautwire.primitives.model_edits import add_on_sensing_edge, drop_new_points
from tautwire.primitives.outcome import Outcome
from tautwire.primitives.pair_transport import PairTransport
from tautwire.primitives.parallel_tension import held_between_grippers
from tautwire.primitives.primitive import Primitive
from tautwire.primitives.slack_watch import SlackWatch
from tautwire.robot import Command, Observation

#: Height [m] above the seat at which the cable is brought over the clip.
ABOVE = 0.015
#: Speed [m/s] at which both grippers descend while pushing.
PUSH_SPEED = 0.015
#: Steepest angle [rad] of the cable on either side of the clip before giving up.
MAX_ANGLE = math.radians(60.0)
#: Lowest height [m] above the table the grippers may go.
TABLE_CLEARANCE = 0.015
#: Half a turn about the tool z-axis [w, x, y, z]: the tool frame with x reversed.
HALF_TURN_Z = np.array([0.0, 0.0, 0.0, 1.0])
#: Largest angle [rad] by which the set point of the line between the grippers leads it.
LEAD = math.radians(6.0)
#: The push begins once the line between the grippers is within this angle [rad] of the slot.
SLOT_TOLERANCE = math.radians(3.0)
#: Largest pull [N] along the line between the grippers that the cable outside
#: the pair may make on the pair before the pair gives way along the slot
#: (:meth:`ParallelClipping._give_way`). A clip lets a slack cable slide
#: through it: on random boards 467180584 (seed 29) and 1729667587 (seed 30)
#: the near gripper, carried round towards the clip behind it (F2) on the way
#: to F3, left that span slack, the slack span hanging between F1 and F2
#: drew 40-45 mm through F2, and at the end pose the near span, then 80 mm
#: long, went taut: 3 -> 13.5 N in half a second (stiff: about 3 N/mm), a
#: protective stop.
OUTSIDE_PULL = 1.5
#: Speed [m/s] at which the pair's set point gives way along the slot at twice ``OUTSIDE_PULL``.
GIVE_WAY_SPEED = 0.05
#: Time constant [s] of the low-pass on the pull from outside the pair.
OUTSIDE_TIME = 0.03
#: Least distance [m] kept between a gripper and the nearer end of the clip when giving way.
GIVE_WAY_MARGIN = 0.015


def _towards(a: np.ndarray, b: np.ndarray, limit: float) -> np.ndarray:
    """Unit vector ``a`` turned towards unit vector ``b`` by at most ``limit`` [rad]."""
    c = min(max(float(a @ b), -1.0), 1.0)
    angle = math.acos(c)
    if angle <= limit:
        return b.copy()
    ortho = b - c * a
    n = float(np.linalg.norm(ortho))
    if n < 1e-12:  # opposite: any normal in the horizontal plane
        ortho, n = np.array([-a[1], a[0], 0.0]), float(np.hypot(a[0], a[1])) or 1.0
    out: np.ndarray = math.cos(limit) * a + math.sin(limit) * ortho / n
    return out


def near_side(ctx: PrimitiveContext, seat: np.ndarray, slot: np.ndarray) -> float | None:
    """The sign s for which the left gripper ends on the seat's ``s * slot`` side.

    The cable runs from a fixed point (a contact or a fixed point of the
    model, the nearest one outside the span between the grippers) to the
    near gripper, over the clip and on to the far gripper; the near gripper
    has to end between that fixed point and the clip. Held with the other
    end's line across the slot, the shorter turn onto the slot can take it
    to the far side instead, beyond the cable it holds past the fixed point
    (random board 905979088's C into F6: the pair lay 96 deg from the slot
    the right way, 84 the wrong way; the near gripper went round, and its
    span pulled 13.8 N while the span between the grippers held 3 N).

    Returns:
        +1 or -1; None where the model has no fixed point outside the
        grippers, or it lies within 10 deg of square to the slot from the
        seat (either side then fits).
    """
    graph = ctx.graph
    left = graph.index_of("gripper", "left")
    right = graph.index_of("gripper", "right")
    if left is None or right is None:
        return None
    lo, hi = sorted((left, right))
    fixed = [i for i, p in enumerate(graph.points) if p.kind in ("fixed", "contact")]
    before = [i for i in fixed if i < lo]
    after = [i for i in fixed if i > hi]
    if before:
        anchor, near = before[-1], lo
    elif after:
        anchor, near = after[0], hi
    else:
        return None
    to_fixed = graph.points[anchor].position - seat
    to_fixed[2] = 0.0
    distance = norm3(to_fixed)
    along = float(to_fixed @ slot)
    if distance < 1e-9 or abs(along) < math.sin(math.radians(10.0)) * distance:
        return None
    side = 1.0 if along > 0.0 else -1.0  # the near gripper's side of the seat
    return side if near == left else -side


class ParallelClipping(Primitive):
    """Primitive C: both grippers hold the cable taut over a clip and push it in.

    Coordinated hybrid control: the absolute pose brings the middle of the
    cable between the grippers ``ABOVE`` over the clip's seat with the
    cable along the slot, turning and moving in step so that the near
    gripper stays within the cable it holds past the fixed point behind it
    (:mod:`~tautwire.primitives.pair_transport`); the grippers' distance is force-controlled (A's
    tension, raised to three times the clip's push force while pushing:
    :func:`push_tension`). The absolute pose then descends: the cable bends
    over the clip at 2 f sin(alpha), until the snap is felt from the sensing
    gripper's force line (:class:`ClipHeight`). The grippers rise again to
    the seat's height, where a clipped cable lies straight in the seat,
    unloaded (higher, the tension would pull up on a weak clip: 2 f sin of
    the slope), and an unclipped one still rests on the jaws; if the force
    line reaches the seat, the cable is in, and the model gets a fixed point
    at the clip. Either tool axis of a gripper may run along the cable: one
    whose x points from the right gripper towards the left is controlled
    through its tool frame turned half about z, so no gripper turns by more
    than a quarter (a half turn would wrap the cable round a fingertip).

    Failure: ``not_clipped`` if no snap is felt down to the steepest bend or
    the table, or the cable came out when lifted (the paper's one clipping
    failure: grippers too far apart for a steep enough bend);
    ``precondition`` if the cable is not held by both grippers; ``slipped``;
    ``timeout``.

    Args:
        clip: Name of the clip (the board design gives its seat and slot).
        timeout: Longest run time [s].
    """

    name = "parallel_clipping"
    letter = "C"

    def __init__(self, clip: str, timeout: float = 25.0) -> None:
        super().__init__(timeout)
        self.clip = clip
        self.phase = "align"
        self.drop = 0.0  # how far [m] the grippers have descended below the align height
        self.shift = 0.0  # how far [m] the pair gave way along the slot (sign: along the line)

    def on_start(self, obs: Observation, ctx: PrimitiveContext) -> None:
        """Check the preconditions; plan the pose over the clip."""
        ctx.estimator.learn_elasticity = False
        ctx.estimator.rotation = None
        self.phase = "align"
        self.drop = 0.0
        self.shift = 0.0
        self._outside: LowPass[float] = LowPass(OUTSIDE_TIME)
        self._slack = SlackWatch(1.0)
        info = ctx.clips.get(self.clip)
        if info is None:
            self.outcome = Outcome.failure("precondition", f"no clip named {self.clip!r}")
            return
        if not held_between_grippers(ctx):
            self.outcome = Outcome.failure(
                "precondition", "parallel clipping needs the cable held by both grippers"
            )
            return
        self.info: ClipInfo = info
        self.sensing = ClipHeight(info.position, info.slot, 0.5 * info.length)
        self.force = push_tension(info.push_force, ctx.tension, ctx.limits.max_force)
        self._base_force = ctx.tension if ctx.tension is not None else 2.0
        self._known = [id(p) for p in ctx.graph.points]
        # the cable along the slot, the near gripper on the side of the fixed
        # point behind it (else each gripper staying on its side)
        rel = obs.left.position - obs.right.position
        sense = near_side(ctx, info.position, info.slot)
        if sense is None:
            sense = 1.0 if float(rel @ info.slot) >= 0.0 else -1.0
        self._rel_dir = sense * info.slot  # p_left - p_right direction
        self._q = orientation_along(-self._rel_dir)  # x from left towards right
        # either tool axis may run along the cable: a gripper whose x points
        # from right to left is controlled through its frame turned half
        # about its own z, so that neither is turned by more than a quarter
        self._flip = tuple(
            float(rotate(g.orientation, [1.0, 0.0, 0.0]) @ -self._rel_dir) < 0.0
            for g in (obs.left, obs.right)
        )
        # the pair carried to over the seat turning and moving in step: the
        # near gripper may not swing out beyond the cable it holds past the
        # fixed point behind it (pair_transport.py)
        rel_now = obs.left.position - obs.right.position
        self._transport = PairTransport(
            0.5 * (obs.left.position + obs.right.position),
            rel_now,
            self._goal(),
            self._rel_dir,
        )
        self._since = obs.time

    def _goal(self) -> np.ndarray:
        """The middle's set point [m]: over the seat, ``drop`` below ``ABOVE``, ``shift`` aside."""
        out: np.ndarray = (
            self.info.position
            + self.shift * self._rel_dir
            + np.array([0.0, 0.0, ABOVE - self.drop])
        )
        return out

    def _give_way(self, obs: Observation, period: float) -> None:
        """Shift the pair's set point along the slot, towards a pull from outside the pair.

        Both wrists measure what the cable pulls on them: the span between
        the grippers pulls the two equally and oppositely (its weight
        aside), so their sum is what the cable outside the pair pulls, the
        span from the near gripper back to the fixed point behind it above
        all. Planned slack, that span can go taut where a clip let cable
        slide through it (:data:`OUTSIDE_PULL`); the pair then gives way
        along the line towards that pull, the seat staying between the
        grippers ``GIVE_WAY_MARGIN`` inside the clip's ends (the push needs
        the cable over the seat, not the seat in the middle). With one
        wrist sensor the sum is not measured and the pair does not give way.
        """
        if not (obs.has_sensor("left") and obs.has_sensor("right")):
            return
        total = obs.wrench("left").force + obs.wrench("right").force
        pull = self._outside.update(obs.time, float(total @ self._rel_dir))
        excess = abs(pull) - OUTSIDE_PULL
        if excess <= 0.0:
            return
        half = 0.5 * norm3(obs.left.position - obs.right.position)
        reach = max(half - 0.5 * self.info.length - GIVE_WAY_MARGIN, 0.0)
        rate = GIVE_WAY_SPEED * min(excess / OUTSIDE_PULL, 1.0)
        step = math.copysign(rate * period, pull)
        self.shift = min(max(self.shift + step, -reach), reach)
        self._transport.goal = self._goal() + np.array([0.0, 0.0, self.drop])

    def _tool_frames(self, obs: Observation) -> DualPose:
        """Both grippers' poses, a flipped one's frame turned half about its z."""
        poses = current_pose(obs)
        left, right = poses.left, poses.right
        if self._flip[0]:
            left = Pose(left.position, multiply(left.orientation, HALF_TURN_Z))
        if self._flip[1]:
            right = Pose(right.position, multiply(right.orientation, HALF_TURN_Z))
        return DualPose(left, right)

    def _desired(self, obs: Observation) -> CoordinatedPose:
        """The set point: over the clip, the line between the grippers turning onto the slot.

        The line's set point leads the grippers' line by at most ``LEAD``,
        and the orientations follow that set point: the tool axes turn only
        as fast as the grippers carry the cable round, and stay along it (set
        straight onto the slot, the orientations turned at the speed limit
        while the positions lagged, the cable bent round both fingertips and
        its tension rose from 3 to 14 N in half a second after H). While
        aligning, the middle and the turn advance in step
        (:class:`~tautwire.primitives.pair_transport.PairTransport`).
        """
        rel = obs.left.position - obs.right.position
        distance = float(np.linalg.norm(rel))
        line = rel / max(distance, 1e-12)
        if self.phase == "align":
            middle = 0.5 * (obs.left.position + obs.right.position)
            direction = _towards(line, self._transport.heading(middle), LEAD)
            centre = self._transport.centre(line)
        else:
            direction = _towards(line, self._rel_dir, LEAD)
            centre = self._goal()
        return CoordinatedPose(
            Pose(centre, orientation_along(-direction)),
            Pose(distance * direction, np.array([1.0, 0.0, 0.0, 0.0])),
        )

    def on_step(self, obs: Observation, ctx: PrimitiveContext) -> Command:
        """Align, push, lift, verify; the distance under tension control throughout."""
        state = ctx.estimator.update(obs)
        if self.outcome.done:
            return Command()
        sensor = obs.gripper(ctx.estimator.arm)
        wrench = obs.wrench(ctx.estimator.arm)
        # where the cable leaves the fingers: on the force's line of action
        # (behind or beside the tool centre point after a regrip, B)
        leaves = line_point(sensor.position, wrench.force, wrench.torque)
        height = self.sensing.update(obs.time, leaves, state.direction, state.taut)
        force = self._base_force
        self._give_way(obs, ctx.control_period)
        now = coordinated_pose(self._tool_frames(obs))
        if self.phase == "align":
            rel = obs.left.position - obs.right.position
            along = float(rel @ self._rel_dir) / max(norm3(rel), 1e-12)
            over = norm3(now.absolute.position - self._goal()) < 0.003
            if over and along >= math.cos(SLOT_TOLERANCE):  # over the seat, along the slot
                self.phase, self._since = "push", obs.time
        elif self.phase == "push":
            force = self.force
            self.drop = PUSH_SPEED * (obs.time - self._since)
            half = 0.5 * float(np.linalg.norm(obs.left.position - obs.right.position))
            angle = math.atan2(self.drop - ABOVE, max(half, 1e-3))
            low = min(obs.left.position[2], obs.right.position[2]) < TABLE_CLEARANCE
            if self.drop > ABOVE and self.sensing.seated:
                self.phase, self._since = "lift", obs.time
            elif angle > MAX_ANGLE or low:
                where = "the table" if low else "the steepest bend"
                self.outcome = Outcome.failure(
                    "not_clipped",
                    f"no snap felt into {self.clip} down to {where}"
                    f" (cable {1e3 * (height or 0.0):.1f} mm above its seat): hold the cable"
                    " with the grippers closer together or tension it more",
                )
        else:  # lift to the seat's height and feel whether the cable stayed in
            self.drop = max(self.drop - 2.0 * PUSH_SPEED * ctx.control_period, ABOVE)
            reached = norm3(now.absolute.position - self._desired(obs).absolute.position) < 0.003
            if self.drop <= ABOVE and reached and obs.time - self._since > 0.3:
                self._verify(ctx, sensor.position)
        if self._slack.update(obs.time, state.tension, force):
            self.outcome = Outcome.failure("slipped", "the cable went slack while clipping")
        return Command(
            ctx.controller.coordinated(
                self._tool_frames(obs),
                self._desired(obs),
                force,
                state.tension,
                ctx.estimator.elasticity.k_trusted,
            )
        )

    def _verify(self, ctx: PrimitiveContext, p_sensor: np.ndarray) -> None:
        verdict = self.sensing.verdict(self.clip)
        if verdict.status != "success":
            self.outcome = verdict
            return
        # the clip lies on the straight cable from the sensing gripper, towards the other
        est = ctx.estimator
        drop_new_points(ctx.graph, self._known)
        g, c = est.gripper_index, est.contact_index
        towards = 1.0 if c is not None and c > g else -1.0
        arc = float(ctx.graph.arc_lengths()[g]) + towards * norm3(self.info.position - p_sensor)
        add_on_sensing_edge(est, arc, self.info.position, "fixed", self.clip)
        self.outcome = verdict
