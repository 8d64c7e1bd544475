"""What the primitives share: the model, the estimators and the controller."""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
from numpy.typing import NDArray

from tautwire.control import (
    AdaptiveForceController,
    HybridController,
    MotionController,
    SafetyLimits,
)
from tautwire.estimation import (
    DEFAULT_PROCESS_NOISE,
    ContactChangeDetector,
    ContactPointFilter,
    ElasticityEstimator,
)
from tautwire.model import PathGraph
from tautwire.primitives.model_estimator import ModelEstimator
from tautwire.robot import Arm

FloatArray = NDArray[np.float64]


@dataclass(frozen=True)
class ClipInfo:
    """A snap-in clip as the board's design gives it.

    Attributes:
        position: Where a clipped cable sits (the seat) [m].  # (3,)
        yaw: Direction of the slot about world z [rad].
        push_force: Force [N] the clip needs to let the cable in.
        length: Length [m] of the clip along its slot (a scenario's clips
            all have ``tautwire.scenario.models.CLIP_LENGTH``).
    """

    position: FloatArray
    yaw: float
    push_force: float
    length: float

    @property
    def slot(self) -> FloatArray:
        """Unit direction of the slot (horizontal)."""
        return np.array([np.cos(self.yaw), np.sin(self.yaw), 0.0])

    def exit_towards(self, point: FloatArray) -> FloatArray:
        """The end of the slot [m] a clipped cable leaves by on its way to ``point``.

        The cable lies along the slot in the jaws and bends only beyond
        them: a line aimed from the seat misses the cable's by up to half
        the clip's length times the bend's sine, at the clip.
        """
        slot = self.slot
        along = np.asarray(point, dtype=float) - self.position
        sign = 1.0 if float(along @ slot) >= 0.0 else -1.0
        out: FloatArray = self.position + sign * 0.5 * self.length * slot
        return out


@dataclass
class PrimitiveContext:
    """The robot's picture of the task, handed from one primitive to the next.

    Attributes:
        estimator: The online model estimation loop (path graph, contact
            filter, elasticity) of the sensing gripper.
        controller: The hybrid motion-force controller.
        limits: Speed and force limits.
        control_period: The robot's control period [s].
        tension: The tension set point [N] that the last tensioning primitive
            established (None before any).
        fixtures: Nominal fixture positions [m] known from the board's design
            (goals such as clips), by name. Not the cable's state.
        clips: The board design's clips by name.
        pegs: The board design's pegs by name: the heights [m] of the foot
            and the top of each, between which a cable can bear on it.
    """

    estimator: ModelEstimator
    controller: HybridController
    limits: SafetyLimits
    control_period: float = 0.004
    tension: float | None = None
    fixtures: dict[str, FloatArray] = field(default_factory=dict)
    clips: dict[str, ClipInfo] = field(default_factory=dict)
    pegs: dict[str, tuple[float, float]] = field(default_factory=dict)

    @property
    def graph(self) -> PathGraph:
        """The path graph of the held cable."""
        return self.estimator.graph

    @property
    def arm(self) -> Arm:
        """The sensing gripper's arm."""
        return self.estimator.arm


def make_context(
    graph: PathGraph,
    arm: Arm,
    *,
    force_limit: float = 15.0,
    force_noise: float = 0.05,
    torque_noise: float = 0.002,
    control_period: float = 0.004,
    k_initial: float = 100.0,
    estimation_period: float = 0.0,
    process_noise: float | None = None,
    bandwidth: float = 5.0,
    max_linear_speed: float = 0.1,
    max_angular_speed: float = 1.0,
    fixtures: dict[str, FloatArray] | None = None,
    model_noise: float = 1e-3,
    min_jump: float = 5e-3,
    round_fixtures: dict[str, tuple[FloatArray, float]] | None = None,
    clips: dict[str, ClipInfo] | None = None,
    pegs: dict[str, tuple[float, float]] | None = None,
) -> PrimitiveContext:
    """A context with the default estimators and controllers.

    Args:
        graph: The path graph of the held cable, with the gripper's point.
        arm: The gripper that holds the cable and carries the FT sensor.
        force_limit: The robot's force limit [N].
        force_noise: FT sensor noise [N], std per axis.
        torque_noise: FT sensor torque noise [N m], std per axis.
        control_period: The robot's control period [s].
        k_initial: Initial stiffness guess [N/m] (it need not be right).
        estimation_period: Period [s] of the contact filter's iterations.
        process_noise: Contact filter process noise [m^2 per iteration].
        bandwidth: lambda [1/s] of the adaptive force controller.
        max_linear_speed: Gripper speed limit [m/s].
        max_angular_speed: Gripper angular speed limit [rad/s].
        fixtures: Nominal fixture positions [m] by name.
        model_noise: Std [m] of what the line model misses (the cable's path
            through the fingers, sensor mounting), added to the filter's
            measurement noise; it keeps a real cable's small systematic
            deviations from reading as contact changes.
        min_jump: Smallest innovation [m] that can declare a contact change.
        round_fixtures: Pegs of the board design: name -> (axis point [m],
            peg radius + cable radius [m]) (see :class:`ModelEstimator`).
        clips: The board design's clips by name.
        pegs: The board design's pegs by name: heights [m] of foot and top.
    """
    samples = max(1.0, estimation_period / control_period)
    # the filter sees the mean force of each estimation period: less noise
    filter_noise = force_noise / np.sqrt(samples)
    contact_filter = ContactPointFilter(
        force_noise=filter_noise,
        torque_noise=torque_noise / np.sqrt(samples),
        process_noise=DEFAULT_PROCESS_NOISE if process_noise is None else process_noise,
        mass_per_length=graph.mass_per_length,
        min_tension=max(0.3, 5.0 * filter_noise),
        position_noise=model_noise,
        detector=ContactChangeDetector(min_innovation=min_jump),
    )
    elasticity = ElasticityEstimator(force_noise=force_noise, k_initial=k_initial)
    estimator = ModelEstimator(
        graph, arm, contact_filter, elasticity, estimation_period, round_fixtures=round_fixtures
    )
    limits = SafetyLimits(force_limit, max_linear_speed, max_angular_speed)
    controller = HybridController(
        MotionController(k_p=2.0, k_o=4.0),
        AdaptiveForceController(bandwidth=bandwidth, k_hat_min=5.0, k_hat_max=5000.0),
        limits,
    )
    return PrimitiveContext(
        estimator,
        controller,
        limits,
        control_period,
        None,
        dict(fixtures or {}),
        dict(clips or {}),
        dict(pegs or {}),
    )
