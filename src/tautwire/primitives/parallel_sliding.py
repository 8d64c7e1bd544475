"""B - Parallel DLO Sliding: the grippers part, the cable slides through one of them."""

from __future__ import annotations

import numpy as np

from tautwire.primitives.context import PrimitiveContext
from tautwire.primitives.model_estimator import TensionState
from tautwire.primitives.outcome import Outcome
from tautwire.primitives.pair_alignment import PairAlignment
from tautwire.primitives.parallel_tension import held_between_grippers
from tautwire.primitives.sliding import SlidingPrimitive
from tautwire.robot import Observation


class ParallelSliding(SlidingPrimitive):
    """Primitive B: coordinated control parts the grippers at a constant relative speed.

    As in the paper: P = 0 (the tension is set by the grip force of
    ``slide_arm``, see :class:`SlidingPrimitive`), x_dot_abs = 0 and
    w_abs = w_rel = 0 under motion control, and a constant relative velocity
    along the cable between the grippers slides ``slide_arm`` along it.

    Before the cable is tensioned for sliding, each gripper lays its tool
    axis, +x or -x, whichever is nearer, along the line between the
    grippers, their distance held
    (:class:`~tautwire.primitives.pair_alignment.PairAlignment`, as A): a
    cable bent round a fingertip reads a wrong tension, and its friction
    through bent fingers is not the fingers' 2 mu F_grip. After A the pair
    is aligned already and this takes no time.

    Args:
        slide_arm: The gripper the cable slides through.
        distance: How far [m] the grippers part.
        friction_force: Desired sliding friction f_slid [N].

    The other parameters (speed, tolerances, timeout) are those of
    :class:`SlidingPrimitive`.
    """

    name = "parallel_sliding"
    letter = "B"

    def on_start(self, obs: Observation, ctx: PrimitiveContext) -> None:
        """Plan the pair's alignment: the start's absolute position, its line between them."""
        self._pair = PairAlignment(obs)
        self._start_distance = self._distance(obs)
        super().on_start(obs, ctx)
        if not held_between_grippers(ctx):
            self.outcome = Outcome.failure(
                "precondition", "parallel sliding needs the cable held by both grippers"
            )

    def begin(self, obs: Observation, ctx: PrimitiveContext, state: TensionState) -> None:
        """The travel counts from here."""
        self._start_distance = self._distance(obs)

    def aligned(self, obs: Observation, ctx: PrimitiveContext, state: TensionState) -> bool:
        """Whether both tool axes lie along the line between the grippers (settled)."""
        return self._pair.settled(obs)

    def tension_motion(
        self, obs: Observation, ctx: PrimitiveContext, state: TensionState, aligned: bool
    ) -> np.ndarray:
        """A's coordinated force control with f_d = f_slid once aligned; else the turn alone."""
        return ctx.controller.coordinated(
            self._pair.tool_frames(obs),
            self._pair.desired,
            self.friction_force if aligned else None,
            state.tension,
            ctx.estimator.elasticity.k_trusted,
        )

    @staticmethod
    def _distance(obs: Observation) -> float:
        return float(np.linalg.norm(obs.left.position - obs.right.position))

    def travel(self, obs: Observation) -> float:
        """How far [m] the grippers have parted."""
        return self._distance(obs) - self._start_distance

    def motion(
        self, obs: Observation, ctx: PrimitiveContext, state: TensionState, moving: bool
    ) -> np.ndarray:
        """Constant relative speed along the cable while moving, else hold."""
        return ctx.controller.coordinated(
            self._pair.tool_frames(obs),
            self._pair.desired,
            None,
            0.0,
            relative_speed=self.speed if moving else 0.0,
        )

    def hold_shift(self, ctx: PrimitiveContext) -> tuple[int, float]:
        """The sliding gripper's point moves away from the other gripper along the arc."""
        graph = ctx.graph
        g = graph.index_of("gripper", self.slide_arm)
        other = graph.index_of("gripper", "right" if self.slide_arm == "left" else "left")
        assert g is not None
        return g, (1.0 if other is None or other < g else -1.0)
