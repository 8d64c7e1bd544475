from __future__ import annotations

import math
from typing import Any

import pytest
import yaml
from pydantic import ValidationError

from tautwire.errors import InvalidArgumentError
from tautwire.scenario import GripperStart, Hold, Peg, Scenario, SensorSettings, TaskStep
from tests.scenario.cases import EXAMPLE


def example() -> dict[str, Any]:
    data: dict[str, Any] = yaml.safe_load(EXAMPLE)
    return data


def test_defaults_of_optional_settings() -> None:
    data = example()
    data["robot"] = {"grippers": data["robot"]["grippers"]}
    del data["seed"]
    s = Scenario.model_validate(data)
    assert s.seed == 0
    assert (s.robot.control_period, s.robot.force_limit) == (0.004, 15.0)
    assert s.robot.sensor == SensorSettings(arm="left", noise_force=0.05, noise_torque=0.002)


def test_orientation_is_normalised() -> None:
    g = GripperStart.model_validate({"position": [0, 0, 0.1], "orientation": [2, 0, 0, 2]})
    assert g.orientation == pytest.approx((math.sqrt(0.5), 0.0, 0.0, math.sqrt(0.5)))


def test_zero_orientation_is_rejected() -> None:
    with pytest.raises(ValidationError, match="must not be zero"):
        GripperStart.model_validate({"position": [0, 0, 0.1], "orientation": [0, 0, 0, 0]})


def test_models_are_frozen_and_forbid_unknown_keys() -> None:
    hold = Hold(arm="left", at=0.2)
    with pytest.raises(ValidationError):
        hold.at = 0.3  # type: ignore[misc]
    with pytest.raises(ValidationError, match="extra"):
        Hold.model_validate({"arm": "left", "at": 0.2, "grip": 1})


@pytest.mark.parametrize("value", ["0.2", True, float("nan"), float("inf")])
def test_numbers_are_strict_and_finite(value: object) -> None:
    with pytest.raises(ValidationError):
        Hold.model_validate({"arm": "left", "at": value})


def test_integers_are_accepted_for_floats() -> None:
    peg = Peg.model_validate(
        {"name": "P", "type": "peg", "position": [0, 0, 0], "radius": 1, "height": 1}
    )
    assert peg.position == (0.0, 0.0, 0.0)


def test_held_by_accepts_one_mapping_or_a_list_of_two() -> None:
    data = example()
    data["cables"][0]["held_by"] = [{"arm": "right", "at": 0.1}, {"arm": "left", "at": 0.42}]
    data["robot"]["grippers"]["right"]["position"] = [0.1, 0.0, 0.12]
    data["cables"][0]["via"] = []
    s = Scenario.model_validate(data)
    assert [h.arm for h in s.cables[0].held_by] == ["right", "left"]
    data["cables"][0]["held_by"] = [{"arm": "left", "at": 0.42}] * 3
    with pytest.raises(ValidationError, match="at most 2"):
        Scenario.model_validate(data)


def test_fixture_and_cable_lookup() -> None:
    s = Scenario.model_validate(example())
    peg = s.fixture("P1")
    assert isinstance(peg, Peg) and peg.height == 0.05
    assert s.cable("W1").length == 0.42
    with pytest.raises(InvalidArgumentError, match="A1, P1, C1"):
        s.fixture("X")
    with pytest.raises(InvalidArgumentError, match="W1"):
        s.cable("W9")


def test_task_step_in_canonical_form_round_trips() -> None:
    step = TaskStep.model_validate({"primitive": "I", "arm": "left", "angle": -1})
    assert (step.primitive, step.letter) == ("rotate_around_feature_point", "I")
    assert step.params == {"arm": "left", "angle": -1.0, "axis": [0.0, 0.0, 1.0]}
    assert TaskStep.model_validate(step.model_dump()) == step
    assert step.spec.letter == "I"


def test_task_step_letter_must_match_its_primitive() -> None:
    with pytest.raises(ValidationError, match="expected 'A'"):
        TaskStep.model_validate(
            {"primitive": "parallel_tension", "letter": "B", "params": {"force": 1.0}}
        )


def test_simulation_settings_are_not_part_of_the_file() -> None:
    data = example()
    data["sim"] = {"timestep": 0.0005}
    with pytest.raises(ValidationError, match="extra"):
        Scenario.model_validate(data)
