"""The robot's prior picture of a cable, from the scenario's board design.

This module converts a scenario (the ``sim`` extra's yaml and pydantic
layer) into the core's plain objects; it imports without that layer, which
only a caller that has a scenario needs.

What the robot knows before it moves: where the fixtures were designed to be,
which fixtures the cable was routed along, its length and mass per length,
and where its grippers hold it. Not the cable's actual state: contacts are
estimated online from the force.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import NDArray

from tautwire.errors import InvalidArgumentError
from tautwire.estimation.round_contact import RADIUS_MARGIN
from tautwire.model import FeatureKind, PathGraph
from tautwire.primitives import PrimitiveContext, make_context
from tautwire.primitives.context import ClipInfo
from tautwire.robot import Arm
from tautwire.tasks.cable_models import CableModels

if TYPE_CHECKING:  # the scenario layer (yaml, pydantic) is the sim extra's
    from tautwire.scenario import Scenario
    from tautwire.scenario.models import CableSpec

FloatArray = NDArray[np.float64]


def fixture_point(scenario: Scenario, name: str, height: float | None = None) -> FloatArray:
    """Nominal point [m] where a cable bears on fixture ``name``.

    A peg's point is on its axis at ``height`` (clamped to the peg), else at
    mid-height; anchors and clips at their position.
    """
    f = scenario.fixture(name)
    p = np.asarray(f.position, dtype=float)
    if f.type == "peg":
        z = (
            p[2] + 0.5 * f.height
            if height is None
            else float(np.clip(height, p[2], p[2] + f.height))
        )
        return np.array([p[0], p[1], z])
    return p


#: Height [m] of the board's surface: the world's plane z = 0, which the
#: primitives keep their clearances from (F's, C's ``TABLE_CLEARANCE``).
BOARD_SURFACE = 0.0


def initial_graph(scenario: Scenario, cable: CableSpec) -> PathGraph:
    """The path graph of ``cable`` as the board design has it.

    Points: the start anchor (``fixed``), the ``via`` fixtures (``contact``,
    nominal positions), the holding gripper(s) (``gripper``, at their start
    poses and held arc lengths), and free ends (``free``, hanging).
    """
    grippers = scenario.robot.grippers
    holds = sorted(cable.held_by, key=lambda h: h.at)
    if not holds:
        raise InvalidArgumentError(f"cable {cable.name!r} is not held by any gripper")
    first_hold = np.asarray(getattr(grippers, holds[0].arm).position, dtype=float)
    points: list[FloatArray] = []
    kinds: list[FeatureKind] = []
    labels: list[str] = []
    arcs: list[float] = []
    if cable.start is not None:
        start = scenario.fixture(cable.start)
        if start.type != "anchor":
            raise InvalidArgumentError(f"cable {cable.name!r} must start at an anchor")
        points.append(np.asarray(start.position, dtype=float))
        kinds.append("fixed")
        labels.append(cable.start)
        arcs.append(0.0)
    route_z = float(points[0][2]) if points else float(first_hold[2])
    for name in cable.via:
        p = fixture_point(scenario, name, route_z)
        arc = arcs[-1] + float(np.linalg.norm(p - points[-1])) if points else 0.0
        points.append(p)
        kinds.append("contact")
        labels.append(name)
        arcs.append(arc)
    for hold in holds:
        p = np.asarray(getattr(grippers, hold.arm).position, dtype=float)
        if arcs and hold.at <= arcs[-1]:
            raise InvalidArgumentError(
                f"cable {cable.name!r}: the hold at {hold.at} m lies before its route's fixtures"
            )
        points.append(p)
        kinds.append("gripper")
        labels.append(hold.arm)
        arcs.append(hold.at)
    if not cable.start and arcs[0] > 0.0:  # a free first end hangs below the first hold
        points.insert(0, points[0] - np.array([0.0, 0.0, arcs[0]]))
        kinds.insert(0, "free")
        labels.insert(0, "end")
        arcs.insert(0, 0.0)
    if arcs[-1] < cable.length:  # the free last end hangs below the last hold
        points.append(points[-1] - np.array([0.0, 0.0, cable.length - arcs[-1]]))
        kinds.append("free")
        labels.append("end")
        arcs.append(cable.length)
    lengths = np.diff(arcs)
    graph = PathGraph.from_positions(
        np.array(points), cable.mass_per_length, lengths=lengths, kinds=kinds, labels=labels
    )
    # a hanging end lies on the board, not below it
    graph.rest_height = BOARD_SURFACE + cable.radius
    rest = graph.positions
    rest[:, 2] = np.maximum(rest[:, 2], graph.rest_height)
    graph.set_positions(rest)
    for e in graph.edges:
        e.stiffness = cable.stiffness * cable.length / e.length if e.length > 0 else cable.stiffness
    return graph


def sensing_arm(scenario: Scenario, cable: CableSpec) -> Arm:
    """The arm that holds ``cable`` and carries a force-torque sensor."""
    sensor = scenario.robot.sensor.arm
    for hold in cable.held_by:
        if sensor in (hold.arm, "both"):
            return hold.arm
    raise InvalidArgumentError(
        f"cable {cable.name!r} is held by {[h.arm for h in cable.held_by]}, "
        f"but the force-torque sensor is on the {sensor} wrist"
    )


def initial_context(
    scenario: Scenario,
    cable: str | None = None,
    *,
    k_initial: float | None = None,
    estimation_period: float = 0.0,
) -> PrimitiveContext:
    """The primitives' shared context for ``cable`` (default: the first cable).

    Args:
        scenario: The scenario.
        cable: Name of the cable the primitives work on.
        k_initial: Initial stiffness guess [N/m]; default a generic 100 N/m
            (the controller adapts; the true stiffness is not known).
        estimation_period: Period [s] of the contact filter's iterations.
    """
    spec = scenario.cable(cable) if cable is not None else scenario.cables[0]
    graph = initial_graph(scenario, spec)
    return cable_context(
        scenario,
        spec.name,
        sensing_arm(scenario, spec),
        graph,
        k_initial,
        estimation_period=estimation_period,
    )


def cable_context(
    scenario: Scenario,
    cable: str,
    arm: Arm,
    graph: PathGraph,
    k_initial: float | None = None,
    *,
    estimation_period: float = 0.0,
) -> PrimitiveContext:
    """The context of gripper ``arm`` sensing ``cable``, whose model is ``graph``.

    Args:
        scenario: The scenario (the board's design, the robot's settings).
        cable: The cable's name.
        arm: The gripper that holds it and carries a force-torque sensor.
        graph: The cable's path graph (shared by every context of the cable).
        k_initial: Initial stiffness guess [N/m]; default a generic 100 N/m.
        estimation_period: Period [s] of the contact filter's iterations.
    """
    # the scenario layer is there whenever a scenario is (the sim extra)
    from tautwire.scenario.models import CLIP_LENGTH

    spec = scenario.cable(cable)
    fixtures = {f.name: fixture_point(scenario, f.name) for f in scenario.board.fixtures}
    round_fixtures = {
        f.name: (fixture_point(scenario, f.name), f.radius + spec.radius + RADIUS_MARGIN)
        for f in scenario.board.fixtures
        if f.type == "peg"
    }
    clips = {
        f.name: ClipInfo(
            np.asarray(f.position, dtype=float), float(f.yaw), float(f.push_force), CLIP_LENGTH
        )
        for f in scenario.board.fixtures
        if f.type == "clip"
    }
    pegs = {
        f.name: (float(f.position[2]), float(f.position[2] + f.height))
        for f in scenario.board.fixtures
        if f.type == "peg"
    }
    robot = scenario.robot
    ctx = make_context(
        graph,
        arm,
        force_limit=robot.force_limit,
        force_noise=robot.sensor.noise_force,
        torque_noise=robot.sensor.noise_torque,
        control_period=robot.control_period,
        k_initial=100.0 if k_initial is None else k_initial,
        estimation_period=estimation_period,
        fixtures=fixtures,
        round_fixtures=round_fixtures,
        clips=clips,
        pegs=pegs,
    )
    ctx.estimator.peg_tops = {name: top for name, (_, top) in pegs.items()}
    ctx.estimator.peg_radii = {f.name: f.radius for f in scenario.board.fixtures if f.type == "peg"}
    ctx.estimator.slots = {
        name: (clip.position.copy(), clip.slot, 0.5 * clip.length) for name, clip in clips.items()
    }
    return ctx


def initial_models(
    scenario: Scenario, *, k_initial: float | None = None, estimation_period: float = 0.0
) -> CableModels:
    """One model per cable, with a context for each gripper that holds it with a sensor.

    Args:
        scenario: The scenario.
        k_initial: Initial stiffness guess [N/m] of every context; default 100 N/m.
        estimation_period: Period [s] of the contact filters' iterations.
    """
    sensor = scenario.robot.sensor.arm
    sensors: frozenset[Arm] = frozenset(("left", "right") if sensor == "both" else (sensor,))

    def factory(cable: str, arm: Arm, graph: PathGraph, k: float | None) -> PrimitiveContext:
        return cable_context(
            scenario,
            cable,
            arm,
            graph,
            k_initial if k is None else k,
            estimation_period=estimation_period,
        )

    graphs = {spec.name: initial_graph(scenario, spec) for spec in scenario.cables}
    return CableModels(graphs, sensors, factory)
