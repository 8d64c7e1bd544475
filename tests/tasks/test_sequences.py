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
from tautwire.scenario.loader import parse_scenario, scenario_from_data
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
@pytest.mark.xfail(
    strict=False,
    reason="measured at f52ae28: the push leaves the cable in the jaws' throat, 3.4-3.9 mm "
    "above the seat (jaw axes at 4.3 mm, truly held), and F's line reads 3.3-4.7 mm about "
    "its SEATED limit of 4 mm: at 88b7422 it read 3.9 mm and passed, here 4.3 mm, so F "
    "pushed again and pulled the cable out (not_clipped, honest). The same throat state "
    "read as seated gives Table I F's false successes",
)
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


#: A cable from an anchor to the left gripper, a clip across the cable's line
#: (69 deg from it: F cannot take it): the planner's H, C, release.
ACROSS_CLIP = """
version: 1
name: h-then-c
seed: 4
robot:
  control_period: 0.004
  force_limit: 15.0
  sensor: {arm: left, noise_force: 0.05, noise_torque: 0.002}
  grippers:
    left:  {position: [0.45, 0.10, 0.12]}
    right: {position: [0.40, -0.20, 0.12]}
board:
  fixtures:
    - {name: A1, type: anchor, position: [0.10, 0.10, 0.08]}
    - {name: C1, type: clip, position: [0.30, 0.12, 0.08], yaw: 1.2, push_force: 2.5}
cables:
  - {name: W1, length: 0.6, mass_per_length: 0.03, stiffness: 200.0, radius: 0.0025,
     start: A1, held_by: {arm: left, at: 0.38}}
task:
  - {primitive: single_arm_tension, arm: left, force: 3.0}
  - {primitive: grasp_tensioned, arm: right, at: 0.26}
  - {primitive: parallel_clipping, clip: C1}
  - {primitive: release, arm: right}
"""


@pytest.mark.slow
def test_c_after_h_turns_the_pair_onto_the_slot_and_clips() -> None:
    # the pair turns 69 deg onto the slot: its tool axes follow the line between
    # the grippers (set straight onto the slot, they turned at the speed limit,
    # the cable bent round both fingertips and C ended at the force limit in 0.6 s)
    result, _, _ = run_scenario(parse_scenario(ACROSS_CLIP))
    _all_true(result)
    assert "is in the jaws of C1" in result.steps[2]["truth"]["detail"]
    assert result.steps[2]["max_force"] < 12.0


@pytest.mark.slow
def test_clip_then_slide_then_turn_about_the_clip() -> None:
    # after F the clip is the cable's last fixed point: E slides out cable
    # beyond it, D pulls against it, I turns the cable about it. At 205fa85
    # and 3f1166c I ended with C1 estimated 3.1 mm from the true clip at a
    # reported 1.4 mm std, trusted (tolerance 3.0 mm): a clip's contact now
    # lies on its slot (model_estimator.on_slot)
    result = _after(
        "F",
        [
            {"primitive": "E", "arm": "left", "distance": 0.03, "friction_force": 1.5},
            {"primitive": "D", "arm": "left", "force": 3.0},
            {"primitive": "I", "arm": "left", "angle": 0.5, "about": "C1"},
        ],
    )
    _all_true(result)
    assert "against C1" in result.steps[3]["truth"]["detail"]


@pytest.mark.slow
def test_h_from_across_the_board_travels_above_the_taut_cable() -> None:
    """The free gripper rises first, travels high, then comes down onto the cable.

    Random board 1695658280: the left gripper, freed low at a clip, went
    straight for W2 across the board and pulled 27 N.
    """
    from tautwire.primitives.grasp_tensioned import NEAR, TRAVEL_HEIGHT

    seed = trial_seed(0, "H", 0)
    doc = scenario_document(trial_scene("H", seed).scenario)
    task = list(doc["task"])
    grasp = task[-1]
    assert grasp["primitive"] in ("grasp_tensioned", "H")
    # start the grasping gripper low and far across the board from its goal
    arm = grasp["arm"]
    doc["robot"]["grippers"][arm]["position"] = [0.55, 0.0 if arm == "right" else 0.05, 0.07]
    path: list[Any] = []

    def tick(rec: Any) -> None:
        if rec.primitive.letter == "H":
            path.append(rec.observation.gripper(arm).position.copy())

    result, _, _ = run_scenario(scenario_from_data(doc), seed, on_tick=tick)
    _all_true(result)
    start, end = path[0], path[-1]
    assert float(((start - end)[:2] ** 2).sum()) ** 0.5 > NEAR
    assert max(float(p[2]) for p in path) >= TRAVEL_HEIGHT - 0.005
