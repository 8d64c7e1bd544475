"""Checks that names are unique and every name a scenario uses exists."""

from __future__ import annotations

from collections.abc import Iterable
from typing import TYPE_CHECKING

from tautwire.scenario.issue import Issue
from tautwire.scenario.primitive_catalogue import find_primitive
from tautwire.scenario.workspace import HOLD_MIN_SEPARATION

if TYPE_CHECKING:
    from tautwire.scenario.models import Scenario


def check_references(scenario: Scenario) -> list[Issue]:
    """Find duplicate names, dangling references and conflicting holds.

    Checks: fixture and cable names are unique; a cable's ``start`` names an
    anchor and its ``via`` entries name pegs or clips; a cable's two holds
    use different arms and different points; an arm holds at most one
    cable; a hold lies on the cable; a task step's ``clip`` names a clip and
    ``about`` a fixture; a grasp (H) lies on some cable.

    Args:
        scenario: a schema-valid scenario.

    Returns:
        The issues found, in document order (empty if none).
    """
    issues: list[Issue] = []
    fixtures = {f.name: f for f in scenario.board.fixtures}
    issues += _duplicates(
        [f.name for f in scenario.board.fixtures], ("board", "fixtures"), "fixture"
    )
    issues += _duplicates([c.name for c in scenario.cables], ("cables",), "cable")
    anchors = [f.name for f in scenario.board.fixtures if f.type == "anchor"]
    routable = [f.name for f in scenario.board.fixtures if f.type != "anchor"]
    holder: dict[str, str] = {}
    for i, cable in enumerate(scenario.cables):
        here = ("cables", i)
        if cable.start is not None and cable.start not in anchors:
            what = (
                f"is {_a(fixtures[cable.start].type)}" if cable.start in fixtures else "is unknown"
            )
            issues.append(
                Issue(
                    (*here, "start"),
                    f"{cable.start!r} {what} (expected an anchor: {_list(anchors)})",
                )
            )
        for j, name in enumerate(cable.via):
            if name not in routable:
                what = f"is {_a(fixtures[name].type)}" if name in fixtures else "is unknown"
                issues.append(
                    Issue(
                        (*here, "via", j),
                        f"{name!r} {what} (expected a peg or clip: {_list(routable)})",
                    )
                )
        for k, hold in enumerate(cable.held_by):
            at = (*here, "held_by", k)
            if hold.at > cable.length:
                issues.append(
                    Issue(
                        (*at, "at"),
                        f"{hold.at:g} m is beyond the end of cable {cable.name} "
                        f"(expected 0 <= at <= length = {cable.length:g} m)",
                    )
                )
            if hold.arm in holder:
                issues.append(
                    Issue(
                        (*at, "arm"),
                        f"the {hold.arm} gripper already holds cable {holder[hold.arm]} "
                        "(expected each gripper to hold at most one point of one cable)",
                    )
                )
            holder[hold.arm] = cable.name
        if len(cable.held_by) == 2:
            gap = abs(cable.held_by[0].at - cable.held_by[1].at)
            if gap < HOLD_MIN_SEPARATION:
                issues.append(
                    Issue(
                        (*here, "held_by", 1, "at"),
                        f"both grippers hold cable {cable.name} at the same point "
                        f"({gap:g} m apart) (expected holds at least "
                        f"{HOLD_MIN_SEPARATION:g} m apart along the cable)",
                    )
                )
    issues += _task_references(scenario)
    return issues


def _task_references(scenario: Scenario) -> list[Issue]:
    """Check the fixtures and arc lengths that task steps refer to."""
    issues: list[Issue] = []
    fixtures = {f.name: f for f in scenario.board.fixtures}
    clips = [f.name for f in scenario.board.fixtures if f.type == "clip"]
    longest = max((c.length for c in scenario.cables), default=0.0)
    for i, step in enumerate(scenario.task):
        spec = find_primitive(step.primitive)
        for param in spec.parameters:
            value = step.params.get(param.name)
            if not isinstance(value, str):
                continue
            loc = ("task", i, param.name)
            if param.kind == "clip" and value not in clips:
                what = f"is {_a(fixtures[value].type)}" if value in fixtures else "is unknown"
                issues.append(Issue(loc, f"{value!r} {what} (expected a clip: {_list(clips)})"))
            if param.kind == "fixture" and value not in fixtures:
                issues.append(
                    Issue(loc, f"{value!r} is unknown (expected a fixture: {_list(fixtures)})")
                )
        at = step.params.get("at")
        if spec.letter == "H" and isinstance(at, float) and at > longest:
            issues.append(
                Issue(
                    ("task", i, "at"),
                    f"{at:g} m is beyond the end of every cable "
                    f"(expected an arc length <= {longest:g} m)",
                )
            )
    return issues


def _duplicates(names: list[str], where: tuple[str, ...], what: str) -> list[Issue]:
    """Issues for every name that repeats an earlier one."""
    issues: list[Issue] = []
    seen: set[str] = set()
    for i, name in enumerate(names):
        if name in seen:
            issues.append(
                Issue(
                    (*where, i, "name"),
                    f"{what} name {name!r} is used twice (expected unique names)",
                )
            )
        seen.add(name)
    return issues


def _a(word: str) -> str:
    """``word`` with its indefinite article: ``an anchor``, ``a peg``."""
    return f"an {word}" if word[:1] in "aeiou" else f"a {word}"


def _list(names: Iterable[str]) -> str:
    """Names for a message, or ``there are none``."""
    items = list(names)
    return ", ".join(str(n) for n in items) if items else "there are none"
