"""F - Single arm DLO Clipping: press the taut cable into a clip, pivoting about its contact."""

from __future__ import annotations

import math

import numpy as np

from tautwire.control import Pose
from tautwire.errors import InvalidArgumentError
from tautwire.estimation.force_line import line_point
from tautwire.model.vector3 import norm3
from tautwire.primitives.arm_control import current_pose, tension_twist, with_pose
from tautwire.primitives.clip_sensing import (
    JAW_TOP,
    MAX_FAR_RISE,
    SIDEWAYS,
    ClipHeight,
    PivotPress,
    far_rise,
    push_tension,
)
from tautwire.primitives.clip_tug import TUG_SETTLE, ClipTug, TugReading, tug_angle
from tautwire.primitives.context import ClipInfo, PrimitiveContext
from tautwire.primitives.low_pass import LowPass
from tautwire.primitives.model_edits import add_on_sensing_edge, drop_new_points
from tautwire.primitives.model_estimator import TensionState
from tautwire.primitives.outcome import Outcome
from tautwire.primitives.peg_leave import axis_offset, leave_point, path_turn, wrap_side
from tautwire.primitives.primitive import Primitive
from tautwire.primitives.slack_watch import SlackWatch
from tautwire.primitives.slot_swing import SlotSwing, turn_onto, turned
from tautwire.primitives.tool_axis import ToolAxis
from tautwire.robot import Arm, Command, Observation

#: Height [m] above the seat at which the cable is brought over the clip.
ABOVE = 0.015
#: Rate [rad/s] at which the gripper pivots down about the clip while pushing.
PUSH_RATE = 0.15
#: Pivot angle [rad] pressed on past the felt snap (and deeper on each new attempt).
PRESS_EXTRA = 0.05
#: Pushes before a cable that did not stay in counts as not clipped.
ATTEMPTS = 3
#: Times the cable, found beside the slot at rest after a push, is brought over
#: the clip again (the alignment) and pushed anew. A cable left on the jaws'
#: crest, not in, is drawn off them sideways by the tug that checks it (random
#: board 1754934167, seed 17: read in at 5 mm over the seat, the tug drew it
#: 9.6 mm beside the slot, and the next push took it down beside the clip).
REALIGNS = 1
#: Share of the turn onto the slot (:mod:`~tautwire.primitives.slot_swing`)
#: made after each new alignment. The whole turn leaves the far side's kink,
#: f sin(alpha), all at the entry end, pulling the cable across towards the
#: far contact; where the groove does not hold it, the cable slides off the
#: jaws on that side, and the same turn again slides it off again (random
#: board 225583068's F1, 8 deg from an anchor 117 mm away, at 6 N: 3.8 mm
#: across the slot when it fell beside the clip, twice). Half the turn
#: splits the kink between the clip's ends, and the cable snapped in there;
#: with no turn at all it stayed on the jaws, crossing them diagonally.
REALIGN_SWING = 0.5
#: Time [s] a new alignment adds to the primitive's timeout.
REALIGN_TIME = 12.0
#: Steepest angle [rad] of the cable below the clip before giving up.
MAX_ANGLE = math.radians(60.0)
#: Lowest height [m] above the table the gripper's tool centre point may go
#: (its finger pads reach 8 mm below it).
TABLE_CLEARANCE = 0.02
#: Largest angle [rad] between the cable and the clip's slot.
MAX_SLOT_ANGLE = math.radians(25.0)
#: Farthest [m] the gripper may be from its aligning set point to start the push.
ALIGN_TOLERANCE = 0.003
#: Farthest [m] the cable's line may pass beside the seat to start the push:
#: a cable whose centre passes outside a jaw's axis (2.6 mm off the slot's
#: centre line for a 2.5 mm cable) is pushed down beside the jaws (the
#: shipped harness's C2: 4.6 mm beside, with the gripper 3 mm off its set
#: point and the cable 2 mm beside the tool centre point). A cable that comes
#: in at alpha crosses the clip diagonally, 15 mm tan(alpha) to either side
#: at its ends: at 8 deg 0.5 mm inside the jaws' axes is left to aim with (a
#: level anchor-clip scene, 8-12 deg off: 4 of 6 seated at 0.7 mm, 10 of 10
#: at 0.3 mm).
ALIGN_MISS = 0.0003
#: Longest time [s] the push waits at the table for the gripper to get down
#: to its set point (force control along the sloping cable lags: random board
#: 1652323633's F1 stopped 11 mm above the floor, a sixth of the drop lost).
FLOOR_DWELL = 1.0
#: How near [m] the floor the gripper must come for the push to end there sooner.
FLOOR_REACHED = 0.002
#: Time constant [s] of the low-pass on where the cable leaves the fingers.
EXIT_TIME = 0.2
#: Smallest turn [rad] of the cable's path round a peg from which the path,
#: not the force's line, says which side of the peg the cable leaves by.
PATH_SIDE_TURN = math.radians(10.0)
#: Largest shift [m] of the far contact, across the line, that the measured
#: pull may make while aligning (beyond it the line bears on something else).
MAX_LINE_SHIFT = 0.01
#: Largest height [m] by which the measured pull may move a peg's leave point
#: up or down while aligning (a peg stands 60 mm tall).
MAX_LINE_RISE = 0.04
#: The measured line may bear on the clip where it passes lower than this
#: [m] over the jaws' top, within ``SIDEWAYS`` of the slot (a cable's radius).
BEARS_ABOVE = 0.003


class SingleArmClipping(Primitive):
    """Primitive F: clip the cable between a fixed point and the gripper.

    The cable is taut from its contact c (an estimated or fixed point) to
    the gripper; from a peg, c is where the cable leaves it tangentially
    (:meth:`_leave`), not the peg's axis. With D's force control along the
    cable, the gripper first moves on the sphere about c (radius: what the
    tension leaves) until the cable's straight line passes ``ABOVE`` over
    the clip's seat q, along the slot: where the cable leaves the fingers
    (on the force's line of action, :meth:`_target`) goes onto the line,
    which runs from c moved across onto the measured pull's line
    (:meth:`_measured_shift`: a stiff cable bent at c leaves it beside c;
    not from a peg, whose tangent leave point the model places, but whose
    height the pull's slope gives, as the cable slides along a peg,
    :meth:`_measured_rise`; nor from an
    anchor, which the cable turns about at a known point; from a clip the
    alignment runs at the push's tension, as the bend there tightens with it),
    and the push starts once the line passes within ``ALIGN_MISS`` of the
    seat (:meth:`_aligned`); then it pivots down about the clip's
    exit at ``PUSH_RATE`` (turning about it onto the slot's axis once the
    cable rests on the jaws, where the cable crosses the slot at an angle:
    :mod:`~tautwire.primitives.slot_swing`), with the tension raised to three times the clip's
    push force (:func:`push_tension`); where a soft cable's stretch would
    then leave too shallow a bend above the table to press ``PRESS_MARGIN``
    times the push force, to the nearest tension that does
    (:class:`PivotPress`, from the contact, the clip's design and k). The
    snap is felt (:class:`ClipHeight`): the force's line drops from the jaws
    to the seat. The gripper presses on by ``PRESS_EXTRA``, then lifts back
    to the straight line from c through the seat (a clipped cable lies there
    unloaded; an unclipped one rests on the jaws); if the force's line still
    reaches the seat, it tugs: lifts the gripper a few degrees about the
    clip's exit (:mod:`~tautwire.primitives.clip_tug`). A pull that turns
    about the clip, not about the far contact, proves the clip holds the
    cable without trusting where it leaves the fingers; it then presses the
    cable home again and lifts back, and if the line still reaches the
    seat, the model gets a fixed point at q. If the line does not reach the
    seat, it pushes again, deeper, up to ``ATTEMPTS`` times. Where the line
    at rest passes the slot's exit beside the channel (beyond ``SIDEWAYS``),
    or the tug turned the pull about the far contact, the cable is brought
    over the clip again (the alignment) and pushed anew, ``REALIGNS`` times,
    each time with ``REALIGN_SWING`` of the last turn onto the slot.

    Where no snap is felt down to ``MAX_ANGLE`` or the table
    (``TABLE_CLEARANCE``), it lifts back all the same and judges the line at
    rest: bent steeply, the line reads high by the bend's offset beyond the
    exit times the bend's slope, and a snap can go unread.

    Failure: ``not_clipped`` if the cable is not seated at rest after the last
    attempt (after a push with no snap felt, the message gives the planned
    press against the clip's push force), or the tug turned the pull about
    the far contact after the new alignments;
    ``precondition`` if the clip is not between the contact and the gripper
    or its slot is across the cable, or the cable rises more
    than :data:`~tautwire.primitives.clip_sensing.MAX_FAR_RISE` from the
    clip to the contact; ``slipped`` if the cable
    goes slack; ``timeout``.

    Args:
        arm: The gripper that holds the cable (it carries the sensor).
        clip: Name of the clip (the board design gives its seat and slot).
        timeout: Longest run time [s].
    """

    name = "single_arm_clipping"
    letter = "F"

    def __init__(self, arm: Arm, clip: str, timeout: float = 30.0) -> None:
        super().__init__(timeout)
        if arm not in ("left", "right"):
            raise InvalidArgumentError(f"arm must be 'left' or 'right', got {arm!r}")
        self.arm: Arm = arm
        self.clip = clip
        self.phase = "align"
        self.angle = 0.0  # how far [rad] the gripper has pivoted below the clip
        self.press = 0.0  # the press [N] on the clip planned for the push tension
        self._line_shift = np.zeros(3)  # the far contact onto the measured line [m]
        self._line_shift_filter: LowPass[np.ndarray] = LowPass(EXIT_TIME)
        self._line_rise = 0.0  # a peg's leave point up onto the measured line [m]
        self._line_rise_filter: LowPass[float] = LowPass(EXIT_TIME)
        self._bent_exit = False  # the cable bends out of a clip (set at the start)
        self._exit_way = np.zeros(3)  # along that clip's slot, out of its exit (horizontal)

    def on_start(self, obs: Observation, ctx: PrimitiveContext) -> None:
        """Check the clip against the model; plan the pivot plane."""
        info = ctx.clips.get(self.clip)
        ctx.estimator.learn_elasticity = False
        ctx.estimator.rotation = None
        # its lines bend over the clip it presses into, not the contact
        ctx.estimator.observe_contacts = False
        self.phase = "align"
        self.angle = 0.0
        self._angle0 = 0.0
        self._angle_rest = 0.0
        self._deeper = 0.0  # the snap counts only beyond this pivot angle [rad]
        self._pressed_to = 0.0
        self.attempts = 1
        self.realigns = 0
        self.floor = TABLE_CLEARANCE  # the board is the plane z = 0
        self._at_floor: float | None = None  # when the push's set point reached the floor
        self._axis = ToolAxis()
        self._hold = current_pose(obs)
        self._slack = SlackWatch(1.0)
        self._exit_offset: LowPass[np.ndarray] = LowPass(EXIT_TIME)
        self._offset = np.zeros(3)
        self._line_shift_filter = LowPass(EXIT_TIME)
        self._line_shift = np.zeros(3)
        self._line_rise_filter = LowPass(EXIT_TIME)
        self._line_rise = 0.0
        self._rises = False  # a peg's leave point moves up or down onto the measured line
        self._span = (-math.inf, math.inf)  # heights [m] the far contact may be moved between
        self._tug = ClipTug(np.array([1.0, 0.0, 0.0]))  # its plane is set when the push starts
        self._tug_reading: TugReading | None = None
        self._reached: float | None = None
        self._line_at_rest = ""  # the force line's verdict at rest, before the tug
        self._no_snap = ""  # what the push read when it found no snap down to its bottom
        self._lead = 0.0  # cable [m] from the contact's model point to where it leaves it
        self._shifts = True  # the far contact moves onto the measured line (not from a peg)
        self._bent_exit = False  # the cable bends out of a clip: align at the push's tension
        self._exit_way = np.zeros(3)  # along that clip's slot, out of its exit (horizontal)
        self._swing = SlotSwing(0.0, JAW_TOP)  # onto the slot once on the jaws (set at the push)
        self._on_line = np.zeros(3)  # over the exit on the aimed line (set at the push) [m]
        if info is None:
            self.outcome = Outcome.failure("precondition", f"no clip named {self.clip!r}")
            return
        self.info: ClipInfo = info
        self.sensing = ClipHeight(info.position, info.slot, 0.5 * info.length)
        state = ctx.estimator.update(obs)
        c = state.contact
        self._contact = self._leave(ctx, state, obs.gripper(self.arm).position, info)
        self._known = [id(p) for p in ctx.graph.points]
        seat = info.position
        along = seat - c
        along[2] = 0.0
        out = obs.gripper(self.arm).position - c
        reach = float(np.hypot(out[0], out[1]))
        if float(np.linalg.norm(along)) > reach - 0.02:
            self.outcome = Outcome.failure(
                "precondition", f"clip {self.clip} is not between the contact and the gripper"
            )
            return
        angle = math.acos(
            min(1.0, abs(float(along @ info.slot)) / max(float(np.linalg.norm(along)), 1e-9))
        )
        if angle > MAX_SLOT_ANGLE:
            self.outcome = Outcome.failure(
                "precondition",
                f"the slot of {self.clip} is {math.degrees(angle):.0f} deg across the cable",
            )
            return
        rise = far_rise(self._contact, seat, info.slot, 0.5 * info.length)
        if rise > MAX_FAR_RISE:
            self.outcome = Outcome.failure(
                "precondition",
                f"the cable rises {math.degrees(rise):.1f} deg from {self.clip} to its contact"
                f" (at most {math.degrees(MAX_FAR_RISE):.0f}): its far side would hold the"
                " slot's entry end up in the jaws' throat, which reads as clipped; hold the"
                " contact's side lower or clip with both arms (C)",
            )
            return
        self.force = push_tension(info.push_force, ctx.tension, ctx.limits.max_force)
        self._base_force = ctx.tension if ctx.tension is not None else 2.0
        self._since = obs.time

    def _leave(
        self, ctx: PrimitiveContext, state: TensionState, p_gripper: np.ndarray, info: ClipInfo
    ) -> np.ndarray:
        """Where the cable leaves its contact on the way over the clip [m].

        A point contact (an anchor, an estimated point): the contact
        itself. A clip: the end of its slot away from the constrained point
        before it (:meth:`ClipInfo.exit_towards`), where the cable leaves its
        jaws, whichever way it turns after.
        A peg: the cable leaves it tangentially, its radius
        (the filter's estimate, else the design's peg + cable radius) beside
        the axis point the model holds, on the side it wraps it now: the
        side the model's path turns round the peg
        (:func:`~tautwire.primitives.peg_leave.path_turn`, from the
        windings the model followed round it and from the constrained
        point before it) where it turns by ``PATH_SIDE_TURN`` or more, or
        where the force's line passes within half the radius of the axis,
        too near to tell; else the side of the force's line
        (:func:`~tautwire.primitives.peg_leave.wrap_side`): the tangent
        point of the line over the clip
        (:func:`~tautwire.primitives.peg_leave.leave_point`). Aiming from the
        axis would put the cable a radius beside the slot.
        """
        c = state.contact.copy()
        est = ctx.estimator
        i = est.contact_index
        label = ctx.graph.points[i].label if i is not None else ""
        clip_before = ctx.clips.get(label)
        if clip_before is not None and label != self.clip:
            # a clip the cable is in: it leaves by the slot's end (random
            # boards 2082005138, 2071274635, 208802845: F aimed from the
            # seat of the clip before, and the cable slid off the jaws)
            # it leaves by the end away from where it came in, whichever
            # way it turns after (random board 914356660's W2 turns 163 deg
            # out of F6 towards F7: aimed from the end towards F7, F pushed
            # the cable into F7 12 mm beside its slot)
            came = None if i is None else est.point_before(i)
            away = (
                info.position
                if came is None
                else 2.0 * clip_before.position - np.asarray(came.position, dtype=float)
            )
            exit_point = clip_before.exit_towards(away)
            # its bend beyond the jaws tightens as the tension rises, which
            # moves the straight span's line: F aligns at the push's tension
            # (random board 303464894's F5, 58 deg on from F4: aligned at 3 N
            # over the seat, the push's 7.5 N moved the cable 3 mm aside
            # before it reached the jaws, and it slid off)
            self._bent_exit = True
            self._lead = norm3(exit_point - clip_before.position)  # cable in its jaws [m]
            way = exit_point - clip_before.position
            way[2] = 0.0
            self._exit_way = way / max(float(np.linalg.norm(way)), 1e-9)
            return exit_point
        if label not in est.round_fixtures:
            if label in ctx.fixtures and ctx.graph.points[i].kind == "fixed":  # type: ignore[index]
                # an anchor holds the cable's end at a point, free to turn:
                # its line passes through it, and the measured line would add
                # only its own error (a level 7 deg anchor-clip scene: shifted
                # 3.9 mm, the cable went down 1.6 mm beside the seat, its
                # entry end beyond a jaw's axis, and slid off)
                self._shifts = False
            return c
        # a peg's leave point is its tangent at the estimated radius; the
        # measured line (the wrench's line of action, good to 6-9 mm) adds
        # only its own error there (the shipped harness's C2 from P1:
        # shifted 8.7 mm, the cable went down 3.6-8 mm beside the slot;
        # unshifted, clipped 1.4 mm beside it)
        self._shifts = False
        # but the height the cable leaves a peg at is not known: pulled taut
        # from a lower fixture before it, it slides down the peg (random
        # board 1627120487's F7 from peg F6: the model held it 95.6 mm high,
        # it was at 75 mm, and the cable aimed 15 mm over the seat met the
        # clip's side below its jaws, 7.8 mm beside the slot); the pull's
        # slope tells it (:meth:`_measured_rise`)
        self._rises = True
        self._span = ctx.pegs.get(label, self._span)
        estimate = est.contact_estimate()
        radius = (
            estimate.radius
            if estimate is not None and estimate.radius is not None
            else est.round_fixtures[label][1]
        )
        side = wrap_side(c, p_gripper, state.direction)
        before = None if i is None else est.point_before(i)
        turn = 0.0
        if before is not None and i is not None:
            turn = path_turn(before.position, c, p_gripper, est.wound(i))
        if abs(turn) >= PATH_SIDE_TURN or (
            turn != 0.0 and abs(axis_offset(c, p_gripper, state.direction)) < 0.5 * radius
        ):
            # the cable's path turns round the peg clearly, or the line passes
            # too near the axis to tell the side (1 deg of direction error at
            # 0.3 m is 5 mm): the side the path turns. The shipped harness's
            # C2 from P1 at seeds 0 and 1: P1 estimated 4.9 mm off towards
            # the true leave point, the line passed it 5 mm on the other side,
            # F aimed from the wrong tangent, 17 mm off, and missed the slot
            side = math.copysign(1.0, turn)
        through = info.position + np.array([0.0, 0.0, ABOVE])
        return leave_point(c, radius, through, side)

    def _plan_force(self, p_gripper: np.ndarray, tension: float, ctx: PrimitiveContext) -> float:
        """The push tension [N]: three times the push force, unless the bend cannot press enough.

        Near the table a soft cable's stretch leaves too little room for the
        bend (:class:`PivotPress`): then the tension closest to that which
        presses ``PRESS_MARGIN`` times the push force, from the model (the
        contact, the clip of the board design, k).
        """
        entry = self._exit - 2.0 * (self._exit - self.info.position)
        entry[2] = self._exit[2]
        far = self._far() - entry
        plan = PivotPress(
            radius=norm3(p_gripper - self._exit),
            tension=max(tension, 0.1),
            stiffness=ctx.estimator.elasticity.k_trusted,
            drop=float(self._exit[2]) - self.floor,
            sin_far=float(far[2]) / max(norm3(far), 1e-9),
            sin_max=math.sin(MAX_ANGLE),
        )
        force = plan.tension_for(self.info.push_force, self.force, 0.6 * ctx.limits.max_force)
        self.press = plan.press(force)
        return force

    def _measured_shift(self, time: float, leaves: np.ndarray, direction: np.ndarray) -> np.ndarray:
        """How far [m] the measured line passes beside the far contact, horizontally.

        The taut span is straight from where it leaves the fingers along the
        pull. A stiff cable bent sharply where it leaves a clip, or a peg
        estimated a few mm off, puts that line beside the model's contact c:
        random board 360400295's F5, 50 deg on from F4, was pushed with the
        cable 4 mm beside its seat while the line from c passed over it. The
        shift (low-passed over ``EXIT_TIME``, at most ``MAX_LINE_SHIFT``) moves
        c onto the measured line for the alignment; nothing changes while the
        pull is too short to tell a direction. Out of a clip, only a shift
        towards the side its slot leads to is taken (the bend puts the line
        there, never on the other side).
        """
        d = np.array([direction[0], direction[1], 0.0])
        size = float(np.linalg.norm(d))
        if size < 0.5:  # the pull runs mostly vertically: no horizontal line
            return self._line_shift
        d /= size
        n = np.array([-d[1], d[0], 0.0])
        away = self._contact - leaves
        shift: np.ndarray = -float(away @ n) * n
        if float(np.linalg.norm(shift)) > MAX_LINE_SHIFT:
            return self._line_shift
        if self._bent_exit and float(shift @ self._exit_way) < 0.0:
            # a cable bent out of a clip's slot runs straight on from a
            # virtual corner ahead of the exit, along the slot: its line
            # passes the exit on the slot's side, never the other (random
            # board 1986348794's F5, 24 deg on from F4: the measured line
            # read 4.2 mm beside the exit the other way, F aimed there, the
            # cable met the jaws 2.8 mm beside the slot and went down beside
            # the clip); a reading on the wrong side is the line's error
            shift = np.zeros(3)
        return self._line_shift_filter.update(time, shift)

    def _measured_rise(self, time: float, leaves: np.ndarray, direction: np.ndarray) -> float:
        """How far [m] the measured line passes above a peg's leave point.

        The taut span is straight from where it leaves the fingers along the
        pull, so the pull's slope gives the height it passes over the leave
        point (1 deg of slope is 4 mm at 0.23 m). Low-passed over
        ``EXIT_TIME``, at most ``MAX_LINE_RISE``; nothing changes while the
        pull runs mostly vertically, and the point stays between the peg's
        foot and top. Not read while the line may bear on the clip
        (:meth:`_bears`).
        """
        d = np.asarray(direction, dtype=float)
        n2 = float(d[0] * d[0] + d[1] * d[1])
        if n2 < 0.25:
            return self._line_rise
        away = self._contact - leaves
        lam = float(away[0] * d[0] + away[1] * d[1]) / n2
        if lam <= 0.0:
            return self._line_rise
        z = float(leaves[2]) + lam * float(d[2])
        low, high = self._span  # the cable bears on the peg between its foot and top
        rise = min(max(z, low), high) - float(self._contact[2])
        rise = min(max(rise, -MAX_LINE_RISE), MAX_LINE_RISE)
        return self._line_rise_filter.update(time, rise)

    def _bears(self) -> bool:
        """Whether the measured line may bear on the clip: low over its slot.

        There the line bends at the clip, not at the peg, and says nothing
        of the peg: a cable lying in the seat already, its line extended to
        the peg reading 30 mm low, lifted the gripper until it pulled the
        cable out (the F-from-peg test scene with the clip raised 12 mm).
        """
        height, miss = self.sensing.height, self.sensing.miss
        return (
            height is not None
            and miss is not None
            and height < JAW_TOP + BEARS_ABOVE
            and miss < SIDEWAYS
        )

    def _far(self) -> np.ndarray:
        """The far contact [m] the cable is aimed from: onto the measured line."""
        out: np.ndarray = self._contact + self._line_shift
        out[2] += self._line_rise
        return out

    def _target(self, obs: Observation, state: TensionState) -> np.ndarray:
        """The gripper's set point while aligning: the cable's exit on the line over the clip.

        The cable leaves the fingers where the force's line of action passes
        (low-passed over ``EXIT_TIME``), a few mm beside or behind the tool
        centre point after a regrip (E, B) or a hand-over: that point, not
        the tool centre point, goes onto the line.
        """
        c = self._far()  # on the measured line
        through = self.info.position + np.array([0.0, 0.0, ABOVE])
        w = (through - c) / float(np.linalg.norm(through - c))
        exit_point = obs.gripper(self.arm).position + self._offset
        radius = float(np.linalg.norm(exit_point - c))
        target: np.ndarray = c + radius * w - self._offset
        return target

    def _aligned(self, me: np.ndarray, target: np.ndarray) -> bool:
        """Whether the gripper is near enough its set point, and the cable over the seat.

        The cable's miss beside the seat is the gripper's error across the
        line, scaled down to the seat (the line turns about c).
        """
        error = me - target
        if float(np.linalg.norm(error)) >= ALIGN_TOLERANCE:
            return False
        c = self._far()  # on the measured line
        through = self.info.position + np.array([0.0, 0.0, ABOVE])
        w = through - c
        w[2] = 0.0
        n = np.array([-w[1], w[0], 0.0]) / max(float(np.linalg.norm(w)), 1e-9)
        exit_point = me + self._offset
        reach = float(np.hypot(*(exit_point - c)[:2]))
        share = float(np.linalg.norm(w)) / max(reach, 1e-9)
        return abs(float(error @ n)) * share < ALIGN_MISS

    def _centre(self) -> np.ndarray:
        """The point [m] the gripper pivots about: over the clip's exit, on the aimed line.

        The push starts in the vertical plane of the line aimed over the
        seat, which passes the slot's exit 15 mm sin(alpha) to the side
        where the cable crosses the slot at alpha: pivoting in the plane
        through the exit itself shifted the cable by that much at the start
        (random board 1695658280's F2: 1.8 mm beside the seat when aligned,
        3.6 mm when it met the jaws, beyond a jaw's crest). As the gripper
        turns onto the slot (:class:`SlotSwing`), the centre moves onto the
        exit, on the slot's axis.
        """
        centre: np.ndarray = self._on_line + self._swing.progress * (self._exit - self._on_line)
        return centre

    def _pivot(self, obs: Observation) -> np.ndarray:
        """The set point while pushing: turned down by ``angle`` about the clip's exit.

        Pivoting about the clip (not about the far contact) bends the cable
        over the clip without moving the gripper away from it, so the bend
        angle asin(P / f) is reached with the least descent.
        """
        me = obs.gripper(self.arm).position
        centre = self._centre()
        offset = me - centre
        ahead = float(offset @ self._out)
        radius = math.hypot(ahead, float(offset[2]))
        target: np.ndarray = centre + radius * (
            math.cos(self.angle) * self._out - math.sin(self.angle) * np.array([0.0, 0.0, 1.0])
        )
        return target

    def on_step(self, obs: Observation, ctx: PrimitiveContext) -> Command:
        """Align, push, verify; keep the tension throughout."""
        state = ctx.estimator.update(obs)
        if self.outcome.done:
            return Command()
        me = obs.gripper(self.arm)
        wrench = obs.wrench(self.arm)
        # where the cable leaves the fingers: on the force's line of action,
        # behind or beside the tool centre point after a regrip (E, B)
        leaves = line_point(me.position, wrench.force, wrench.torque)
        if state.taut:
            self._offset = self._exit_offset.update(obs.time, leaves - me.position)
            if self.phase == "align" and self._shifts:
                self._line_shift = self._measured_shift(obs.time, leaves, state.direction)
        height = self.sensing.update(obs.time, leaves, state.direction, state.taut)
        if state.taut and self.phase == "align" and self._rises and not self._bears():
            self._line_rise = self._measured_rise(obs.time, leaves, state.direction)
        if self.phase in ("lift", "tug"):
            self._tug.update(obs.time, wrench.force)
        force = self._base_force
        if self.phase == "align":
            if self._bent_exit:  # the line from a clip moves with the tension
                force = self.force
            target = self._target(obs, state)
            if self._aligned(me.position, target):
                self.phase, self._since = "push", obs.time
                out = me.position - self.info.position
                out[2] = 0.0
                self._out = out / max(float(np.linalg.norm(out)), 1e-9)
                self._tug = ClipTug(self._out)
                share = REALIGN_SWING**self.realigns
                self._swing = SlotSwing(share * turn_onto(self._out, self.info.slot), JAW_TOP)
                self._exit = self.info.exit_towards(me.position)
                self._exit[2] += JAW_TOP
                seat = self.info.position
                self._on_line = seat + float((self._exit - seat) @ self._out) * self._out
                self._on_line[2] = self._exit[2]
                offset = me.position - self._on_line
                self._angle0 = math.atan2(-float(offset[2]), float(offset @ self._out))
                self.angle = self._angle0
                self._deeper = self._angle0 + 0.05
                # lift back only to the straight line from the contact through
                # the seat: a clipped cable then lies in the seat unloaded
                # (a weak clip is not pulled open), an unclipped one on the jaws
                far = self._far()
                rise = float(far[2] - self.info.position[2])
                run = float(np.hypot(*(self.info.position - far)[:2]))
                self._angle_rest = max(math.atan2(rise, run), self._angle0)
                self.force = self._plan_force(me.position, state.tension, ctx)
        elif self.phase in ("push", "press"):
            force = self.force
            # pressed home after a tug at the lift's rate: no snap to feel
            rate = PUSH_RATE if self._tug_reading is None else 2.0 * PUSH_RATE
            if self.phase == "push":
                # resting on the jaws across the slot: turn onto it (slot_swing.py)
                turn = self._swing.step(obs.time, height, self.angle, ctx.control_period)
                if turn != 0.0:
                    self._out = turned(self._out, turn)
                    self._tug = ClipTug(self._out)
            self.angle += rate * ctx.control_period
            target = self._pivot(obs)
            floored = False
            if self.phase == "push" and target[2] < self.floor:
                # at the table: hold the set point there until the gripper
                # is down too (or a dwell passes), feeling for the snap
                self.angle -= rate * ctx.control_period
                target = self._pivot(obs)
                target[2] = max(float(target[2]), self.floor)
                if self._at_floor is None:
                    self._at_floor = obs.time
                floored = (
                    obs.time - self._at_floor >= FLOOR_DWELL
                    or float(me.position[2]) - self.floor <= FLOOR_REACHED
                )
            if self.phase == "press":
                if self.angle >= self._pressed_to or target[2] < self.floor:
                    self.phase, self._since = "lift", obs.time
            elif self.angle > self._deeper and self.sensing.seated:
                # felt the snap: press on a little (the line's height is
                # a few mm uncertain), then lift and verify
                self.phase, self._pressed_to = "press", self.angle + PRESS_EXTRA
            elif self.angle > MAX_ANGLE or floored:
                # no snap read on the way down: lift back and judge at rest.
                # Steeply bent, the line reads high by the bend's offset
                # beyond the exit times tan(angle) (random board 1219064744's
                # F2: the cable snapped in at 42 deg, the line read 7-9 mm
                # above the seat, 16 mm before the snap); at rest it reads true
                where = "the table" if floored else "the steepest bend"
                self._no_snap = (
                    f"no snap felt into {self.clip} down to {where}"
                    f" (cable {1e3 * (height or 0.0):.1f} mm above its seat there; the bend"
                    f" presses about {self.press:.1f} N of the {self.info.push_force:.1f} N it"
                    " needs)"
                )
                self.attempts = ATTEMPTS
                self._pressed_to = self.angle = min(self.angle, MAX_ANGLE)
                target = self._pivot(obs)
                self.phase, self._since = "lift", obs.time
        elif self.phase == "lift":  # back over the clip: feel whether the cable stayed in
            rest = self._angle_rest
            self.angle = max(self.angle - 2.0 * PUSH_RATE * ctx.control_period, rest)
            target = self._pivot(obs)
            settled = obs.time - self._since > 0.3
            if settled and self.angle <= rest and norm3(me.position - target) < 0.003:
                if self.sensing.seated and self._tug_reading is not None:
                    self._verify(ctx)  # tugged, and pressed home again
                elif self.sensing.seated:
                    self._tug.mark_rest(me.position)
                    self._line_at_rest = self.sensing.verdict(self.clip).detail
                    self.phase, self._reached = "tug", None
                elif self._beside() and self.realigns < REALIGNS:
                    self._realign()
                elif self.attempts >= ATTEMPTS:
                    self._verify(ctx)
                else:  # not in: push again, deeper than the last time (and tug again)
                    self.attempts += 1
                    self.phase, self._deeper = "push", self._pressed_to + PRESS_EXTRA
                    self._at_floor = None
                    self._tug_reading = None
        else:  # tug: lift above the line (clip_tug.py)
            goal = self._angle_rest - tug_angle(self.info.push_force, self._base_force)
            self.angle = max(self.angle - 2.0 * PUSH_RATE * ctx.control_period, goal)
            target = self._pivot(obs)
            if self.angle == goal and norm3(me.position - target) < 0.003:
                self._reached = obs.time if self._reached is None else self._reached
            if self._reached is not None and obs.time - self._reached > TUG_SETTLE:
                self._read_tug(me.position)
        if self._slack.update(obs.time, state.tension, force):
            self.outcome = Outcome.failure("slipped", "the cable went slack while clipping")
        q_target = (
            self._axis.target(me.orientation, state.direction) if state.taut else me.orientation
        )
        desired = with_pose(self._hold, self.arm, Pose(target, q_target))
        return Command(tension_twist(ctx, obs, self.arm, desired, force, state))

    def _read_tug(self, p_gripper: np.ndarray) -> None:
        """Judge the tug: a pull that turned about the far contact was not held by the clip."""
        reading = self._tug.reading(p_gripper, self._exit, self._far())
        self._tug_reading = reading
        if reading.distinct and not reading.holds:
            if self.realigns < REALIGNS:
                self._realign()
                return
            self.outcome = Outcome.failure(
                "not_clipped",
                f"the cable is not held by {self.clip}: {reading.describe()}; at rest the"
                f" force's line read it {self._line_at_rest}",
            )
            return
        # held: press it home again (the tug can draw a cable in the jaws'
        # throat up by 1-2 mm: Table I F seed 0 trial 0, and after it I's
        # estimate of the clip 3.9 mm off, 1.7 mm without the tug)
        self.phase = "press"

    def _beside(self) -> bool:
        """Whether the force's line, at rest, passes the slot's exit beside the channel."""
        return self.sensing.miss is not None and self.sensing.miss > SIDEWAYS

    def _realign(self) -> None:
        """Bring the cable over the clip again (the alignment), then push anew.

        The alignment lifts the cable to ``ABOVE`` over the seat, clear of
        the jaws, and puts its line over the seat again; the push then
        starts from its beginning, with its attempts.
        """
        self.realigns += 1
        self.attempts = 1
        self.timeout += REALIGN_TIME
        self.phase = "align"
        self._no_snap = ""
        self._at_floor = None
        self._tug_reading = None
        self._reached = None

    def _verify(self, ctx: PrimitiveContext) -> None:
        """The verdict: the force's line at rest after the tug and the press home, and the tug.

        The line is judged again after the tug: a cable caught in the jaws'
        throat, at their narrowest gap, turns the pull about the clip as a
        seated one does, and the tug draws it up (Table I F, seed 0, trial
        0: 3.5 mm above the seat before the tug, 3.9 mm after it, the jaws'
        axes at 4.3 mm, then above them), so it is pressed home again first.
        """
        verdict = self.sensing.verdict(self.clip)
        if verdict.status != "success":
            if self._no_snap:
                verdict = Outcome.failure(
                    "not_clipped",
                    f"{self._no_snap}, and {verdict.detail}: hold the cable closer to the clip",
                )
            self.outcome = verdict
            return
        if self._tug_reading is not None:
            held = "held" if self._tug_reading.distinct else "not told apart"
            verdict = Outcome.success(f"{verdict.detail}; {self._tug_reading.describe()}: {held}")
        # the clip lies on the straight cable from the contact, |q - c| along it
        est = ctx.estimator
        drop_new_points(ctx.graph, self._known)
        g, c = est.gripper_index, est.contact_index
        s_c = float(ctx.graph.arc_lengths()[c]) if c is not None else 0.0
        sense = 1.0 if c is None or c < g else -1.0
        arc = s_c + sense * (self._lead + norm3(self.info.position - self._far()))
        add_on_sensing_edge(est, arc, self.info.position, "fixed", self.clip)
        self.outcome = verdict
