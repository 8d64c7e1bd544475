from __future__ import annotations

from typing import Any

import pytest
import yaml

from tautwire.scenario import Scenario, ScenarioError, scenario_from_data
from tautwire.scenario.geometry import check_geometry
from tests.scenario.cases import EXAMPLE


def example() -> dict[str, Any]:
    data: dict[str, Any] = yaml.safe_load(EXAMPLE)
    return data


def field_of(data: dict[str, Any]) -> tuple[str, str]:
    with pytest.raises(ScenarioError) as info:
        scenario_from_data(data)
    return info.value.field, info.value.message


def test_example_has_no_issues() -> None:
    assert check_geometry(Scenario.model_validate(example())) == []


def test_cable_shorter_than_its_route() -> None:
    # A1 -> P1 (its axis at z = 0.12) -> left gripper: 0.1581 + 0.2236 = 0.3817 m.
    data = example()
    data["cables"][0]["length"] = 0.38
    data["cables"][0]["held_by"]["at"] = 0.38
    field, message = field_of(data)
    assert field == "cables[0].length"
    assert "A1 -> P1 -> left gripper is 0.382 m" in message
    data["cables"][0]["length"] = 0.385
    data["cables"][0]["held_by"]["at"] = 0.385
    assert scenario_from_data(data).cables[0].length == 0.385


def test_hold_too_close_to_the_start_for_the_route() -> None:
    data = example()
    data["cables"][0]["held_by"]["at"] = 0.30
    field, message = field_of(data)
    assert field == "cables[0].held_by[0].at" and "cannot span" in message


def test_two_holds_too_far_apart_for_the_cable_between_them() -> None:
    data = example()
    data["cables"][0]["via"] = []
    data["cables"][0]["held_by"] = [{"arm": "left", "at": 0.42}, {"arm": "right", "at": 0.10}]
    data["robot"]["grippers"]["right"]["position"] = [0.05, 0.0, 0.12]
    # left (0.35, 0.15) and right (0.05, 0) are 0.335 m apart; 0.32 m of cable between them
    field, message = field_of(data)
    assert field == "cables[0].held_by[0].at" and "right gripper -> left gripper" in message


def test_free_end_with_via_fixture() -> None:
    data = example()
    data["cables"][0]["start"] = None
    data["cables"][0]["held_by"]["at"] = 0.2
    # P1 -> left gripper is about 0.2245 m
    assert "P1 -> left gripper" in field_of(data)[1]
    data["cables"][0]["held_by"]["at"] = 0.23
    assert scenario_from_data(data).cables[0].start is None


@pytest.mark.parametrize("position", [[0.9, 0.0, 0.1], [0.3, -0.7, 0.1], [0.3, 0.0, -0.01]])
def test_gripper_out_of_reach(position: list[float]) -> None:
    data = example()
    data["robot"]["grippers"]["right"]["position"] = position
    field, message = field_of(data)
    assert field == "robot.grippers.right.position" and "out of the robot's reach" in message


def test_peg_top_out_of_reach() -> None:
    data = example()
    data["board"]["fixtures"][1]["height"] = 0.6
    assert field_of(data)[0] == "board.fixtures[1].position"


def test_grippers_starting_on_top_of_each_other() -> None:
    data = example()
    data["robot"]["grippers"]["right"]["position"] = [0.35, 0.16, 0.12]
    field, message = field_of(data)
    assert field == "robot.grippers.right.position" and "apart" in message


def test_via_fixtures_lie_before_the_first_hold_by_arc_length() -> None:
    # Holds listed out of order: the route is P1 -> right (at 0.15) -> left (at 0.42).
    data = example()
    data["cables"][0]["start"] = None
    data["cables"][0]["held_by"] = [{"arm": "left", "at": 0.42}, {"arm": "right", "at": 0.15}]
    data["robot"]["grippers"]["right"]["position"] = [0.25, 0.05, 0.12]
    assert scenario_from_data(data).cables[0].held_by[1].arm == "right"
    data["robot"]["grippers"]["right"]["position"] = [0.35, -0.10, 0.12]
    field, message = field_of(data)
    assert field == "cables[0].held_by[1].at" and "P1 -> right gripper" in message
