"""Building the simulated world from a scenario."""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import numpy as np
from numpy.typing import NDArray

from tautwire.robot.arm import Arm
from tautwire.scenario import Anchor, Clip, Fault, Peg, Scenario
from tautwire.sim.fault_injector import FaultInjector
from tautwire.sim.ground_truth import GroundTruth
from tautwire.sim.options import SimOptions
from tautwire.sim.sim_robot import SimRobot
from tautwire.sim.spec import (
    AnchorSpec,
    CableSpec,
    ClipSpec,
    FixtureSpec,
    GripperSpec,
    HoldSpec,
    PegSpec,
    WorldSpec,
)
from tautwire.sim.world import SimWorld

FloatArray = NDArray[np.float64]


def _array(values: tuple[float, ...]) -> FloatArray:
    return np.asarray(values, dtype=float)


def world_spec(scenario: Scenario, seed: int | None = None) -> WorldSpec:
    """Convert a scenario into the simulator's :class:`WorldSpec`.

    Args:
        scenario: A validated scenario.
        seed: Overrides the scenario's seed (sensor noise).
    """
    fixtures: list[FixtureSpec] = []
    for f in scenario.board.fixtures:
        if isinstance(f, Anchor):
            fixtures.append(AnchorSpec(f.name, _array(f.position)))
        elif isinstance(f, Peg):
            fixtures.append(PegSpec(f.name, _array(f.position), f.radius, f.height))
        elif isinstance(f, Clip):
            fixtures.append(ClipSpec(f.name, _array(f.position), f.yaw, f.push_force))
    cables = tuple(
        CableSpec(
            c.name,
            c.length,
            c.mass_per_length,
            c.stiffness,
            c.radius,
            start=c.start,
            via=tuple(c.via),
            holds=tuple(HoldSpec(h.arm, h.at) for h in c.held_by),
        )
        for c in scenario.cables
    )
    robot = scenario.robot
    arms: tuple[Arm, ...] = ("left", "right") if robot.sensor.arm == "both" else (robot.sensor.arm,)
    grippers = robot.grippers
    return WorldSpec(
        fixtures=tuple(fixtures),
        cables=cables,
        left=GripperSpec(_array(grippers.left.position), _array(grippers.left.orientation)),
        right=GripperSpec(_array(grippers.right.position), _array(grippers.right.orientation)),
        control_period=robot.control_period,
        force_limit=robot.force_limit,
        sensor_arms=arms,
        noise_force=robot.sensor.noise_force,
        noise_torque=robot.sensor.noise_torque,
        seed=scenario.seed if seed is None else seed,
        start_at_rest=True,
    )


def build_world(scenario: Scenario, seed: int | None = None, **options: Any) -> SimWorld:
    """Build and settle the simulated world of ``scenario``.

    A scenario file carries no simulation resolution: the timestep, the
    number of segments, friction and the rest are ``options``.

    Args:
        scenario: A validated scenario.
        seed: Overrides the scenario's seed (sensor noise).
        **options: Any field of :class:`SimOptions` (e.g. ``timestep``,
            ``segment_length``, ``pad_friction``).

    Returns:
        The world; drive it through :func:`robot_of` and score it with
        :class:`GroundTruth`.

    Raises:
        InvalidArgumentError: for an unknown option.
        SimulationError: where the scene cannot be simulated faithfully
            (wave-speed guard, over-stretched route) or does not settle.
    """
    return SimWorld(world_spec(scenario, seed), SimOptions.from_kwargs(**options))


def robot_of(
    world: SimWorld, seed: int | None = None, faults: Sequence[Fault] = ()
) -> SimRobot | FaultInjector:
    """The :class:`tautwire.robot.Robot` view of ``world`` (what primitives get).

    Args:
        world: The simulated world.
        seed: Seed of the sensor noise (default: the world spec's seed).
        faults: The scenario's ``faults:``; with any, the robot is wrapped in
            a :class:`FaultInjector` (a ``slip`` without ``arm`` hits the
            arm that holds the first cable and carries a sensor).
    """
    robot = SimRobot(world, seed)
    if not faults:
        return robot
    return FaultInjector(robot, faults, _sensing_arm(world))


def _sensing_arm(world: SimWorld) -> Arm:
    sensors = world.spec.sensor_arms
    for cable in world.spec.cables:
        for hold in cable.holds:
            if hold.arm in sensors:
                return hold.arm
    return sensors[0] if sensors else "left"


def truth_of(world: SimWorld) -> GroundTruth:
    """The ground truth of ``world`` (for scoring only)."""
    return GroundTruth(world)
