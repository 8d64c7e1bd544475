"""Table I's randomised scenes: F's clips stay within what one arm can press; every holding
gripper starts at any yaw, and the slack is measured along the route the simulator lays."""

from __future__ import annotations

import math
from typing import Any

import numpy as np
import pytest

from tautwire.experiments import run_scenario as run_scenario_module
from tautwire.experiments.robustness_scene import PAD_EXIT
from tautwire.experiments.run_scenario import RunResult
from tautwire.experiments.trial import LETTERS, TrialSpec, trial_seed
from tautwire.experiments.trial_scenes import (
    FORCE_LIMIT,
    PRESS_RESERVE,
    _pivot_press,
    pair_route_length,
    trial_scene,
)
from tautwire.primitives.clip_sensing import JAW_TOP
from tautwire.primitives.single_arm_clipping import TABLE_CLEARANCE
from tautwire.scenario.models import CLIP_LENGTH
from tautwire.sim.build import world_spec
from tautwire.sim.mjcf import scene_model
from tautwire.sim.options import SimOptions


def test_pivot_press_of_a_stiff_cable_level_with_the_clip() -> None:
    # the anchor level with the jaws' top: no press lost on its side; a stiff
    # span keeps the gripper 0.1 m beyond the exit at any tension, so the
    # hardest press is at the highest tension, bent down to the table
    seat = np.array([0.3, 0.0, 0.1])
    u = np.array([1.0, 0.0, 0.0])
    anchor = seat - np.array([0.2, 0.0, -JAW_TOP])
    far = 0.2 - 0.5 * CLIP_LENGTH
    at = far + CLIP_LENGTH + 0.1
    press = _pivot_press(anchor, seat, u, at, 1e7)
    drop = seat[2] + JAW_TOP - TABLE_CLEARANCE
    assert press == pytest.approx(0.6 * FORCE_LIMIT * min(drop / 0.1, math.sin(math.radians(60))))


def test_soft_cable_presses_less_than_a_stiff_one_in_the_same_place() -> None:
    seat = np.array([0.3, 0.0, 0.12])
    u = np.array([1.0, 0.0, 0.0])
    anchor = seat + np.array([-0.25, 0.0, 0.05])
    assert _pivot_press(anchor, seat, u, 0.35, 30.0) < _pivot_press(anchor, seat, u, 0.35, 3000.0)


@pytest.mark.parametrize("index", range(0, 100, 7))
def test_f_clip_needs_at_most_the_press_one_arm_can_make(index: int) -> None:
    scene = trial_scene("F", trial_seed(0, "F", index))
    x = scene.inputs
    anchor = np.array([x["anchor_x"], x["anchor_y"], x["anchor_z"]])
    seat = np.array([x["clip_x"], x["clip_y"], x["clip_z"]])
    gripper = np.array([x["gripper_x"], x["gripper_y"], x["gripper_z"]])
    u = gripper - anchor
    u[2] = 0.0
    u /= np.linalg.norm(u)
    span = x["stiffness"] * x["length"] / x["hold_at"]
    top = _pivot_press(anchor, seat, u, x["hold_at"], span) / PRESS_RESERVE
    assert 1.0 <= x["push_force"] <= min(top, 4.0) + 1e-5


#: The inputs naming each holding gripper's start yaw against the cable, by scene letter.
YAW_INPUTS = {
    "A": ("yaw_left_to_cable", "yaw_right_to_cable"),
    "B": ("yaw_left_to_cable", "yaw_right_to_cable"),
    "C": ("yaw_left_to_cable", "yaw_right_to_cable"),
    **{letter: ("tool_yaw_to_cable",) for letter in "DEFGHI"},
}


@pytest.mark.parametrize("letter", LETTERS)
def test_every_holding_gripper_starts_at_any_yaw(letter: str) -> None:
    # over 40 seeds each yaw against the cable fills the circle: along it,
    # across it and pointing back at the fixture or the other gripper
    for name in YAW_INPUTS[letter]:
        yaws = np.array(
            [float(trial_scene(letter, trial_seed(0, letter, i)).inputs[name]) for i in range(40)]
        )
        assert np.all((yaws >= -math.pi) & (yaws < math.pi))
        counts = np.histogram(yaws, bins=4, range=(-math.pi, math.pi))[0]
        assert np.all(counts >= 3), counts


def test_the_two_grippers_yaws_are_independent() -> None:
    pairs = [trial_scene("A", trial_seed(0, "A", i)).inputs for i in range(40)]
    left = np.array([float(x["yaw_left_to_cable"]) for x in pairs])
    right = np.array([float(x["yaw_right_to_cable"]) for x in pairs])
    assert abs(float(np.corrcoef(left, right)[0, 1])) < 0.5
    assert np.sum(np.sign(np.cos(left)) != np.sign(np.cos(right))) >= 10


def _laid_ratio(letter: str, index: int) -> tuple[float, float]:
    """(laid length / rest length of the held span, the drawn slack) of one scene."""
    scene = trial_scene(letter, trial_seed(0, letter, index))
    scenario = scene.scenario
    model = scene_model(world_spec(scenario), SimOptions())
    cable = scenario.cables[0]
    laid, arc = model.vertices["W1"], model.discretizations["W1"].arc
    holds = sorted(h.at for h in cable.held_by)
    a = 0.0 if cable.start is not None else holds[0]
    b = holds[-1]
    ia, ib = int(np.argmin(np.abs(arc - a))), int(np.argmin(np.abs(arc - b)))
    length = float(np.sum(np.linalg.norm(np.diff(laid[ia : ib + 1], axis=0), axis=1)))
    return length / (b - a), float(scene.inputs["slack"])


@pytest.mark.parametrize("letter", LETTERS)
@pytest.mark.parametrize("index", [0, 3, 6, 9])
def test_the_route_the_simulator_lays_leaves_the_drawn_slack(letter: str, index: int) -> None:
    # a grasp across the cable or pointing back along it starts slack, not stretched
    # (the laid vertices cut the corner where the route bends into the fingers;
    # G's pitch tilts the fingers' exit out of the yawed route the slack is drawn on)
    ratio, slack = _laid_ratio(letter, index)
    assert ratio < 1.0
    assert ratio == pytest.approx(slack, abs=2e-3 if letter == "G" else 2e-4)


def test_pair_route_lengths_of_simple_layouts() -> None:
    left, right = np.array([0.0, 0.0, 0.3]), np.array([0.2, 0.0, 0.3])
    x, y = np.array([1.0, 0.0, 0.0]), np.array([0.0, 1.0, 0.0])
    # along the line, either sense: straight
    assert pair_route_length(left, right, x, x) == pytest.approx(0.2)
    assert pair_route_length(left, right, -x, x) == pytest.approx(0.2)
    # both across it: out of the fingers sideways, then straight across
    assert pair_route_length(left, right, y, y) == pytest.approx(0.2 + 2.0 * PAD_EXIT)
    # one across: the right entry lies on the straight line from the left exit
    side = math.hypot(0.2 - PAD_EXIT, PAD_EXIT)
    assert pair_route_length(left, right, x, y) == pytest.approx(side + 2.0 * PAD_EXIT)


def test_a_success_the_simulator_denies_fails_the_trial(monkeypatch: pytest.MonkeyPatch) -> None:
    scene = trial_scene("A", trial_seed(0, "A", 0))

    def denied(*args: Any, **kwargs: Any) -> tuple[RunResult, None, None]:
        step = {
            "primitive": "parallel_tension",
            "letter": "A",
            "outcome": "success",
            "cause": None,
            "detail": "tension 2.60 N held 0.5 s",
            "sim_time": 1.0,
            "max_force": 2.7,
            "cable": "W1",
            "truth": {"agrees": False, "detail": "true tension 0.50 N"},
        }
        result = RunResult("s", 0, False, [step], [], {}, None, 2.7, 1.0, 1.0, false_successes=1)
        return result, None, None

    monkeypatch.setattr(run_scenario_module, "run_scenario", denied)
    trial = scene.run(TrialSpec("A", 0, 0))
    assert trial.outcome == "failure" and trial.cause == "false_success"
    assert "true tension 0.50 N" in trial.detail
