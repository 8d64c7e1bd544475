"""A - Parallel DLO Tension: tension the cable between the two grippers."""

from __future__ import annotations

import math

import numpy as np

from tautwire.errors import InvalidArgumentError
from tautwire.primitives.context import PrimitiveContext
from tautwire.primitives.outcome import Outcome
from tautwire.primitives.pair_alignment import PairAlignment
from tautwire.primitives.primitive import Primitive
from tautwire.primitives.tension_judge import TensionJudge
from tautwire.robot import Command, Observation


def held_between_grippers(ctx: PrimitiveContext) -> bool:
    """Whether both grippers hold the cable and the sensing gripper's edge runs towards the other.

    The edge ends at the other gripper, or at a clip between the two (after
    C, or F, the clip's point sits between the grippers: the sensing
    gripper then feels the tension of its side of the clip, which A, B and
    C control).
    """
    est = ctx.estimator
    graph = ctx.graph
    c = est.contact_index
    other = graph.index_of("gripper", "right" if est.arm == "left" else "left")
    if c is None or other is None:
        return False
    if graph.points[c].kind == "gripper":
        return True
    lo, hi = sorted((est.gripper_index, other))
    return graph.points[c].kind == "fixed" and lo < c < hi


class ParallelTension(Primitive):
    """Primitive A: both grippers hold the cable; coordinated control tensions it.

    Coordinated hybrid control (:meth:`HybridController.coordinated`): the
    absolute position and the direction between the grippers hold their
    start values, the grippers' distance is under the adaptive
    inverse-damping force control (k_f = lambda / k_hat) with the tension
    measured by the sensing wrist.

    Either tool axis may run along the cable, and a gripper may start at
    any yaw (:class:`~tautwire.primitives.pair_alignment.PairAlignment`):
    first each gripper turns its tool axis, +x or -x, whichever is nearer,
    onto the line between the grippers by the shortest arc, their distance
    held (a cable bent round a fingertip reads a wrong tension and rubs
    the pad). The turn only shortens the cable's route, never stretches it.
    Only once both axes lie within ``ALIGNED`` of the line (for
    ``ALIGNED_TIME`` if they had to turn) does the force control run, the
    elasticity estimate learn and the success test count.

    Success: the tension stays within ``tolerance`` of ``force`` for
    ``hold_time``, aligned. Failure: ``no_contact`` when the grippers part by
    ``max_travel`` without the cable becoming taut (it is not held by both);
    ``timeout``.

    Args:
        force: Desired tension f_d [N].
        tolerance: Allowed tension error, a fraction of ``force``.
        hold_time: How long [s] the tension must stay within tolerance.
        max_travel: Longest distance [m] the grippers may part to find tension.
        timeout: Longest run time [s].
    """

    name = "parallel_tension"
    letter = "A"

    def __init__(
        self,
        force: float,
        tolerance: float = 0.1,
        hold_time: float = 0.5,
        max_travel: float = 0.3,
        timeout: float = 10.0,
    ) -> None:
        super().__init__(timeout)
        if not (force > 0.0 and math.isfinite(force)):
            raise InvalidArgumentError(f"force must be > 0 N, got {force}")
        self.force = float(force)
        self.tolerance = float(tolerance)
        self.hold_time = float(hold_time)
        self.max_travel = float(max_travel)
        self._judge = TensionJudge(self.force, self.tolerance, self.hold_time)
        self._start_distance = 0.0
        self._ever_taut = False

    def on_start(self, obs: Observation, ctx: PrimitiveContext) -> None:
        """Plan the pair's alignment; check that both grippers hold the cable."""
        if not held_between_grippers(ctx):
            self.outcome = Outcome.failure(
                "precondition", "parallel tension needs the cable held by both grippers"
            )
        ctx.estimator.learn_elasticity = False  # until aligned
        ctx.estimator.rotation = None
        self._pair = PairAlignment(obs)
        self._start_distance = float(np.linalg.norm(obs.left.position - obs.right.position))
        self._judge = TensionJudge(self.force, self.tolerance, self.hold_time)
        self._ever_taut = False

    def on_step(self, obs: Observation, ctx: PrimitiveContext) -> Command:
        """Update the model; align, then run the coordinated hybrid controller and judge."""
        state = ctx.estimator.update(obs)
        if self.outcome.done:
            return Command()
        self._ever_taut |= state.taut
        aligned = self._pair.settled(obs)
        ctx.estimator.learn_elasticity = aligned
        twist = ctx.controller.coordinated(
            self._pair.tool_frames(obs),
            self._pair.desired,
            self.force if aligned else None,
            state.tension,
            ctx.estimator.elasticity.k_trusted,
        )
        if not aligned:
            self._judge.reset()
        elif self._judge.update(obs.time, state.tension):
            self.outcome = Outcome.success(
                f"tension {self._judge.smoothed:.2f} N held {self.hold_time:g} s"
            )
            ctx.tension = self.force
        distance = float(np.linalg.norm(obs.left.position - obs.right.position))
        if not self._ever_taut and distance - self._start_distance > self.max_travel:
            self.outcome = Outcome.failure(
                "no_contact",
                f"the grippers parted {distance - self._start_distance:.2f} m"
                " and the cable never became taut",
            )
        return Command(twist)
