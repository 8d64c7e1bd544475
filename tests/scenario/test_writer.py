from __future__ import annotations

from pathlib import Path

import pytest

from tautwire.scenario import load_scenario, parse_scenario, scenario_from_data
from tautwire.scenario.writer import dump_scenario, scenario_document
from tests.scenario.cases import SCENARIOS


@pytest.mark.parametrize("path", sorted(SCENARIOS.glob("*.yaml")), ids=lambda p: p.name)
def test_round_trip_through_text(path: Path) -> None:
    scenario = load_scenario(path)
    assert parse_scenario(dump_scenario(scenario)) == scenario


def test_document_writes_steps_flat() -> None:
    document = scenario_document(load_scenario(SCENARIOS / "peg-and-clip.yaml"))
    assert document["task"][0] == {"primitive": "single_arm_tension", "arm": "left", "force": 3.0}
    assert document["robot"]["grippers"]["left"]["position"] == [0.35, 0.15, 0.12]
    assert scenario_from_data(document).name == "peg-and-clip"
