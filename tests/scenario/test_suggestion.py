from __future__ import annotations

import pytest

from tautwire.scenario.suggestion import did_you_mean
from tests.scenario.cases import edit, error_of


def test_the_closest_name_or_nothing() -> None:
    keys = ["length", "stiffness", "radius"]
    assert did_you_mean("stifness", keys) == ", did you mean 'stiffness'?"
    assert did_you_mean("Radius", ["radius"]) == ", did you mean 'radius'?"
    assert did_you_mean("colour", keys) == ""
    assert did_you_mean(3, ["x"]) == "" and did_you_mean("", ["x"]) == ""


@pytest.mark.parametrize(
    ("old", "new", "suggested"),
    [
        ("force: 3.0}", "forse: 3.0}", "'force'"),
        ("primitive: single_arm_tension", "primitive: single_arm_tenson", "'single_arm_tension'"),
        ("arm: left   ", "arm: lfet   ", "'left'"),
        ("type: peg", "type: pge", "'peg'"),
        ("    stiffness:", "    stifness:", "'stiffness'"),
    ],
)
def test_misspelt_names_in_a_scenario_get_a_suggestion(old: str, new: str, suggested: str) -> None:
    err = error_of(edit(old, new))
    assert f"did you mean {suggested}?" in str(err)
