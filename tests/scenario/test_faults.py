"""The optional ``faults:`` section of a scenario (SCENARIO.md, "Faults")."""

from __future__ import annotations

import pytest

from tautwire.scenario import (
    BiasDriftFault,
    FreezeFault,
    NanFault,
    RobotErrorFault,
    SlipFault,
    SpikeFault,
    parse_scenario,
)
from tautwire.scenario.writer import dump_scenario
from tests.scenario.cases import EXAMPLE, error_of, line_of

ALL_FAULTS = """faults:
  - {type: spike, at: 3.2, force: [0, 0, 40]}
  - {type: nan, at: 5.0}
  - {type: freeze, at: 4.0, duration: 0.5}
  - {type: bias_drift, at: 2.0, duration: 10.0, force: [0.5, 0, 0]}
  - {type: slip, at: 6.0, duration: 1.0, arm: left}
  - {type: slip, at: 6.0, duration: 1.0}
  - {type: robot_error, at: 7.0}
  - {type: robot_error, at: 7.0, count: 3}
  - {type: robot_error, at: 7.0, duration: 0.2}
"""


def with_faults(section: str) -> str:
    return EXAMPLE.rstrip("\n") + "\n" + section


def test_a_file_without_faults_has_none() -> None:
    assert parse_scenario(EXAMPLE).faults == []


def test_every_fault_type_of_scenario_md_loads() -> None:
    faults = parse_scenario(with_faults(ALL_FAULTS)).faults
    assert faults[0] == SpikeFault(type="spike", at=3.2, force=(0.0, 0.0, 40.0))
    assert faults[1] == NanFault(type="nan", at=5.0)
    assert faults[2] == FreezeFault(type="freeze", at=4.0, duration=0.5)
    assert faults[3] == BiasDriftFault(
        type="bias_drift", at=2.0, duration=10.0, force=(0.5, 0.0, 0.0)
    )
    assert faults[4] == SlipFault(type="slip", at=6.0, duration=1.0, arm="left")
    assert isinstance(faults[5], SlipFault) and faults[5].arm is None
    assert faults[6] == RobotErrorFault(type="robot_error", at=7.0)
    assert isinstance(faults[7], RobotErrorFault) and faults[7].count == 3
    assert isinstance(faults[8], RobotErrorFault) and faults[8].duration == 0.2


def test_faults_survive_the_round_trip_through_text() -> None:
    scenario = parse_scenario(with_faults(ALL_FAULTS))
    assert parse_scenario(dump_scenario(scenario)) == scenario


@pytest.mark.parametrize(
    ("entry", "field", "words"),
    [
        ("{type: quake, at: 1}", "faults[0].type", "expected one of: 'spike', 'nan', 'freeze'"),
        ("{at: 1}", "faults[0].type", "missing (expected one of: 'spike', 'nan'"),
        ("{type: nan, at: 1, force: [1, 2, 3]}", "faults[0].force", "unknown key"),
        ("{type: nan}", "faults[0].at", "missing (expected time from the start"),
        ("{type: nan, at: -0.5}", "faults[0].at", "greater than or equal to 0 [s]"),
        ("{type: freeze, at: 1, duration: 0}", "faults[0].duration", "greater than 0 [s]"),
        ("{type: spike, at: 1, force: [1, 2]}", "faults[0].force", "exactly 3 [N]"),
        ("{type: spike, at: 1}", "faults[0].force", "missing"),
        ("{type: slip, at: 1, duration: 1, arm: middle}", "faults[0].arm", "'left' or 'right'"),
        ("{type: robot_error, at: 1, count: 2.5}", "faults[0].count", "an integer"),
        ("{type: robot_error, at: 1, count: 0}", "faults[0].count", "greater than or equal to 1"),
        (
            "{type: robot_error, at: 1, count: 2, duration: 0.2}",
            "faults[0].duration",
            "count or duration, not both",
        ),
        (
            "{type: bias_drift, at: 1, duration: 1, force: [.nan, 0, 0]}",
            "faults[0].force[0]",
            "finite",
        ),
    ],
)
def test_a_wrong_fault_names_its_line_and_field(entry: str, field: str, words: str) -> None:
    text = with_faults(f"faults:\n  - {{type: nan, at: 0.5}}\n  - {entry}\n")
    message = str(error_of(text))
    assert f":{line_of(text, entry)}: " in message
    assert f" {field.replace('[0]', '[1]', 1)}: " in message
    assert words in message


def test_faults_must_be_a_list() -> None:
    message = str(error_of(with_faults("faults: {type: nan, at: 1}\n")))
    assert "faults: " in message and "expected a list" in message
