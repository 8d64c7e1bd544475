"""Two cables on one board: each step works on its own cable's model, sensed by its gripper.

The harness board with its task cut down to a pull on each cable: with
``sensor.arm: both`` each gripper measures the tension of its own cable
(the truth of each step agrees), and each cable has its own model and
scores; with one sensor, a pull by the gripper without one is refused.
"""

from __future__ import annotations

import pytest

pytest.importorskip("mujoco")

from tautwire.experiments.run_scenario import run_scenario, task_of
from tautwire.scenario import Scenario, load_scenario
from tautwire.scenario.loader import scenario_from_data
from tautwire.scenario.registry import scenario_path
from tautwire.scenario.route_problem import plan_scenario
from tautwire.scenario.writer import scenario_document

PULLS = [
    {"primitive": "single_arm_tension", "arm": "left", "force": 3.0, "cable": "W1"},
    {"primitive": "single_arm_tension", "arm": "right", "force": 2.0},
]


def _harness(task: list[dict[str, object]] | None, sensor: str = "both") -> Scenario:
    doc = scenario_document(load_scenario(scenario_path("harness")))
    doc["robot"]["sensor"]["arm"] = sensor
    if task is None:
        doc.pop("task", None)
    else:
        doc["task"] = task
    return scenario_from_data(doc)


@pytest.mark.slow
def test_with_two_sensors_each_step_senses_its_own_cable() -> None:
    result, _, _ = run_scenario(_harness(PULLS))
    assert [s["outcome"] for s in result.steps] == ["success", "success"], result.steps
    assert [s["cable"] for s in result.steps] == ["W1", "W2"]
    assert all(s["truth"]["agrees"] for s in result.steps), result.steps
    assert result.success and result.false_successes == 0
    assert [c["name"] for c in result.cables] == ["W1", "W2"]
    for cable, truth in zip(result.cables, (200.0, 350.0), strict=True):
        assert cable["stiffness"]["truth"] == truth
        assert cable["stiffness"]["estimate"] is not None
        assert cable["route_done"] is False  # the routes were not run
        # the anchor and the gripper of each cable against their true points
        assert cable["model_error"]["horizontal_max"] < 0.003
        assert cable["shape_error"] is not None
    assert result.model_error is not None and result.shape_error is not None


@pytest.mark.slow
def test_with_one_sensor_the_other_gripper_cannot_pull_its_cable() -> None:
    result, _, _ = run_scenario(_harness(PULLS, sensor="left"))
    assert [s["outcome"] for s in result.steps] == ["success", "failure"]
    assert result.steps[1]["cause"] == "precondition"
    assert "no force sensor" in result.steps[1]["detail"]
    assert not result.success


def test_a_scenario_with_routes_and_no_task_runs_the_planned_task() -> None:
    scenario = _harness(None)
    assert not scenario.task
    planned = [{"primitive": s.primitive, **s.params} for s in task_of(scenario)]
    assert planned == plan_scenario(scenario).task()
    assert len(planned) > 10
