"""Routes, a step's cable and the moves in scenario files (SCENARIO.md, additions)."""

from __future__ import annotations

import pytest

from tautwire.scenario import load_scenario, parse_scenario
from tautwire.scenario.models import RouteEntry
from tautwire.scenario.route_problem import plan_scenario
from tests.scenario.cases import EXAMPLE, SCENARIOS, edit, error_of, line_of

HELD = (
    "    held_by: {arm: left, at: 0.42} # gripper and arc length (m from start) where it is held;"
)

ROUTED = edit(
    HELD,
    HELD + "\n    route:\n      - {fixture: P1, side: left, wind: 2}\n      - {fixture: C1}",
)


def test_a_route_is_read_in_order() -> None:
    cable = parse_scenario(ROUTED).cables[0]
    assert cable.route == [RouteEntry(fixture="P1", side="left", wind=2), RouteEntry(fixture="C1")]


def test_without_a_task_a_route_is_enough() -> None:
    task = EXAMPLE[EXAMPLE.index("task:") :]
    scenario = parse_scenario(ROUTED.replace(task, ""))
    assert scenario.task == []
    err = error_of(EXAMPLE.replace(task, ""))
    assert err.field == "task" and "route" in err.message


@pytest.mark.parametrize(
    ("entry", "field", "words"),
    [
        ("{fixture: P9, side: left}", "cables[0].route[0].fixture", "'P9' is unknown"),
        ("{fixture: A1}", "cables[0].route[0].fixture", "is an anchor"),
        ("{fixture: P1}", "cables[0].route[0]", "needs a side"),
        ("{fixture: C1, side: left}", "cables[0].route[0].side", "takes no side"),
        ("{fixture: C1, wind: 1}", "cables[0].route[0].wind", "takes no wind"),
        ("{fixture: P1, side: up}", "cables[0].route[0].side", "left"),
        ("{fixture: P1, side: left, wind: -1}", "cables[0].route[0].wind", ""),
        ("{fixture: P1, side: left, wind: 1.5}", "cables[0].route[0].wind", ""),
    ],
)
def test_a_wrong_route_entry_is_named_with_its_line(entry: str, field: str, words: str) -> None:
    text = edit(HELD, HELD + f"\n    route:\n      - {entry}")
    err = error_of(text)
    assert err.field == field
    assert words in err.message
    assert err.line == line_of(text, entry)


def test_a_step_names_its_cable() -> None:
    step = "{primitive: single_arm_tension, arm: left, force: 3.0}"
    scenario = parse_scenario(edit(step, step.replace("}", ", cable: W1}")))
    assert scenario.task[0].params["cable"] == "W1"
    text = edit(step, step.replace("}", ", cable: W7}"))
    err = error_of(text)
    assert err.field == "task[0].cable" and "'W7' is unknown" in err.message


def test_move_and_release_steps() -> None:
    step = "  - {primitive: single_arm_tension, arm: left, force: 3.0}"
    moves = (
        "\n  - {primitive: move, arm: left, to: [0.3, 0.1, 0.2]}"
        "\n  - {primitive: move, arm: right, by: [0, 0, 0.05], taut: false,"
        " orientation: [2, 0, 0, 0]}"
        "\n  - {primitive: release, arm: left, cable: W1}"
    )
    task = parse_scenario(edit(step, step + moves)).task
    move, lift, release = task[1:4]
    assert (move.primitive, move.letter) == ("move", "")
    assert move.params == {"arm": "left", "to": [0.3, 0.1, 0.2], "taut": True, "observe": True}
    assert lift.params == {
        "arm": "right",
        "by": [0.0, 0.0, 0.05],
        "taut": False,
        "observe": True,
        "orientation": [1.0, 0.0, 0.0, 0.0],
    }
    assert release.params == {"arm": "left", "cable": "W1"}


@pytest.mark.parametrize(
    ("move", "words"),
    [
        ("{primitive: move, arm: left}", "missing (expected to or by"),
        ("{primitive: move, arm: left, to: [0, 0, 0.1], by: [0, 0, 0.1]}", "both given"),
        ("{primitive: move, arm: left, to: [0, 0.1]}", "a list of 3 numbers"),
        ("{primitive: move, arm: left, to: [0, 0, 0.1], taut: 1}", "true or false"),
        ("{primitive: release}", "missing parameter of release"),
    ],
)
def test_wrong_moves(move: str, words: str) -> None:
    step = "  - {primitive: single_arm_tension, arm: left, force: 3.0}"
    err = error_of(edit(step, step + "\n  - " + move))
    assert err.field.startswith("task[1]")
    assert words in err.message


def test_the_harness_task_is_what_the_planner_makes() -> None:
    """scenarios/harness.yaml carries its routes and the task planned from them."""
    harness = load_scenario(SCENARIOS / "harness.yaml")
    assert all(len(c.route) >= 4 for c in harness.cables)
    assert any(e.wind for c in harness.cables for e in c.route)
    planned = plan_scenario(harness)
    assert [{"primitive": s.primitive, **s.params} for s in harness.task] == planned.task()
