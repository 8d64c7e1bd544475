"""The shipped harness board runs its planned routes, and never claims what the simulator denies.

``harness.yaml`` carries routes for two cables and the task the planner
makes from them. Whatever step it reaches, every success must be true
(0 false successes), every step names its cable, a failure names its cause,
and a cable's route counts as done only if the simulator shows it on its
route.
"""

from __future__ import annotations

import pytest

pytest.importorskip("mujoco")

from tautwire.experiments.run_scenario import run_scenario
from tautwire.scenario import load_scenario
from tautwire.scenario.registry import scenario_path


@pytest.mark.slow
def test_the_harness_run_is_truthful() -> None:
    scenario = load_scenario(scenario_path("harness"))
    result, _, _ = run_scenario(scenario)
    assert result.steps
    assert result.false_successes == 0, [s["truth"] for s in result.steps]
    assert all(s["cable"] in ("W1", "W2") for s in result.steps)
    for step in result.steps:
        assert (step["outcome"] == "success") == (step["cause"] is None)
    assert [c["name"] for c in result.cables] == ["W1", "W2"]
    for cable in result.cables:
        if cable["route_done"]:
            assert cable["route_truth"]["agrees"], cable
    if result.success:  # a run that completes has every route truly done
        assert all(c["route_truth"]["agrees"] for c in result.cables), result.cables
