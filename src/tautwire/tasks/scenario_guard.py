"""The :class:`RobotGuard` of a run, set up from the scenario.

What the guard needs to know of a run: the force limit, the sensor noise, the
box the grippers reach, and what load the held cables explain at rest (for
the tare).
The expected load of a sensing arm is the weight share of its gripper's
feature points in the board design's path graphs (eq:mass); the tolerance is
:data:`TARE_LOAD_FACTOR` times the weight of the cables it holds, which covers
a slack cable's sag tension and the hanging ends the design does not place.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from tautwire.model import GRAVITY
from tautwire.robot import WORKSPACE, Robot, Workspace
from tautwire.tasks.initial_model import initial_graph
from tautwire.tasks.robot_guard import TARE_SAMPLES, RobotGuard

if TYPE_CHECKING:  # the scenario layer (yaml, pydantic) is the sim extra's
    from tautwire.scenario import Scenario

#: The tare leaves alone any offset within this many held-cable weights of
#: the expected load.
TARE_LOAD_FACTOR = 3.0

#: How far [m] the grippers reach beyond the box where fixtures and start
#: poses lie (``WORKSPACE``), sideways and upwards; not below the board
#: surface. Primitives legitimately go past that box: on the Table I scenes
#: (seeds 0-7 of D and I) a tensioning pull went 0.06 m past it and circles
#: of I up to 0.17 m.
REACH_MARGIN = 0.3

#: The box the guard keeps the grippers' tool centre points in.
REACH = Workspace(
    lower=(
        WORKSPACE.lower[0] - REACH_MARGIN,
        WORKSPACE.lower[1] - REACH_MARGIN,
        WORKSPACE.lower[2],
    ),
    upper=(
        WORKSPACE.upper[0] + REACH_MARGIN,
        WORKSPACE.upper[1] + REACH_MARGIN,
        WORKSPACE.upper[2] + REACH_MARGIN,
    ),
)


def rest_loads(scenario: Scenario) -> tuple[dict[str, np.ndarray], float]:
    """Expected force [N] on each sensing gripper at rest, and the tare tolerance [N].

    Returns:
        By arm (each arm with a sensor), the force the held cables' weight
        shares exert on it (world frame, ``m g``); and
        ``TARE_LOAD_FACTOR`` times the largest weight [N] that one arm holds.
    """
    sensor = scenario.robot.sensor.arm
    arms = ("left", "right") if sensor == "both" else (sensor,)
    expected = {arm: np.zeros(3) for arm in arms}
    weight = dict.fromkeys(arms, 0.0)
    for cable in scenario.cables:
        graph = initial_graph(scenario, cable)
        masses = graph.masses()
        for hold in cable.held_by:
            if hold.arm not in expected:
                continue
            i = graph.index_of("gripper", hold.arm)
            if i is not None:
                expected[hold.arm] = expected[hold.arm] + masses[i] * GRAVITY
            weight[hold.arm] += cable.mass_per_length * cable.length * float(-GRAVITY[2])
    return expected, TARE_LOAD_FACTOR * max(weight.values(), default=0.0)


def scenario_guard(
    robot: Robot,
    scenario: Scenario,
    *,
    workspace: Workspace | None = REACH,
    tare_samples: int = TARE_SAMPLES,
    max_linear_speed: float = 0.1,
) -> RobotGuard:
    """The guard for one run of ``scenario`` on ``robot`` (create once per run).

    Args:
        robot: The robot (simulated, possibly with faults, or real).
        scenario: The scenario being run.
        workspace: The box the grippers must stay in (default :data:`REACH`).
        tare_samples: Samples of the tare at the start (0: none).
        max_linear_speed: The primitives' gripper speed limit [m/s].
    """
    expected, tolerance = rest_loads(scenario)
    return RobotGuard(
        robot,
        force_limit=scenario.robot.force_limit,
        force_noise=scenario.robot.sensor.noise_force,
        max_linear_speed=max_linear_speed,
        workspace=workspace,
        tare_samples=tare_samples,
        expected_load=expected,
        tare_tolerance=tolerance,
    )
