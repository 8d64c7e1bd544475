from __future__ import annotations

from typing import Any

import pytest
import yaml
from pydantic import ValidationError

from tautwire.scenario import Scenario
from tautwire.scenario.error_messages import describe_error
from tests.scenario.cases import EXAMPLE


def describe(data: dict[str, Any]) -> tuple[tuple[str | int, ...], str]:
    with pytest.raises(ValidationError) as info:
        Scenario.model_validate(data)
    return describe_error(Scenario, info.value.errors()[0])


def test_discriminated_union_tag_is_located_at_type() -> None:
    data = yaml.safe_load(EXAMPLE)
    del data["board"]["fixtures"][0]["type"]
    location, message = describe(data)
    assert location == ("board", "fixtures", 0, "type")
    assert message.startswith("missing")


def test_missing_field_inside_a_fixture_names_unit() -> None:
    data = yaml.safe_load(EXAMPLE)
    del data["board"]["fixtures"][1]["radius"]
    location, message = describe(data)
    assert location == ("board", "fixtures", 1, "peg", "radius")
    assert message == "missing (expected peg radius [m])"


def test_located_validator_error_gets_its_full_location() -> None:
    data = yaml.safe_load(EXAMPLE)
    data["task"][0]["force"] = 0
    assert describe(data) == (
        ("task", 0, "force"),
        "got 0 (expected a number > 0: desired cable tension [N])",
    )


def test_wrong_mapping_lists_its_keys() -> None:
    data = yaml.safe_load(EXAMPLE)
    data["robot"]["sensor"] = 5
    assert describe(data) == (
        ("robot", "sensor"),
        "got 5 (expected a mapping with arm, noise_force, noise_torque)",
    )
