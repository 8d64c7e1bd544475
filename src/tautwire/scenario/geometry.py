"""Checks that a scenario's geometry is physically possible.

Run after :mod:`tautwire.scenario.references` found every name: a cable's
route is a polyline through named fixtures and gripper positions.
"""

from __future__ import annotations

import itertools
import math
from typing import TYPE_CHECKING, NamedTuple

from tautwire.scenario.issue import Issue, Location
from tautwire.scenario.workspace import GRIPPER_MIN_DISTANCE, ROUTE_TOLERANCE, WORKSPACE

if TYPE_CHECKING:
    from tautwire.scenario.models import Anchor, CableSpec, Clip, Peg, Scenario


class RoutePoint(NamedTuple):
    """A point a cable's initial route passes through.

    Attributes:
        label: what it is, for messages (``"A1"``, ``"left gripper"``).
        position: where it is [m], (3,).
    """

    label: str
    position: tuple[float, float, float]


def check_geometry(scenario: Scenario) -> list[Issue]:
    """Find fixtures and grippers out of reach and cables shorter than their route.

    Args:
        scenario: a schema-valid scenario whose names all resolve
            (:func:`~tautwire.scenario.references.check_references` is clean).

    Returns:
        The issues found (empty if none).
    """
    issues: list[Issue] = []
    grippers = scenario.robot.grippers
    for arm, start in (("left", grippers.left), ("right", grippers.right)):
        if not WORKSPACE.contains(start.position):
            issues.append(
                Issue(
                    ("robot", "grippers", arm, "position"),
                    f"{_fmt(start.position)} is out of the robot's reach "
                    f"(expected {WORKSPACE.describe()})",
                )
            )
    gap = math.dist(grippers.left.position, grippers.right.position)
    if gap < GRIPPER_MIN_DISTANCE:
        issues.append(
            Issue(
                ("robot", "grippers", "right", "position"),
                f"the grippers start {gap:.3g} m apart "
                f"(expected at least {GRIPPER_MIN_DISTANCE:g} m between them)",
            )
        )
    for i, fixture in enumerate(scenario.board.fixtures):
        top = list(fixture.position)
        if fixture.type == "peg":
            top[2] += fixture.height
        if not (WORKSPACE.contains(fixture.position) and WORKSPACE.contains(top)):
            issues.append(
                Issue(
                    ("board", "fixtures", i, "position"),
                    f"fixture {fixture.name} at {_fmt(fixture.position)} is out of the robot's "
                    f"reach (expected {WORKSPACE.describe()})",
                )
            )
    for i, cable in enumerate(scenario.cables):
        issues += _check_route(scenario, cable, ("cables", i))
    return issues


def _check_route(scenario: Scenario, cable: CableSpec, here: Location) -> list[Issue]:
    """Check that enough cable spans each part of the cable's initial route.

    The route runs from the start anchor (arc length 0), or from the free
    end, through the ``via`` fixtures in order to the first hold (smallest
    ``at``), then on to the second hold. The straight-line polyline of each
    part must not be longer than the cable between its ends; from a free
    end, the part is measured from the first ``via`` fixture (the free end
    may lie anywhere before it), which keeps it a lower bound.
    """
    fixtures = {f.name: f for f in scenario.board.fixtures}
    grippers = scenario.robot.grippers
    holds = sorted(enumerate(cable.held_by), key=lambda kv: kv[1].at)
    first: RoutePoint | None = None
    if cable.start is not None:
        first = RoutePoint(cable.start, fixtures[cable.start].position)
    via = [fixtures[name] for name in cable.via]
    issues: list[Issue] = []
    arc = 0.0
    for n, (k, hold) in enumerate(holds):
        start = grippers.left if hold.arm == "left" else grippers.right
        gripper = RoutePoint(f"{hold.arm} gripper", start.position)
        points = _route_points(via if n == 0 else [], first, gripper)
        span = hold.at - arc
        first, arc = gripper, hold.at
        if len(points) < 2:
            continue
        route = sum(math.dist(a.position, b.position) for a, b in itertools.pairwise(points))
        if route <= span + ROUTE_TOLERANCE:
            continue
        path = " -> ".join(p.label for p in points)
        if n == 0 and hold.at == cable.length:
            issues.append(
                Issue(
                    (*here, "length"),
                    f"cable {cable.name} is {cable.length:g} m long but its route {path} is "
                    f"{route:.3f} m (expected a length >= {route:.3f} m or a shorter route)",
                )
            )
        else:
            issues.append(
                Issue(
                    (*here, "held_by", k, "at"),
                    f"{span:g} m of cable {cable.name} cannot span the route {path} of "
                    f"{route:.3f} m (expected at least {route:.3f} m of cable there)",
                )
            )
    return issues


def _route_points(
    via: list[Anchor | Peg | Clip], first: RoutePoint | None, last: RoutePoint
) -> list[RoutePoint]:
    """The route's points; a peg is the point of its axis nearest the route's height.

    A peg contributes the point on its axis at the mean height of its
    neighbours, clamped to the peg, which keeps the route a close lower
    bound of the cable it needs.
    """
    points: list[RoutePoint] = [] if first is None else [first]
    points += [RoutePoint(f.name, _mid(f)) for f in via]
    points.append(last)
    refined = list(points)
    for n, fixture in enumerate(via):
        if fixture.type != "peg":
            continue
        m = n + (0 if first is None else 1)
        neighbours = [points[j].position[2] for j in (m - 1, m + 1) if 0 <= j < len(points)]
        z = sum(neighbours) / len(neighbours)
        base = fixture.position[2]
        x, y, _ = fixture.position
        refined[m] = RoutePoint(fixture.name, (x, y, min(max(z, base), base + fixture.height)))
    return refined


def _mid(fixture: Anchor | Peg | Clip) -> tuple[float, float, float]:
    """A fixture's representative point: a peg's mid-height, else its position [m]."""
    x, y, z = fixture.position
    if fixture.type == "peg":
        return (x, y, z + fixture.height / 2.0)
    return (x, y, z)


def _fmt(point: tuple[float, ...]) -> str:
    """A point for a message: ``[0.1, 0.2, 0.3]``."""
    return "[" + ", ".join(f"{c:g}" for c in point) + "]"
