"""Table I's randomised scenes: F's clips stay within what one arm can press."""

from __future__ import annotations

import math

import numpy as np
import pytest

from tautwire.experiments.trial import trial_seed
from tautwire.experiments.trial_scenes import (
    FORCE_LIMIT,
    PRESS_RESERVE,
    _pivot_press,
    trial_scene,
)
from tautwire.primitives.single_arm_clipping import JAW_TOP, TABLE_CLEARANCE
from tautwire.scenario.models import CLIP_LENGTH


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
