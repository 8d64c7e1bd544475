"""A scenario's routes as the planner's plain data, and the planned task.

The planner (:mod:`tautwire.tasks.planner`) is core code: it takes plain
dataclasses, never the scenario's pydantic models. This module builds them
from a validated scenario and writes the plan back as a ``task:`` list.
"""

from __future__ import annotations

import yaml

from tautwire.robot import Arm
from tautwire.robot.workspace import WORKSPACE
from tautwire.scenario.models import CLIP_LENGTH, Scenario
from tautwire.tasks.planner import (
    BoardFixture,
    CableToRoute,
    ParamValue,
    Plan,
    RobotLayout,
    RouteEntry,
    RouteProblem,
    plan_routes,
)


def route_problem(scenario: Scenario) -> RouteProblem:
    """The planner's view of ``scenario``: board, cables with routes, robot.

    The reach box is :data:`~tautwire.robot.workspace.WORKSPACE`, where the
    grippers start and the fixtures stand; the force limit and the sensing
    arms are the scenario's.
    """
    fixtures: list[BoardFixture] = []
    for f in scenario.board.fixtures:
        if f.type == "anchor":
            fixtures.append(BoardFixture(f.name, "anchor", f.position))
        elif f.type == "peg":
            fixtures.append(
                BoardFixture(f.name, "peg", f.position, radius=f.radius, height=f.height)
            )
        else:
            fixtures.append(
                BoardFixture(
                    f.name,
                    "clip",
                    f.position,
                    yaw=f.yaw,
                    push_force=f.push_force,
                    length=CLIP_LENGTH,
                )
            )
    cables = tuple(
        CableToRoute(
            name=c.name,
            length=c.length,
            stiffness=c.stiffness,
            radius=c.radius,
            start=c.start,
            via=tuple(c.via),
            holds=tuple((h.arm, h.at) for h in c.held_by),
            route=tuple(RouteEntry(e.fixture, e.side, e.wind) for e in c.route),
        )
        for c in scenario.cables
    )
    sensor = scenario.robot.sensor.arm
    sensors: frozenset[Arm] = frozenset(("left", "right") if sensor == "both" else (sensor,))
    grippers = scenario.robot.grippers
    robot = RobotLayout(
        grippers={"left": grippers.left.position, "right": grippers.right.position},
        sensors=sensors,
        reach=WORKSPACE,
        force_limit=scenario.robot.force_limit,
    )
    return RouteProblem(tuple(fixtures), cables, robot)


def plan_scenario(scenario: Scenario) -> Plan:
    """Plan the routes of ``scenario``'s cables.

    Raises:
        RouteError: for the first route entry the robot cannot do.
    """
    return plan_routes(route_problem(scenario))


def task_yaml(plan: Plan) -> str:
    """The plan as a scenario's ``task:`` list, one flow mapping a step, each after a comment."""
    lines = ["task:"]
    for step in plan.steps:
        lines.append(f"  # {step.why}")
        lines.append("  - " + _flow(step.as_task_step()))
    return "\n".join(lines) + "\n"


def _flow(step: dict[str, ParamValue]) -> str:
    """One step as a YAML flow mapping, e.g. ``{primitive: move, arm: left, to: [0.1, 0, 0.1]}``."""
    text = yaml.safe_dump(step, default_flow_style=True, sort_keys=False, width=1_000_000)
    return text.strip()
