"""Sequences that compose: after a primitive, every primitive whose physics allows runs.

Each starts from a seeded Table I scene (its own preparatory steps and
primitive), then runs what a harness builder runs next. Every step must
succeed with the simulator agreeing.
"""

from __future__ import annotations

from typing import Any

import pytest

pytest.importorskip("mujoco")

from tautwire.experiments.run_scenario import RunResult, run_scenario
from tautwire.experiments.trial import trial_seed
from tautwire.experiments.trial_scenes import trial_scene
from tautwire.scenario.loader import scenario_from_data
from tautwire.scenario.writer import scenario_document


def _after(letter: str, extra: list[dict[str, Any]], before_last: bool = False) -> RunResult:
    """The scene of ``letter`` with ``extra`` after its task (or before its last step)."""
    seed = trial_seed(0, letter, 0)
    doc = scenario_document(trial_scene(letter, seed).scenario)
    task = list(doc["task"])
    doc["task"] = task[:-1] + extra + task[-1:] if before_last else task + extra
    result, _, _ = run_scenario(scenario_from_data(doc), seed)
    return result


def _all_true(result: RunResult) -> None:
    assert [s["outcome"] for s in result.steps] == ["success"] * len(result.steps), result.steps
    assert all(s["truth"]["agrees"] for s in result.steps), result.steps
    assert result.success and result.false_successes == 0


@pytest.mark.slow
def test_a_and_b_run_after_a_parallel_clip() -> None:
    # the clip's point now sits between the grippers: each side is still held by both
    result = _after(
        "C",
        [
            {"primitive": "A", "force": 3.0},
            {"primitive": "B", "slide_arm": "right", "distance": 0.03, "friction_force": 1.5},
        ],
    )
    _all_true(result)
    assert "against C1" in result.steps[-2]["truth"]["detail"]  # A's tension: the clip's side


@pytest.mark.slow
def test_a_hand_over_grasp_release_and_the_first_gripper_pulls_again() -> None:
    result = _after(
        "H",
        [
            {"primitive": "release", "arm": "right"},
            {"primitive": "move", "arm": "right", "by": [0.0, 0.0, 0.05], "taut": False},
            {"primitive": "D", "arm": "left", "force": 3.0},
        ],
    )
    _all_true(result)
    assert "truly let go" in result.steps[2]["truth"]["detail"]
    assert "against A1" in result.steps[-1]["truth"]["detail"]


@pytest.mark.slow
def test_f_after_a_regrip_feels_the_snap_where_the_cable_leaves_the_fingers() -> None:
    # E leaves the cable behind and below the tool centre point; F reads the
    # clip's height from the force's line of action, not from the TCP (from
    # the TCP it read 12.8 mm above the seat and never felt the snap)
    result = _after(
        "F",
        [
            {"primitive": "E", "arm": "left", "distance": 0.03, "friction_force": 1.5},
            {"primitive": "D", "arm": "left", "force": 3.0},
        ],
        before_last=True,
    )
    _all_true(result)
    assert result.steps[-1]["letter"] == "F"
    assert "is in the jaws of C1" in result.steps[-1]["truth"]["detail"]
