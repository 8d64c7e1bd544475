from __future__ import annotations

from typing import Any

import pytest
import yaml

from tautwire.scenario import Scenario, ScenarioError, scenario_from_data
from tautwire.scenario.references import check_references
from tests.scenario.cases import EXAMPLE


def example() -> dict[str, Any]:
    data: dict[str, Any] = yaml.safe_load(EXAMPLE)
    return data


def field_of(data: dict[str, Any]) -> tuple[str, str]:
    with pytest.raises(ScenarioError) as info:
        scenario_from_data(data)
    return info.value.field, info.value.message


def test_example_has_no_issues() -> None:
    assert check_references(Scenario.model_validate(example())) == []


def test_duplicate_fixture_name() -> None:
    data = example()
    data["board"]["fixtures"][2]["name"] = "A1"
    field, message = field_of(data)
    assert field == "board.fixtures[2].name" and "used twice" in message


def test_duplicate_cable_name() -> None:
    data = example()
    second = dict(data["cables"][0], held_by={"arm": "right", "at": 0.42}, via=[])
    data["cables"].append(second)
    field, message = field_of(data)
    assert field == "cables[1].name" and "'W1' is used twice" in message


def test_start_must_be_an_anchor() -> None:
    data = example()
    data["cables"][0]["start"] = "C1"
    assert field_of(data) == ("cables[0].start", "'C1' is a clip (expected an anchor: A1)")


def test_via_must_name_pegs_or_clips() -> None:
    data = example()
    data["cables"][0]["via"] = ["P1", "Q7"]
    assert field_of(data)[0] == "cables[0].via[1]"
    data["cables"][0]["via"] = ["A1"]
    assert "is an anchor" in field_of(data)[1]


def test_hold_beyond_the_cable() -> None:
    data = example()
    data["cables"][0]["held_by"] = {"arm": "left", "at": 0.43}
    field, message = field_of(data)
    assert field == "cables[0].held_by[0].at" and "beyond the end" in message


def test_both_grippers_at_the_same_point() -> None:
    data = example()
    data["cables"][0]["held_by"] = [{"arm": "left", "at": 0.42}, {"arm": "right", "at": 0.41}]
    field, message = field_of(data)
    assert field == "cables[0].held_by[1].at" and "same point" in message


def test_one_gripper_cannot_hold_two_places() -> None:
    data = example()
    data["cables"][0]["held_by"] = [{"arm": "left", "at": 0.42}, {"arm": "left", "at": 0.2}]
    assert field_of(data)[0] == "cables[0].held_by[1].arm"


def test_parallel_clipping_needs_a_clip() -> None:
    data = example()
    data["task"] = [{"primitive": "C", "clip": "C1"}]
    assert scenario_from_data(data).task[0].params == {"clip": "C1"}
    data["task"] = [{"primitive": "C", "clip": "A1"}]
    assert field_of(data) == ("task[0].clip", "'A1' is an anchor (expected a clip: C1)")
