"""Checks of the routes a scenario's cables carry and of the cables its steps name.

SCENARIO.md, additions: a route lists pegs (with the side the peg stays on
and optional windings) and clips (nothing else) in order from the cable's
start; a step's optional ``cable`` names a cable; a scenario without a task
needs a route on some cable, for the planner to make the task. Whether the
robot can do a route (reach, clip heights and slots, the cable's length) is
the planner's question (:mod:`tautwire.tasks.planner`), not this module's.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from tautwire.scenario.issue import Issue

if TYPE_CHECKING:
    from tautwire.scenario.models import Scenario


def check_routes(scenario: Scenario) -> list[Issue]:
    """Find route entries that name no peg or clip or carry the wrong keys, and unknown cables.

    Args:
        scenario: a schema-valid scenario.

    Returns:
        The issues found, in document order (empty if none).
    """
    issues: list[Issue] = []
    fixtures = {f.name: f for f in scenario.board.fixtures}
    routable = [f.name for f in scenario.board.fixtures if f.type != "anchor"]
    for i, cable in enumerate(scenario.cables):
        for j, entry in enumerate(cable.route):
            here = ("cables", i, "route", j)
            fixture = fixtures.get(entry.fixture)
            if fixture is None or fixture.type == "anchor":
                what = "is an anchor" if fixture is not None else "is unknown"
                issues.append(
                    Issue(
                        (*here, "fixture"),
                        f"{entry.fixture!r} {what} (expected a peg or clip: {_list(routable)})",
                    )
                )
            elif fixture.type == "peg" and entry.side is None:
                issues.append(
                    Issue(
                        here,
                        f"peg {entry.fixture} needs a side (expected side: left or right, the "
                        "side of the cable the peg stays on)",
                    )
                )
            elif fixture.type == "clip" and (entry.side is not None or entry.wind):
                key = "side" if entry.side is not None else "wind"
                issues.append(
                    Issue(
                        (*here, key),
                        f"clip {entry.fixture} takes no {key} (expected only fixture: the cable "
                        "runs along the slot)",
                    )
                )
    names = [c.name for c in scenario.cables]
    for i, step in enumerate(scenario.task):
        named = step.params.get("cable")
        if isinstance(named, str) and named not in names:
            issues.append(
                Issue(
                    ("task", i, "cable"), f"{named!r} is unknown (expected a cable: {_list(names)})"
                )
            )
    if not scenario.task and not any(c.route for c in scenario.cables):
        issues.append(
            Issue(
                ("task",),
                "missing (expected a task, or a route on a cable for the planner to make one)",
            )
        )
    return issues


def _list(names: list[str]) -> str:
    """Names for a message: ``'A1, P1'`` or ``'none'``."""
    return ", ".join(names) if names else "none"
